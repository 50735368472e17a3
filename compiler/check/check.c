/* check.c — from the syntax tree to the checked model: constants, functions, laws, the
 * scene settings, bodies and expectations.  Reports every error it finds. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "check_body.h"
#include "check_expr.h"
#include "law_require.h"
#include "reference_csv.h"
#include "seen_settings.h"
#include "util/diag.h"
#include "geom/mesh.h"
#include "util/source.h"
#include "model/eval.h"
#include "ir/law.h"
#include "lang/builtins.h"

/* ------------------------------------------------------------------ let, fn, material */

static int name_taken(const Model *m, const char *name, SrcLoc loc)
{
    const ConstDef *c = model_find_const(m, name);
    const FnDef *f = model_find_fn(m, name);
    if (c || f) {
        diag_error(loc, "'%s' is already defined", name);
        diag_note(c ? c->loc : f->loc, "previous definition of '%s'", name);
        return 1;
    }
    if (builtin_variable(name) >= 0 || builtin_function_arity(name) >= 0) {
        diag_error(loc, "'%s' is a built-in name and cannot be redefined", name);
        return 1;
    }
    return 0;
}

static int check_let(Model *m, const Item *it)
{
    if (name_taken(m, it->name, it->loc))
        return -1;
    double v;
    if (check_const_expr(m, it->value, "the value of a 'let'", &v))
        return -1;
    model_add_const(m, (ConstDef){it->name, v, it->loc});
    return 0;
}

/* Constant folding and the material laws write a function's calls out (eval.c, law.c), so
 * a chain of functions that each call the one before twice would cost 2^n: a function may
 * stand for at most this many nodes, its calls written out. */
#define FN_MAX_SIZE 1e6

/* Nodes of e with calls of user functions written out, or -1 after reporting a call of fn
 * itself. */
static double written_out(const Model *m, const Item *fn, const Expr *e)
{
    double n = 1;
    if (e->kind == EX_CALL && !strcmp(e->name, fn->name)) {
        diag_error(e->loc, "function '%s' calls itself: recursion is not supported", fn->name);
        return -1;
    }
    if (e->kind == EX_CALL) {
        const FnDef *f = model_find_fn(m, e->name);
        if (f)
            n += f->size;
    }
    for (int i = 0; i < e->nargs; i++) {
        const double a = written_out(m, fn, e->args[i]);
        if (a < 0)
            return -1;
        n += a;
    }
    return n;
}

/* The size of fn (its body e) into f, or -1 after reporting recursion or a size too large. */
static int fn_size(const Model *m, const Item *fn, const Expr *e, FnDef *f)
{
    f->size = written_out(m, fn, e);
    if (f->size < 0)
        return -1;
    if (f->size > FN_MAX_SIZE) {
        diag_error(fn->loc, "function '%s' written out with the functions it calls has %.3g "
                   "operations, more than %g", fn->name, f->size, FN_MAX_SIZE);
        return -1;
    }
    return 0;
}

static int check_fn(Model *m, const Item *it)
{
    if (name_taken(m, it->name, it->loc))
        return -1;
    for (int i = 0; i < it->nparams; i++)
        for (int j = 0; j < i; j++)
            if (!strcmp(it->params[i], it->params[j])) {
                diag_error(it->loc, "parameter '%s' of '%s' given twice", it->params[i],
                           it->name);
                return -1;
            }
    ExprScope s = {m, it->params, it->nparams, 0, 0, "the body of a function"};
    /* Register first so that the body can be checked; recursion is refused below (a
     * function sees only those defined before it, so only a call of itself can recur). */
    model_add_fn(m, (FnDef){it->name, it->params, it->nparams, it->value, it->loc, 0});
    if (check_scalar_expr(&s, it->value, 0)) {
        m->nfns--;
        return -1;
    }
    if (fn_size(m, it, it->value, &m->fns[m->nfns - 1])) {
        m->fns[m->nfns - 1].body = ast_num(it->loc, 0.0); /* known, and harmless to use */
        m->fns[m->nfns - 1].size = 1;
        return -1;
    }
    return 0;
}

static int check_law_def(Model *m, const Item *it)
{
    for (int i = 0; i < m->nlaws; i++)
        if (!strcmp(m->laws[i]->name, it->material.name)) {
            diag_error(it->loc, "material '%s' is already defined", it->material.name);
            return -1;
        }
    m->laws[m->nlaws++] = &it->material;
    const int bad = law_check(m, &it->material) != 0;
    return law_require_check(m, &it->material) || bad ? -1 : 0;
}

/* ------------------------------------------------------------------ scene */

static int scene_name(const Setting *s, const char *const *names, int n, int *out)
{
    const Expr *e = s->values[0];
    if (s->nvalues == 1 && e->kind == EX_NAME)
        for (int i = 0; i < n; i++)
            if (!strcmp(e->name, names[i])) {
                *out = i;
                return 0;
            }
    diag_error(e->loc, "'%s' must be one of: %s%s%s", s->key, names[0], n > 1 ? ", " : "",
               n > 1 ? names[1] : "");
    return -1;
}

static int scene_number(const Model *m, const Setting *s, double *out, int positive)
{
    if (s->nvalues != 1) {
        diag_error(s->loc, "'%s' takes one value", s->key);
        return -1;
    }
    if (check_const_expr(m, s->values[0], s->key, out))
        return -1;
    if (positive && !(*out > 0)) {
        diag_error(s->values[0]->loc, "'%s' must be positive (got %g)", s->key, *out);
        return -1;
    }
    return 0;
}

static int scene_setting(Model *m, const Setting *s)
{
    static const char *const kernels[] = {"wendland", "cubic"};
    static const char *const integrators[] = {"verlet", "symplectic"};
    static const char *const precisions[] = {"double", "single"};
    static const char *const timesteps[] = {"auto", "undeformed", "stretch"};
    static const char *const gradients[] = {"linear", "quadratic"};
    int k;
    double v;
    if (!strcmp(s->key, "dimension")) {
        if (scene_number(m, s, &v, 1))
            return -1;
        if (v != 2 && v != 3) {
            diag_error(s->values[0]->loc, "dimension must be 2 or 3 (got %g)", v);
            return -1;
        }
        m->dim = (int)v;
        return 0;
    }
    if (!strcmp(s->key, "kernel")) {
        if (scene_name(s, kernels, 2, &k))
            return -1;
        m->kernel = (KernelKind)k;
        return 0;
    }
    if (!strcmp(s->key, "integrator")) {
        if (scene_name(s, integrators, 2, &k))
            return -1;
        m->integrator = (IntegratorKind)k;
        return 0;
    }
    if (!strcmp(s->key, "precision")) {
        if (scene_name(s, precisions, 2, &k))
            return -1;
        m->single = k == 1;
        return 0;
    }
    if (!strcmp(s->key, "timestep")) {
        if (scene_name(s, timesteps, 3, &k))
            return -1;
        m->dt_mode = (TimestepKind)k;
        return 0;
    }
    if (!strcmp(s->key, "gradient")) {
        if (scene_name(s, gradients, 2, &k))
            return -1;
        m->gradient = (GradientKind)k;
        m->gradient_loc = s->loc;
        return 0;
    }
    if (!strcmp(s->key, "gravity"))
        return s->nvalues == 1 ? check_vec3(m, s->values[0], "gravity", m->gravity) : -1;
    if (!strcmp(s->key, "contact")) {
        if (scene_number(m, s, &m->contact, 0))
            return -1;
        if (!(m->contact >= 0) || !isfinite(m->contact)) {
            diag_error(s->values[0]->loc, "'contact' must be 0 (off) or a positive stiffness "
                                          "multiplier (got %g)", m->contact);
            return -1;
        }
        return 0;
    }
    struct { const char *key; double *dst; } nums[] = {
        {"dp", &m->dp}, {"coefh", &m->coefh}, {"cfl", &m->cfl}, {"dtmin", &m->dtmin},
        {"dt", &m->dt}, {"end", &m->t_end}, {"output", &m->t_out},
        {"checkpoint", &m->t_checkpoint},
    };
    for (size_t i = 0; i < sizeof nums / sizeof nums[0]; i++)
        if (!strcmp(s->key, nums[i].key))
            return scene_number(m, s, nums[i].dst, 1);
    diag_error(s->loc, "unknown scene setting '%s'", s->key);
    return -1;
}

/* Where the scene sets KEY (its value), or NULL when it keeps the default. */
static const SrcLoc *setting_loc(const Item *scene, const char *key)
{
    const Setting *s = ast_find_setting(&scene->scene, key);
    return s ? &s->values[0]->loc : NULL;
}

static int check_scene(Model *m, const Item *scene)
{
    int bad = 0;
    SeenSettings seen = {0};
    for (int i = 0; i < scene->scene.n; i++)
        bad |= setting_once(&seen, &scene->scene.items[i], "the scene") ||
               scene_setting(m, &scene->scene.items[i]) != 0;
    seen_settings_free(&seen);
    if (bad)
        return -1;
    const char *missing = !m->dim ? "dimension" : !(m->dp > 0) ? "dp" : !(m->t_end > 0) ? "end" : NULL;
    if (missing) {
        diag_error(scene->loc, "scene needs '%s'", missing);
        return -1;
    }
    if (!(m->t_out > 0))
        m->t_out = m->t_end / 100.0;
    /* The program reaches its output times by adding the interval, which stalls where it is
     * below the spacing of doubles near t (runtime/run/run.c, too_many_outputs). */
    if (m->t_end / m->t_out > 1e9) {
        const SrcLoc *at = setting_loc(scene, "output");
        diag_error(at ? *at : scene->loc, "the output interval %g s gives %.3g outputs up "
                   "to the end time %g s, more than 10^9", m->t_out, m->t_end / m->t_out,
                   m->t_end);
        return -1;
    }
    if (m->cfl > 1.0)
        diag_warning(scene->loc, "cfl %g is above 1: the run is likely to be unstable", m->cfl);
    /* The quadratic fit's stiffest modes, at a corner, are about 2.5 times as fast as eq. 63's
     * (bench/bending/diagnose): stable up to cfl 0.35 in 3D and 0.4 in 2D when measured. */
    const double cfl_quadratic = m->dim == 3 ? 0.3 : 0.35;
    if (m->gradient == GRADIENT_QUADRATIC && !(m->dt > 0) && m->cfl > cfl_quadratic) {
        const SrcLoc *at = setting_loc(scene, "cfl");
        diag_warning(at ? *at : m->gradient_loc, "cfl %g with 'gradient quadratic': its explicit "
                     "step was stable up to about %g in %dD; %g or less is safe", m->cfl,
                     m->dim == 3 ? 0.35 : 0.4, m->dim, cfl_quadratic);
    }
    /* The adaptive step is at most cfl h/c0 (eq. 64, 65) and the run stops as unstable below
     * dtmin h/c0: with cfl < dtmin the very first step would. */
    if (!(m->dt > 0) && m->cfl < m->dtmin) {
        const SrcLoc *at = setting_loc(scene, "cfl");
        at = at ? at : setting_loc(scene, "dtmin");
        diag_error(at ? *at : scene->loc, "cfl %g is below dtmin %g: every time step (at most "
                   "cfl h/c0, eq. 64) would be below the floor dtmin h/c0, and the run would "
                   "stop at its first step", m->cfl, m->dtmin);
        return -1;
    }
    return 0;
}

static void scene_defaults(Model *m)
{
    m->kernel = KERNEL_WENDLAND;
    m->integrator = INTEGRATOR_VERLET;
    m->coefh = 1.0;
    m->cfl = 0.2;
    m->dtmin = 0.01;
    m->contact = 1.0;
}

/* ------------------------------------------------------------------ expectations */

static int find_measure(const Model *m, const ExpectDecl *d, ExpectModel *x)
{
    for (int b = 0; b < m->nbodies; b++)
        for (int k = 0; k < m->bodies[b].nmeasures; k++)
            if (!strcmp(m->bodies[b].measures[k].name, d->measure)) {
                x->body = b;
                x->measure = k;
                return 0;
            }
    diag_error(d->target_loc, "unknown measurement '%s'", d->measure);
    return -1;
}

static int quantity_index(const char *q)
{
    static const char *const names[] = {"ux", "uy", "uz", "fx", "fy", "fz"};
    for (int i = 0; i < 6; i++)
        if (!strcmp(q, names[i]))
            return i;
    return -1;
}

static int check_expect(Model *m, const Item *it)
{
    const ExpectDecl *d = &it->expect;
    ExpectModel *x = &m->expects[m->nexpects];
    memset(x, 0, sizeof *x);
    x->kind = d->kind;
    x->loc = d->loc;
    x->body = x->measure = -1;
    x->tolerance = -1;
    if (d->kind != EXPECT_ENERGY) {
        if (find_measure(m, d, x))
            return -1;
        x->quantity = quantity_index(d->quantity);
        if (x->quantity < 0) {
            diag_error(d->target_loc, "unknown quantity '%s' (expected ux, uy, uz, fx, fy or fz)",
                       d->quantity);
            return -1;
        }
    }
    if (d->kind == EXPECT_REFERENCE && d->file) {
        char *path = source_beside(d->loc.file, d->file);
        if (reference_csv_read(path, d->file_loc, &x->ref_t, &x->ref_v, &x->ref_n)) {
            free(path);
            return -1;
        }
        x->ref_file = path;
    } else if (d->kind == EXPECT_REFERENCE) {
        static char *const t_only[] = {"t"};
        ExprScope s = {m, (char **)t_only, 1, 0, 0, "a reference solution (a function of t)"};
        if (check_scalar_expr(&s, d->value, 0))
            return -1;
        x->reference = d->value;
    } else if (d->kind != EXPECT_ENERGY &&
               check_const_expr(m, d->value, "the expected value", &x->value)) {
        return -1;
    }
    if (d->tolerance) {
        if (check_const_expr(m, d->tolerance, "the tolerance", &x->tolerance))
            return -1;
        if (!(x->tolerance > 0)) {
            diag_error(d->tolerance->loc, "the tolerance must be positive");
            return -1;
        }
        x->tolerance /= 100.0;
    }
    m->nexpects++;
    return 0;
}

/* ------------------------------------------------------------------ the program */

static void allocate(Model *m, const Program *p)
{
    size_t n = (size_t)p->n + 1;
    m->consts = calloc(n, sizeof *m->consts);
    m->fns = calloc(n, sizeof *m->fns);
    m->laws = calloc(n, sizeof *m->laws);
    m->bodies = calloc(n, sizeof *m->bodies);
    m->expects = calloc(n, sizeof *m->expects);
}

static int check_definitions(Model *m, const Program *p)
{
    int bad = 0;
    for (int i = 0; i < p->n; i++) {
        const Item *it = &p->items[i];
        if (it->kind == IT_LET)
            bad |= check_let(m, it) != 0;
        else if (it->kind == IT_FN)
            bad |= check_fn(m, it) != 0;
        else if (it->kind == IT_MATERIAL)
            bad |= check_law_def(m, it) != 0;
    }
    return bad;
}

static int check_scene_item(Model *m, const Program *p)
{
    const Item *scene = NULL;
    for (int i = 0; i < p->n; i++)
        if (p->items[i].kind == IT_SCENE) {
            if (scene) {
                diag_error(p->items[i].loc, "a model has one scene");
                return 1;
            }
            scene = &p->items[i];
        }
    if (!scene) {
        SrcLoc top = {p->file, 1, 1};
        diag_error(top, "the model has no 'scene { ... }'");
        return 1;
    }
    return check_scene(m, scene) != 0;
}

/* Surfaces region r adds to the program's cache (runtime/geom/mesh_cache.c) beyond those in
 * seen[0..*nseen-1], the files of unmoved surfaces counted so far (each counted once). */
static int meshes_of(const Region *r, const char **seen, int *nseen)
{
    int count = 0;
    for (int k = 0; k < r->n; k++) {
        const ShapePrim *s = &r->prims[k];
        if (s->kind != SHAPE_SURFACE || s->npts) {
            count += s->kind == SHAPE_SURFACE || s->kind == SHAPE_PRISM ||
                     s->kind == SHAPE_PYRAMID;
            continue;
        }
        int known = 0;
        for (int q = 0; q < *nseen && !known; q++)
            known = !strcmp(seen[q], s->file);
        if (!known && *nseen < SPH_MESH_MAX + 1)
            seen[(*nseen)++] = s->file;
        count += !known;
    }
    return count;
}

/* The program keeps at most SPH_MESH_MAX surfaces (files, moved files, prisms, pyramids). */
static int check_mesh_count(const Model *m, SrcLoc at)
{
    const char *seen[SPH_MESH_MAX + 1];
    int nseen = 0;
    long count = 0;
    for (int b = 0; b < m->nbodies; b++) {
        const BodyModel *body = &m->bodies[b];
        count += meshes_of(&body->region, seen, &nseen);
        for (int k = 0; k < body->nbcs; k++)
            if (body->bcs[k].has_near)
                count += meshes_of(&body->bcs[k].near, seen, &nseen);
    }
    if (count <= SPH_MESH_MAX)
        return 0;
    diag_error(at, "the model's shapes need %ld surfaces (surface files, prisms, pyramids), "
                   "more than the %d a program keeps", count, SPH_MESH_MAX);
    return -1;
}

static int check_bodies(Model *m, const Program *p)
{
    int bad = 0;
    NameIndex names = {0};
    for (int i = 0; i < p->n; i++) {
        if (p->items[i].kind != IT_BODY)
            continue;
        const BodyDecl *d = &p->items[i].body;
        if (name_index_get(&names, d->name) >= 0) {
            diag_error(d->loc, "body '%s' is defined twice", d->name);
            bad = 1;
        }
        name_index_put(&names, d->name, m->nbodies);
        bad |= check_body(m, d, &m->bodies[m->nbodies++]) != 0;
    }
    name_index_free(&names);
    SrcLoc top = {p->file, 1, 1};
    if (!m->nbodies && !bad) {
        diag_error(top, "the model has no body");
        bad = 1;
    }
    return bad || check_mesh_count(m, top) != 0;
}

int check_program(const Program *p, Model *m)
{
    const char *name = m->name;
    memset(m, 0, sizeof *m);
    m->name = name;
    m->source = p->file;
    m->compat_outputs = p->from_xml;
    scene_defaults(m);
    allocate(m, p);
    int bad = check_definitions(m, p);
    if (check_scene_item(m, p))
        return -1; /* bodies need the dimension */
    bad |= check_bodies(m, p);
    /* The strain-gradient term of the quadratic gradient's cells is the undamaged body's
     * (templates/body_quadratic.c): a crack's phase field does not degrade it yet. */
    for (int i = 0; i < m->nbodies && !bad && m->gradient == GRADIENT_QUADRATIC; i++)
        if (m->bodies[i].fracture.on) {
            diag_error(m->gradient_loc, "'gradient quadratic' does not take phase-field "
                                        "fracture (body '%s'): use 'gradient linear'",
                       m->bodies[i].name);
            bad = 1;
        }
    for (int i = 0; i < p->n && !bad; i++)
        if (p->items[i].kind == IT_EXPECT)
            bad |= check_expect(m, &p->items[i]) != 0;
    return bad || diag_error_count() ? -1 : 0;
}
