/* law.c — material laws: type checking and symbolic evaluation into the scalar graph.
 *
 * A law's statements are evaluated with F as nine graph inputs (in 2D, plane strain: the
 * out-of-plane row and column of F are those of the identity and fold away).  Tensors
 * are 3×3, row-major.  The result is one graph node per component of the second
 * Piola–Kirchhoff stress S and one for the strain energy density psi. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "util/diag.h"
#include "model/eval.h"
#include "law.h"
#include "lang/builtins.h"
#include "spectral.h"

typedef struct {
    int tensor;  /* 0 scalar, 1 tensor */
    int s;       /* scalar node */
    int t[9];    /* tensor nodes */
} Val;

typedef struct {
    const char *name;
    Val v;
    int assigned;  /* made by `name = ...` (or the merge after an if): outlives its block */
} Binding;

typedef struct {
    const Model *m;
    SGraph *g;
    const MaterialDef *law;
    const double *params;  /* NULL: symbolic parameters (checking) */
    double rho0;           /* the body's reference density; NaN: symbolic (checking) */
    int dim;               /* the body's dimension (2: plane strain) */
    Binding *env;
    int nenv, capenv;
    int has_stress, has_energy;
    int energy_line;   /* the line of the law's (not the tension block's) energy */
    int tension_energy_line; /* the line of the tension block's energy (psi+) */
    const char *of;    /* the energy is a function of C or E (bound instead of F), or NULL */
    Val var;           /* its variables (symmetric_variable) */
    int want_tension;  /* evaluate the tension block (fracture) */
    int in_tension;    /* inside it: stress and energy are S+ and psi+ */
    int in_if;         /* inside an if block: only let and assignments */
    LawRoots out;
} Law;

static const Val BAD = {-1, -1, {0}};

static Val scalar(int s)
{
    Val v = {0, s, {0}};
    return v;
}

static int ok(Val v) { return v.tensor >= 0; }

static void bind(Law *L, const char *name, Val v)
{
    if (L->nenv == L->capenv) {
        L->capenv = L->capenv ? 2 * L->capenv : 16;
        L->env = realloc(L->env, (size_t)L->capenv * sizeof *L->env);
    }
    L->env[L->nenv++] = (Binding){name, v, 0};
}

/* The innermost binding of name, or NULL. */
static Binding *find_binding(Law *L, const char *name)
{
    for (int i = L->nenv - 1; i >= 0; i--)
        if (!strcmp(L->env[i].name, name))
            return &L->env[i];
    return NULL;
}

static Val identity(Law *L)
{
    Val v = {1, -1, {0}};
    for (int k = 0; k < 9; k++)
        v.t[k] = sg_const(L->g, k % 4 == 0 ? 1.0 : 0.0);
    return v;
}

/* ------------------------------------------------------------------ tensor algebra */

static Val t_map2(Law *L, SnOp op, Val a, Val b)
{
    Val r = {1, -1, {0}};
    for (int k = 0; k < 9; k++)
        r.t[k] = sg_binary(L->g, op, a.tensor ? a.t[k] : a.s, b.tensor ? b.t[k] : b.s);
    return r;
}

static Val t_matmul(Law *L, Val a, Val b)
{
    Val r = {1, -1, {0}};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            int acc = sg_const(L->g, 0.0);
            for (int k = 0; k < 3; k++)
                acc = sg_binary(L->g, SN_ADD, acc,
                                sg_binary(L->g, SN_MUL, a.t[3 * i + k], b.t[3 * k + j]));
            r.t[3 * i + j] = acc;
        }
    return r;
}

static Val t_transpose(Val a)
{
    Val r = a;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            r.t[3 * i + j] = a.t[3 * j + i];
    return r;
}

static int t_trace(Law *L, Val a)
{
    return sg_binary(L->g, SN_ADD, sg_binary(L->g, SN_ADD, a.t[0], a.t[4]), a.t[8]);
}

static int cofactor(Law *L, Val a, int i, int j)
{
    int r0 = (i + 1) % 3, r1 = (i + 2) % 3, c0 = (j + 1) % 3, c1 = (j + 2) % 3;
    return sg_binary(L->g, SN_SUB, sg_binary(L->g, SN_MUL, a.t[3 * r0 + c0], a.t[3 * r1 + c1]),
                     sg_binary(L->g, SN_MUL, a.t[3 * r0 + c1], a.t[3 * r1 + c0]));
}

static int t_det(Law *L, Val a)
{
    int d = sg_const(L->g, 0.0);
    for (int j = 0; j < 3; j++)
        d = sg_binary(L->g, SN_ADD, d, sg_binary(L->g, SN_MUL, a.t[j], cofactor(L, a, 0, j)));
    return d;
}

static Val t_inverse(Law *L, Val a)
{
    Val r = {1, -1, {0}};
    int inv_det = sg_binary(L->g, SN_DIV, sg_const(L->g, 1.0), t_det(L, a));
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) /* inverse = adjugate / det, adj_ij = cof_ji */
            r.t[3 * i + j] = sg_binary(L->g, SN_MUL, cofactor(L, a, j, i), inv_det);
    return r;
}

static int t_ddot(Law *L, Val a, Val b)
{
    int acc = sg_const(L->g, 0.0);
    for (int k = 0; k < 9; k++)
        acc = sg_binary(L->g, SN_ADD, acc, sg_binary(L->g, SN_MUL, a.t[k], b.t[k]));
    return acc;
}

/* The positive part of a symmetric tensor, sum of max(lambda_k, 0) q_k q_k^T (eq. 13, 16),
 * by a runtime routine (runtime/sph_tensor.h).  Its upper triangle is used.  A tensor with
 * the plane-strain structure (no y coupling, zero yy) takes the 2×2 closed form. */
static Val t_pos(Law *L, Val a)
{
    Val r = {1, -1, {0}};
    int zero = sg_const(L->g, 0.0);
    int plane = 1;
    for (int k = 1; k < 8; k++)
        plane &= (k == 2 || k == 6) || a.t[k] == zero;
    if (plane) {
        int args[3] = {a.t[0], a.t[2], a.t[8]};
        int ext = sg_ext(L->g, SPECTRAL_POS2, args, 3, 3);
        for (int k = 0; k < 9; k++)
            r.t[k] = zero;
        r.t[0] = sg_part(L->g, ext, 0);
        r.t[2] = r.t[6] = sg_part(L->g, ext, 1);
        r.t[8] = sg_part(L->g, ext, 2);
        return r;
    }
    int args[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            args[3 * i + j] = a.t[i <= j ? 3 * i + j : 3 * j + i];
    int ext = sg_ext(L->g, SPECTRAL_POS3, args, 9, 9);
    for (int k = 0; k < 9; k++)
        r.t[k] = sg_part(L->g, ext, k);
    return r;
}

/* ------------------------------------------------------------------ expressions */

static Val eval(Law *L, const Expr *e);

/* J = det F; with an energy of C or E, sqrt(det C) (C = 2 E + I). */
static int volume_ratio(Law *L)
{
    if (!L->of)
        return t_det(L, find_binding(L, "F")->v);
    Val C = L->var;
    if (!strcmp(L->of, "E"))
        C = t_map2(L, SN_ADD, t_map2(L, SN_MUL, C, scalar(sg_const(L->g, 2.0))), identity(L));
    return sg_call(L->g, BI_sqrt, t_det(L, C));
}

static Val F_value(Law *L, int dim, int all_inputs);

/* dF/dt, the material function's input Fd: the corrected gradient of the velocity as F's of
 * the displacement (the gradient pass), F's in-plane block in 2D (the rest 0). */
static Val Fdot_value(Law *L)
{
    Val v = {1, -1, {0}};
    for (int k = 0; k < 9; k++)
        v.t[k] = L->dim == 2 && (k / 3 == 1 || k % 3 == 1) ? sg_const(L->g, 0.0)
                                                         : sg_input(L->g, LAW_INPUT_FDOT, k);
    return v;
}

/* dC/dt = Fdot^T F + F^T Fdot, from F itself (the law's energy may be one of C). */
static Val Cdot_value(Law *L)
{
    const Val F = F_value(L, L->dim, 0), Fd = Fdot_value(L);
    const Val a = t_matmul(L, t_transpose(Fd), F);
    return t_map2(L, SN_ADD, a, t_transpose(a));
}

/* What a law reads besides F (or C, E), its parameters and state: the step of its update
 * dt (an input of the material function), the rates Fdot, Cdot and Edot (from the velocity
 * gradient, an input too), the volume ratio J, the reference density rho0 (the body's) and
 * the current density rho = rho0 / J.  BAD for another name. */
static Val law_input(Law *L, const char *name)
{
    if (!strcmp(name, LAW_INPUT_DT))
        return scalar(sg_input(L->g, LAW_INPUT_DT, -1));
    if (!strcmp(name, "Fdot"))
        return Fdot_value(L);
    if (!strcmp(name, "Cdot"))
        return Cdot_value(L);
    if (!strcmp(name, "Edot"))
        return t_map2(L, SN_MUL, Cdot_value(L), scalar(sg_const(L->g, 0.5)));
    if (!strcmp(name, "J"))
        return scalar(volume_ratio(L));
    if (strcmp(name, "rho0") && strcmp(name, "rho"))
        return BAD;
    const int rho0 = isnan(L->rho0) ? sg_input(L->g, "rho0", -1) : sg_const(L->g, L->rho0);
    return scalar(!strcmp(name, "rho0") ? rho0 : sg_binary(L->g, SN_DIV, rho0, volume_ratio(L)));
}

static Val lookup(Law *L, const Expr *e)
{
    for (int i = L->nenv - 1; i >= 0; i--)
        if (!strcmp(L->env[i].name, e->name))
            return L->env[i].v;
    for (int i = 0; i < L->law->nparams; i++)
        if (!strcmp(L->law->params[i], e->name))
            return scalar(L->params ? sg_const(L->g, L->params[i]) : sg_param(L->g, i));
    if (!strcmp(e->name, "I"))
        return identity(L);
    Val in = law_input(L, e->name);
    if (ok(in))
        return in;
    double v;
    if (eval_expr(L->m, e, NULL, &v) == EVAL_OK)
        return scalar(sg_const(L->g, v));
    if (L->of && !strcmp(e->name, "F"))
        diag_error(e->loc, "material '%s' gives its energy as a function of %s: write it with "
                   "%s, not F (J = sqrt(det(C)))", L->law->name, L->of, L->of);
    else if (builtin_variable(e->name) >= 0)
        diag_error(e->loc, "'%s' is a particle variable and cannot be used in a material law",
                   e->name);
    else
        diag_error(e->loc, "unknown name '%s' in material '%s'", e->name, L->law->name);
    return BAD;
}

static Val need_scalar(const Expr *e, Val v, const char *what)
{
    if (ok(v) && v.tensor) {
        diag_error(e->loc, "%s needs a scalar, got a tensor", what);
        return BAD;
    }
    return v;
}

static Val need_tensor(const Expr *e, Val v, const char *what)
{
    if (ok(v) && !v.tensor) {
        diag_error(e->loc, "%s needs a tensor, got a scalar", what);
        return BAD;
    }
    return v;
}

static Val binary(Law *L, const Expr *e)
{
    Val a = eval(L, e->args[0]), b = eval(L, e->args[1]);
    if (!ok(a) || !ok(b))
        return BAD;
    static const SnOp map[] = {
        [OP_ADD] = SN_ADD, [OP_SUB] = SN_SUB, [OP_MUL] = SN_MUL, [OP_DIV] = SN_DIV,
        [OP_POW] = SN_POW, [OP_LT] = SN_LT,   [OP_GT] = SN_GT,   [OP_LE] = SN_LE,
        [OP_GE] = SN_GE,   [OP_EQ] = SN_EQ,   [OP_NE] = SN_NE,   [OP_AND] = SN_AND,
        [OP_OR] = SN_OR,
    };
    SnOp op = map[e->op];
    if (!a.tensor && !b.tensor)
        return scalar(sg_binary(L->g, op, a.s, b.s));
    if (e->op == OP_MUL)
        return a.tensor && b.tensor ? t_matmul(L, a, b) : t_map2(L, SN_MUL, a, b);
    if ((e->op == OP_ADD || e->op == OP_SUB) && a.tensor && b.tensor)
        return t_map2(L, op, a, b);
    if (e->op == OP_DIV && a.tensor && !b.tensor)
        return t_map2(L, SN_DIV, a, b);
    diag_error(e->loc, "operator '%s' cannot combine a %s and a %s", op_spelling(e->op),
               a.tensor ? "tensor" : "scalar", b.tensor ? "tensor" : "scalar");
    return BAD;
}

static Val unary(Law *L, const Expr *e)
{
    Val a = eval(L, e->args[0]);
    if (!ok(a))
        return BAD;
    if (e->op == OP_NOT)
        return need_scalar(e, a, "'not'").tensor ? BAD : scalar(sg_unary(L->g, SN_NOT, a.s));
    if (!a.tensor)
        return scalar(sg_unary(L->g, SN_NEG, a.s));
    for (int k = 0; k < 9; k++)
        a.t[k] = sg_unary(L->g, SN_NEG, a.t[k]);
    return a;
}

static Val tensor_fn(Law *L, const Expr *e, Val a)
{
    const char *f = e->name;
    if (!strcmp(f, "transpose"))
        return t_transpose(a);
    if (!strcmp(f, "tr"))
        return scalar(t_trace(L, a));
    if (!strcmp(f, "det"))
        return scalar(t_det(L, a));
    if (!strcmp(f, "inv"))
        return t_inverse(L, a);
    if (!strcmp(f, "sym"))
        return t_map2(L, SN_MUL, t_map2(L, SN_ADD, a, t_transpose(a)), scalar(sg_const(L->g, 0.5)));
    if (!strcmp(f, "pos"))
        return t_pos(L, a);
    if (!strcmp(f, "neg")) /* A- = A - A+ (eq. 14) */
        return t_map2(L, SN_SUB, a, t_pos(L, a));
    /* dev(A) = A - tr(A)/3 I */
    int third = sg_binary(L->g, SN_MUL, t_trace(L, a), sg_const(L->g, 1.0 / 3.0));
    return t_map2(L, SN_SUB, a, t_map2(L, SN_MUL, identity(L), scalar(third)));
}

static int is_tensor_fn(const char *f)
{
    static const char *const names[] = {"transpose", "tr", "det", "inv", "sym", "dev",
                                        "pos", "neg"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(f, names[i]))
            return 1;
    return 0;
}

static int check_arity(const Expr *e, int n)
{
    if (e->nargs == n)
        return 0;
    diag_error(e->loc, "function '%s' takes %d argument%s, got %d", e->name, n, n == 1 ? "" : "s",
               e->nargs);
    return -1;
}

static Val user_fn(Law *L, const Expr *e, const FnDef *fn)
{
    if (check_arity(e, fn->nparams))
        return BAD;
    int mark = L->nenv, bad = 0;
    Val *args = malloc((size_t)(fn->nparams + 1) * sizeof *args);
    for (int i = 0; i < fn->nparams && !bad; i++) {
        args[i] = need_scalar(e->args[i], eval(L, e->args[i]), "a function argument");
        bad = !ok(args[i]);
    }
    for (int i = 0; i < fn->nparams && !bad; i++)
        bind(L, fn->params[i], args[i]);
    free(args);
    Val r = bad ? BAD : eval(L, fn->body);
    L->nenv = mark;
    return r;
}

/* A built-in function of Table 2 by its form (lang/builtins.h); `if` also chooses between
 * tensors. */
static Val builtin(Law *L, const Expr *e, int f)
{
    const Builtin *b = &BUILTIN_FUNCTION[f];
    if (check_arity(e, b->arity))
        return BAD;
    if (b->form == BF_IF) {
        Val c = need_scalar(e, eval(L, e->args[0]), "the condition of 'if'");
        Val x = eval(L, e->args[1]), y = eval(L, e->args[2]);
        if (!ok(c) || !ok(x) || !ok(y))
            return BAD;
        if (x.tensor != y.tensor) {
            diag_error(e->loc, "the branches of 'if' must have the same type");
            return BAD;
        }
        if (!x.tensor)
            return scalar(sg_select(L->g, c.s, x.s, y.s));
        for (int k = 0; k < 9; k++)
            x.t[k] = sg_select(L->g, c.s, x.t[k], y.t[k]);
        return x;
    }
    Val a[2];
    int bad = 0;
    for (int i = 0; i < b->arity; i++)
        bad |= !ok(a[i] = need_scalar(e, eval(L, e->args[i]), e->name));
    if (bad)
        return BAD;
    switch (b->form) {
    case BF_POW: return scalar(sg_binary(L->g, SN_POW, a[0].s, a[1].s));
    case BF_MIN: return scalar(sg_binary(L->g, SN_MIN, a[0].s, a[1].s));
    case BF_MAX: return scalar(sg_binary(L->g, SN_MAX, a[0].s, a[1].s));
    case BF_RECIP: { /* 1 / c(x), its call shared with uses of c itself (cot and tan) */
        int t = sg_call(L->g, builtin_of_c(b->c), a[0].s);
        return scalar(sg_binary(L->g, SN_DIV, sg_const(L->g, 1.0), t));
    }
    default: return scalar(sg_call(L->g, f, a[0].s));
    }
}

static Val call(Law *L, const Expr *e)
{
    const FnDef *fn = model_find_fn(L->m, e->name);
    if (fn)
        return user_fn(L, e, fn);
    if (!strcmp(e->name, "ddot")) {
        if (check_arity(e, 2))
            return BAD;
        Val a = need_tensor(e, eval(L, e->args[0]), "ddot");
        Val b = need_tensor(e, eval(L, e->args[1]), "ddot");
        return ok(a) && ok(b) ? scalar(t_ddot(L, a, b)) : BAD;
    }
    if (is_tensor_fn(e->name)) {
        if (check_arity(e, 1))
            return BAD;
        Val a = need_tensor(e, eval(L, e->args[0]), e->name);
        return ok(a) ? tensor_fn(L, e, a) : BAD;
    }
    int f = builtin_function(e->name);
    if (f >= 0)
        return builtin(L, e, f);
    diag_error(e->loc, "unknown function '%s'", e->name);
    return BAD;
}

static Val eval(Law *L, const Expr *e)
{
    switch (e->kind) {
    case EX_NUM: return scalar(sg_const(L->g, e->num));
    case EX_NAME: return lookup(L, e);
    case EX_BINARY: return binary(L, e);
    case EX_UNARY: return unary(L, e);
    case EX_CALL: return call(L, e);
    case EX_VEC: diag_error(e->loc, "vectors are not supported in material laws"); return BAD;
    case EX_SKIP: diag_error(e->loc, "'skip' cannot be used in a material law"); return BAD;
    }
    return BAD;
}

/* ------------------------------------------------------------------ statements */

static int statement(Law *L, const MatStmt *s);

static int not_in_if(Law *L, const MatStmt *s, const char *what)
{
    diag_error(s->loc, "%s cannot be inside an if block of material '%s' (compute the value "
                       "with lets and assignments, then define it after the block)",
               what, L->law->name);
    return -1;
}

/* Whether node reads an input of the law (F, the state, ...): a value that is not a
 * constant once the parameters are known. */
static int reads_input(const SGraph *g, int node)
{
    char *live = calloc((size_t)g->n + 1, 1);
    sg_mark_live(g, &node, 1, live);
    int reads = 0;
    for (int id = 0; id <= node && !reads; id++)
        reads = live[id] && g->nodes[id].op == SN_INPUT;
    free(live);
    return reads;
}

/* A value that must be known for each body before it runs (a state's initial value, a
 * specific heat): a constant, or symbolic in the law's parameters while the law is checked
 * alone (*v NaN then).  Returns 0, or -1 where it reads an input of the law. */
static int body_constant(Law *L, int node, double *v)
{
    if (sg_is_const(L->g, node, v))
        return 0;
    *v = NAN;
    return L->params || reads_input(L->g, node) ? -1 : 0;
}

/* state name = initial value: a per-particle variable read at the start of the law (graph
 * inputs) whose value at the end of the law is stored back.  The initial value must be a
 * constant (a number or a constant tensor such as I) or an expression of the law's
 * parameters (a reference temperature). */
static int state_stmt(Law *L, const MatStmt *s)
{
    if (L->in_if || L->in_tension)
        return not_in_if(L, s, "a state declaration");
    LawRoots *r = &L->out;
    if (find_binding(L, s->name)) {
        diag_error(s->loc, "'%s' is already defined in material '%s'", s->name, L->law->name);
        return -1;
    }
    Val v = eval(L, s->value);
    if (!ok(v))
        return -1;
    int size = v.tensor ? 9 : 1;
    if (r->nstates == LAW_MAX_STATES || r->nslots + size > LAW_MAX_SLOTS) {
        diag_error(s->loc, "material '%s' has more state than sphc supports (%d values)",
                   L->law->name, LAW_MAX_SLOTS);
        return -1;
    }
    Val in = v;
    for (int k = 0; k < size; k++) {
        int node = v.tensor ? v.t[k] : v.s;
        if (body_constant(L, node, &r->init[r->nslots + k])) {
            diag_error(s->value->loc, "the initial value of state '%s' must be a constant or "
                       "an expression of the law's parameters", s->name);
            return -1;
        }
        int input = sg_input(L->g, LAW_INPUT_STATE, r->nslots + k);
        *(v.tensor ? &in.t[k] : &in.s) = input;
    }
    r->states[r->nstates++] = (LawState){s->name, r->nslots, size};
    r->nslots += size;
    bind(L, s->name, in);
    return 0;
}

/* The slot of the scalar state variable that statement s (`dissipation name`, `temperature
 * name, c`) names, or -1 after an error at it: what it is for, and an example. */
static int scalar_state(Law *L, const MatStmt *s, const char *what, const char *example)
{
    const LawRoots *r = &L->out;
    for (int v = 0; v < r->nstates; v++)
        if (!strcmp(r->states[v].name, s->name) && r->states[v].size == 1)
            return r->states[v].offset;
    diag_error(s->loc, "'%s' is not a scalar state variable of material '%s' (%s names one, "
                       "e.g. %s)", s->name, L->law->name, what, example);
    return -1;
}

/* A declaration `word name` that names the scalar state variable `name` for what the
 * program does with it (dissipation, viscousheat, temperature): once a law, not inside an
 * `if` or `tension` block; *field gets 1 + its slot.  what: the declaration's thing ("viscous
 * heat"), example: a state to name.  Returns 0, or -1 after an error at it. */
static int declare_state(Law *L, const MatStmt *s, const char *word, const char *what,
                         const char *example, int *field)
{
    if (L->in_if || L->in_tension) {
        char decl[64];
        snprintf(decl, sizeof decl, "a %s declaration", word);
        return not_in_if(L, s, decl);
    }
    if (*field) {
        diag_error(s->loc, "material '%s' declares its %s twice", L->law->name, what);
        return -1;
    }
    const int slot = scalar_state(L, s, word, example);
    if (slot < 0)
        return -1;
    *field = 1 + slot;
    return 0;
}

/* dissipation name: the scalar state variable `name` accumulates the energy density the law
 * has dissipated (plastic work); the program reports its volume integral per body. */
static int dissipation_stmt(Law *L, const MatStmt *s)
{
    return declare_state(L, s, "dissipation", "dissipation", "state wp = 0",
                         &L->out.dissipation);
}

/* viscousheat name: the program adds to the scalar state variable `name` the energy density
 * [J/m^3 of the reference volume] that the artificial viscosity dissipates at the particle,
 * half of each of its pairs' (templates/body_forces.c), after each step; the law reads it
 * as it reads any state (and should not assign it). */
static int viscous_heat_stmt(Law *L, const MatStmt *s)
{
    return declare_state(L, s, "viscousheat", "viscous heat", "state q = 0",
                         &L->out.viscous_heat);
}

/* temperature name, c: the scalar state variable `name` is the particle's temperature [K],
 * of specific heat c [J/(kg K)] (a constant or an expression of the parameters): the
 * program reports the body's heat, sum m c (T - T at the start), and writes T to the VTU
 * files. */
static int temperature_stmt(Law *L, const MatStmt *s)
{
    LawRoots *r = &L->out;
    if (declare_state(L, s, "temperature", "temperature", "state T = T0", &r->temperature))
        return -1;
    Val c = need_scalar(s->value, eval(L, s->value), "a specific heat");
    if (!ok(c))
        return -1;
    if (body_constant(L, c.s, &r->heat_capacity)) {
        diag_error(s->value->loc, "the specific heat of material '%s' must be a constant or an "
                   "expression of its parameters", L->law->name);
        return -1;
    }
    return 0;
}

/* wavespeed c: the particle's longitudinal wave speed in its current state [m/s], where the
 * law stiffens beyond the body's elastic constants (an equation of state under compression):
 * the time step bound takes it (templates/body_particle.c). */
static int wavespeed_stmt(Law *L, const MatStmt *s)
{
    LawRoots *r = &L->out;
    if (L->in_if || L->in_tension)
        return not_in_if(L, s, "a wave speed");
    if (r->has_wavespeed) {
        diag_error(s->loc, "material '%s' gives its wave speed twice", L->law->name);
        return -1;
    }
    Val c = need_scalar(s->value, eval(L, s->value), "a wave speed");
    if (!ok(c))
        return -1;
    r->has_wavespeed = 1, r->wavespeed = c.s;
    return 0;
}

/* name = expr: a new value of a let or a state variable, of the same type. */
static int assign_stmt(Law *L, const MatStmt *s)
{
    Binding *b = find_binding(L, s->name);
    if (!b) {
        diag_error(s->loc, "'%s' is not a variable of material '%s' (declare it with let or "
                           "state first)",
                   s->name, L->law->name);
        return -1;
    }
    if (!strcmp(s->name, "F")) {
        diag_error(s->loc, "the deformation gradient F cannot be assigned");
        return -1;
    }
    int tensor = b->v.tensor;
    Val v = eval(L, s->value);
    if (!ok(v))
        return -1;
    if (v.tensor != tensor) {
        diag_error(s->value->loc, "'%s' is a %s and cannot take a %s", s->name,
                   tensor ? "tensor" : "scalar", v.tensor ? "tensor" : "scalar");
        return -1;
    }
    bind(L, s->name, v);
    L->env[L->nenv - 1].assigned = 1;
    return 0;
}

/* The assignments a branch made to variables that existed before it (the last of each):
 * names and values in out, their count returned.  Its lets end with it. */
static int branch(Law *L, const MatStmtList *body, int mark, Binding *out, int cap, int *bad)
{
    for (int i = 0; i < body->n; i++)
        *bad |= statement(L, &body->items[i]) != 0;
    int n = 0;
    for (int i = L->nenv - 1; i >= mark; i--) {
        const Binding *b = &L->env[i];
        if (!b->assigned)
            continue;
        int seen = 0;
        for (int k = 0; k < n; k++)
            seen |= !strcmp(out[k].name, b->name);
        if (!seen && n < cap)
            out[n++] = *b;
    }
    L->nenv = mark;
    return n;
}

static const Binding *among(const Binding *list, int n, const char *name)
{
    for (int k = 0; k < n; k++)
        if (!strcmp(list[k].name, name))
            return &list[k];
    return NULL;
}

/* if c { ... } else { ... }: both branches are evaluated; every variable either assigns
 * becomes select(c, its then-value, its else-value), with the value from before the block
 * where a branch leaves it alone (the graph is pure, so this is exact). */
static int if_stmt(Law *L, const MatStmt *s)
{
    Val c = need_scalar(s->value, eval(L, s->value), "the condition of 'if'");
    if (!ok(c))
        return -1;
    enum { CAP = 64 };
    Binding thn[CAP], els[CAP];
    int mark = L->nenv, bad = 0, was = L->in_if;
    if (!was && !L->in_tension && s->orelse.n == 0 && L->out.nrare < LAW_MAX_RARE)
        L->out.rare[L->out.nrare++] = c.s; /* (law_fast) */
    L->in_if = 1;
    int nt = branch(L, &s->body, mark, thn, CAP, &bad);
    int ne = branch(L, &s->orelse, mark, els, CAP, &bad);
    L->in_if = was;
    if (bad)
        return -1;
    for (int pass = 0; pass < 2; pass++) {
        const Binding *list = pass ? els : thn;
        for (int k = 0; k < (pass ? ne : nt); k++) {
            const char *name = list[k].name;
            if (pass && among(thn, nt, name))
                continue; /* merged in the first pass */
            const Binding *pre = find_binding(L, name);
            if (!pre)
                continue; /* a let of the branch itself */
            Val before = pre->v;
            const Binding *a = among(thn, nt, name), *b = among(els, ne, name);
            Val va = a ? a->v : before, vb = b ? b->v : before, m = va;
            if (!va.tensor)
                m.s = sg_select(L->g, c.s, va.s, vb.s);
            else
                for (int q = 0; q < 9; q++)
                    m.t[q] = sg_select(L->g, c.s, va.t[q], vb.t[q]);
            bind(L, name, m);
            L->env[L->nenv - 1].assigned = 1;
        }
    }
    return 0;
}

/* tension { let ...; energy psi = ...; stress S = ... }: the tensile parts psi+ and S+
 * (eq. 11, 17, 20, 31); the energy is required, the stress derived from it where the block
 * does not write it (derive_stresses); the compressive parts are the rest (psi- = psi -
 * psi+, S- = S - S+).  Its names are local to it.  Evaluated only for fracture bodies. */
static int tension_block(Law *L, const MatStmt *blk)
{
    if (L->in_tension || (L->has_stress & 2) || (L->has_energy & 2)) {
        diag_error(blk->loc, "material '%s' has more than one tension block", L->law->name);
        return -1;
    }
    if (!L->want_tension) {
        L->has_stress |= 2; /* present, not needed by this body */
        L->has_energy |= 2;
        return 0;
    }
    int mark = L->nenv, bad = 0;
    L->in_tension = 1;
    for (int i = 0; i < blk->body.n; i++)
        bad |= statement(L, &blk->body.items[i]) != 0;
    L->in_tension = 0;
    L->nenv = mark;
    if (!bad && !(L->has_energy & 2)) {
        diag_error(blk->loc, "the tension block of material '%s' needs 'energy' (psi+; its "
                             "'stress' S+ is derived from it when not written)",
                   L->law->name);
        bad = 1;
    }
    L->out.has_tension = !bad;
    return bad ? -1 : 0;
}

static int statement(Law *L, const MatStmt *s)
{
    if (s->kind == MS_REQUIRE) /* a condition on the parameters (check/law_require.c) */
        return 0;
    L->g->line = s->loc.line;
    L->g->file = s->loc.file;
    Val v;
    switch (s->kind) {
    case MS_LET:
        v = eval(L, s->value);
        if (!ok(v))
            return -1;
        bind(L, s->name, v);
        return 0;
    case MS_STRESS:
        if (L->in_if)
            return not_in_if(L, s, "stress");
        if ((L->in_tension ? 2 : 1) & L->has_stress) {
            diag_error(s->loc, "material '%s' defines its %sstress twice", L->law->name,
                       L->in_tension ? "tensile " : "");
            return -1;
        }
        L->has_stress |= L->in_tension ? 2 : 1;
        v = need_tensor(s->value, eval(L, s->value), "stress");
        if (!ok(v))
            return -1;
        memcpy(L->in_tension ? L->out.Sp : L->out.S, v.t, sizeof v.t);
        bind(L, s->name, v);
        return 0;
    case MS_ENERGY:
        if (L->in_if)
            return not_in_if(L, s, "energy");
        if ((L->in_tension ? 2 : 1) & L->has_energy) {
            diag_error(s->loc, "material '%s' defines its %senergy twice", L->law->name,
                       L->in_tension ? "tensile " : "");
            return -1;
        }
        L->has_energy |= L->in_tension ? 2 : 1;
        v = need_scalar(s->value, eval(L, s->value), "energy");
        if (!ok(v))
            return -1;
        *(L->in_tension ? &L->out.psip : &L->out.psi) = v.s;
        *(L->in_tension ? &L->tension_energy_line : &L->energy_line) = s->loc.line;
        bind(L, s->name, v);
        return 0;
    case MS_BLOCK:
        if (L->in_if)
            return not_in_if(L, s, "a tension block");
        if (!strcmp(s->name, "tension"))
            return tension_block(L, s);
        diag_error(s->loc, "unknown block '%s' in a material law (expected tension)", s->name);
        return -1;
    case MS_STATE:
        return state_stmt(L, s);
    case MS_IF:
        return if_stmt(L, s);
    case MS_ASSIGN:
        return assign_stmt(L, s);
    case MS_DISSIPATION:
        return dissipation_stmt(L, s);
    case MS_TEMPERATURE:
        return temperature_stmt(L, s);
    case MS_VISCOUSHEAT:
        return viscous_heat_stmt(L, s);
    case MS_WAVESPEED:
        return wavespeed_stmt(L, s);
    case MS_REQUIRE: /* a condition on the parameters, no part of the graph (check/law_require.c) */
        return 0;
    }
    return -1;
}

/* F as the law's input; in 2D its out-of-plane entries are constants (folded away), unless
 * the law's stress is to be derived, which needs every entry as a variable. */
static Val F_value(Law *L, int dim, int all_inputs)
{
    Val F = {1, -1, {0}};
    for (int k = 0; k < 9; k++) {
        int r = k / 3, c = k % 3;
        int out_of_plane = dim == 2 && !all_inputs && (r == 1 || c == 1);
        F.t[k] = out_of_plane ? sg_const(L->g, r == c ? 1.0 : 0.0)
                              : sg_input(L->g, LAW_INPUT_F, k);
    }
    return F;
}

/* energy psi(C) or psi(E): the law sees a symmetric C (or E) of six variables instead of F;
 * its derivatives give S, then C = F^T F (E = (C - I) / 2) is put in (variables_to_F). */
static Val symmetric_variable(Law *L, const char *name)
{
    Val v = {1, -1, {0}};
    for (int k = 0; k < 9; k++) {
        const int r = k / 3, c = k % 3;
        v.t[k] = sg_input(L->g, !strcmp(name, "C") ? LAW_INPUT_C : LAW_INPUT_E,
                          r <= c ? k : c * 3 + r);
    }
    return v;
}

/* S = s^2 S+ + (S - S+) (eq. 18), psi = s^2 psi+ + (psi - psi+) (eq. 7). */
static void degrade(SGraph *g, LawRoots *r)
{
    int s = sg_input(g, LAW_INPUT_S, -1);
    int s2 = sg_binary(g, SN_MUL, s, s);
    for (int k = 0; k < 9; k++)
        r->Sd[k] = sg_binary(g, SN_ADD, sg_binary(g, SN_MUL, s2, r->Sp[k]),
                             sg_binary(g, SN_SUB, r->S[k], r->Sp[k]));
    r->psid = sg_binary(g, SN_ADD, sg_binary(g, SN_MUL, s2, r->psip),
                        sg_binary(g, SN_SUB, r->psi, r->psip));
}

/* Whether a list of statements writes a stress (at its top level: not in an if block, nor
 * in a block). */
static int writes_stress(const MatStmtList *body)
{
    for (int i = 0; i < body->n; i++)
        if (body->items[i].kind == MS_STRESS)
            return 1;
    return 0;
}

/* Whether the law has a tension block that gives psi+ only (its S+ to be derived). */
static int derives_tension(const MaterialDef *law)
{
    for (int i = 0; i < law->body.n; i++) {
        const MatStmt *s = &law->body.items[i];
        if (s->kind == MS_BLOCK && !strcmp(s->name, "tension") && !writes_stress(&s->body))
            return 1;
    }
    return 0;
}

/* The plane-strain constants of a 2D F put for its out-of-plane inputs, once the derivatives
 * with respect to them are taken. */
static int plane_strain_entry(const SNode *s, void *ctx)
{
    SGraph *g = ctx;
    const int k = (int)s->v, r = k / 3, c = k % 3;
    if (strcmp(s->name, LAW_INPUT_F) || !(r == 1 || c == 1))
        return -1;
    return sg_const(g, r == c ? 1.0 : 0.0);
}

/* The results of a law: S, psi, the state's end values and, with a tension block, S+ and
 * psi+ (and once degraded, the degraded S and psi): their slots in *r, into slots[];
 * returns how many. */
enum { LAW_MAX_RESULTS = 4 * 9 + 5 + LAW_MAX_SLOTS + LAW_MAX_RARE };
static int result_slots(LawRoots *r, int degraded, int *slots[LAW_MAX_RESULTS])
{
    int n = 0;
    for (int k = 0; k < 9; k++)
        slots[n++] = &r->S[k];
    slots[n++] = &r->psi;
    for (int k = 0; k < r->nslots; k++)
        slots[n++] = &r->next[k];
    for (int k = 0; r->has_tension && k < 9; k++)
        slots[n++] = &r->Sp[k];
    if (r->has_tension)
        slots[n++] = &r->psip;
    for (int k = 0; r->has_tension && degraded && k < 9; k++)
        slots[n++] = &r->Sd[k];
    if (r->has_tension && degraded)
        slots[n++] = &r->psid;
    for (int k = 0; k < r->nrare; k++) /* (rebuilt with the results) */
        slots[n++] = &r->rare[k];
    if (r->has_wavespeed)
        slots[n++] = &r->wavespeed;
    return n;
}

int law_fast(SGraph *g, const LawRoots *r, LawRoots *fast, int *flag)
{
    if (r->nrare == 0 || r->has_tension)
        return -1;
    *fast = *r;
    int *slots[LAW_MAX_RESULTS], roots[LAW_MAX_RESULTS], out[LAW_MAX_RESULTS];
    int zero[LAW_MAX_RARE];
    const int n = result_slots(fast, 0, slots);
    for (int k = 0; k < n; k++)
        roots[k] = *slots[k];
    for (int k = 0; k < r->nrare; k++)
        zero[k] = sg_const(g, 0);
    sg_replace(g, roots, n, r->rare, zero, r->nrare, out);
    for (int k = 0; k < n; k++)
        *slots[k] = out[k];
    /* each condition on the fast path: rebuilt with the others put to 0, itself kept */
    int conds[LAW_MAX_RARE];
    for (int k = 0; k < r->nrare; k++) {
        int from[LAW_MAX_RARE], m = 0;
        for (int j = 0; j < r->nrare; j++)
            if (r->rare[j] != r->rare[k])
                from[m++] = r->rare[j];
        sg_replace(g, &r->rare[k], 1, from, zero, m, &conds[k]);
    }
    fast->nrare = 0;
    *flag = conds[0];
    for (int k = 1; k < r->nrare; k++)
        *flag = sg_binary(g, SN_OR, *flag, conds[k]);
    return 0;
}

/* Every result of the law rebuilt with some inputs replaced (sg_substitute's `input`). */
static void substitute_results(Law *L, int (*input)(const SNode *, void *), void *ctx)
{
    int *slots[LAW_MAX_RESULTS], roots[LAW_MAX_RESULTS], out[LAW_MAX_RESULTS];
    const int n = result_slots(&L->out, 0, slots);
    for (int k = 0; k < n; k++)
        roots[k] = *slots[k];
    sg_substitute(L->g, roots, n, input, ctx, out);
    for (int k = 0; k < n; k++)
        *slots[k] = out[k];
}

/* The 2D plane-strain constants put for F's out-of-plane inputs in every result, once the
 * derivatives with respect to them are taken. */
static void fold_plane_strain(Law *L)
{
    substitute_results(L, plane_strain_entry, L->g);
}

/* The state slots put to 0 (zero_state_entry's set). */
typedef struct {
    SGraph *g;
    const char *zero; /* zero[k]: slot k is 0 */
} ZeroState;

static int zero_state_entry(const SNode *s, void *ctx)
{
    const ZeroState *z = ctx;
    if (strcmp(s->name, LAW_INPUT_STATE) || s->v < 0 || !z->zero[(int)s->v])
        return -1;
    return sg_const(z->g, 0);
}

/* State slots that start at 0 and that the law leaves at 0 as long as they are 0 (the
 * out-of-plane entries of J2's plastic metric Cp in 2D plane strain, where F's are 0): 0 in
 * every result, so that the emitted law leaves out what they multiply.  The largest such
 * set: every slot that starts at 0, less those whose end value does not fold to 0 with the
 * set put to 0, until none is left out.  (The state's values come from the law alone: its
 * constant initial values, then its end values step by step; except the `viscousheat`
 * slot, to which the program adds, never taken for 0.) */
static void fold_zero_state(Law *L)
{
    LawRoots *r = &L->out;
    char zero[LAW_MAX_SLOTS] = {0};
    int nzero = 0;
    for (int k = 0; k < r->nslots; k++)
        nzero += zero[k] = r->init[k] == 0 && k != r->viscous_heat - 1;
    ZeroState z = {L->g, zero};
    for (int changed = nzero > 0; changed;) {
        int next[LAW_MAX_SLOTS];
        sg_substitute(L->g, r->next, r->nslots, zero_state_entry, &z, next);
        changed = 0;
        for (int k = 0; k < r->nslots; k++) {
            double v;
            if (zero[k] && !(sg_is_const(L->g, next[k], &v) && v == 0)) {
                zero[k] = 0, nzero--;
                changed = 1;
            }
        }
    }
    if (nzero > 0)
        substitute_results(L, zero_state_entry, &z);
}

/* S = F^-1 dpsi/dF (eq. 10, 17: S = 2 dpsi/dC) of energy psi, under the energy's line:
 * the stress of a law that gives only its energy (a hyperelastic law is its strain energy;
 * P = dpsi/dF, S = F^-1 P), and S+ of a tension block that gives only psi+ (eq. 11, 17).
 * A law with state is differentiated at its returned state: the state's values at the end
 * of the step are held fixed (for J2, 2 dpsi/dC at the returned C_p, eq. 37-38).  pos and
 * neg differentiate by their adjoint routine (spectral.c).  Returns 0, or -1 after
 * reporting. */
static int derive(Law *L, int psi, int line, int S[9])
{
    const Val F = L->of ? L->var : find_binding(L, "F")->v;
    int P[9];
    L->g->line = line;
    if (sg_derivatives_held(L->g, psi, F.t, 9, L->out.next, L->out.nslots, P)) {
        diag_error(L->law->loc, "material '%s': its energy uses a runtime routine that sphc "
                   "cannot differentiate; write its stress", L->law->name);
        return -1;
    }
    if (L->of) { /* S = 2 dpsi/dC or dpsi/dE; an off-diagonal variable stands for two entries */
        const double diag = !strcmp(L->of, "C") ? 2.0 : 1.0;
        for (int k = 0; k < 9; k++)
            S[k] = sg_binary(L->g, SN_MUL, sg_const(L->g, k % 4 ? 0.5 * diag : diag),
                             P[k / 3 <= k % 3 ? k : (k % 3) * 3 + k / 3]);
        return 0;
    }
    Val Pv = {1, -1, {0}};
    memcpy(Pv.t, P, sizeof P);
    Val Sv = t_matmul(L, t_inverse(L, F), Pv);
    memcpy(S, Sv.t, sizeof Sv.t);
    return 0;
}

/* The stresses the law does not write, derived from its energies: S from psi, S+ from psi+
 * (the tension block's); in 2D the plane-strain constants are then put for F's
 * out-of-plane entries (unless the energy is a function of C or E: variables_to_F). */
static int derive_stresses(Law *L, int dim, int stress, int tension)
{
    if (stress && derive(L, L->out.psi, L->energy_line, L->out.S))
        return -1;
    if (tension && derive(L, L->out.psip, L->tension_energy_line, L->out.Sp))
        return -1;
    if (dim == 2 && !L->of)
        fold_plane_strain(L);
    return 0;
}

/* The variable the law's energy is a function of (energy psi(C) or psi(E)), or NULL; "" after
 * reporting another. */
static const char *energy_variable(const MaterialDef *law)
{
    for (int i = 0; i < law->body.n; i++) {
        const MatStmt *s = &law->body.items[i];
        if (s->kind != MS_ENERGY || !s->of)
            continue;
        if (!strcmp(s->of, "C") || !strcmp(s->of, "E"))
            return s->of;
        diag_error(s->loc, "energy %s(%s): an energy is a function of C (= F^T F) or E "
                   "(= (C - I) / 2)", s->name, s->of);
        return "";
    }
    return NULL;
}

/* C (or E) of F put for the law's symmetric variables, in every result. */
static int input_of_F(const SNode *s, void *ctx)
{
    const Val *v = ctx;
    return !strcmp(s->name, LAW_INPUT_C) || !strcmp(s->name, LAW_INPUT_E) ? v->t[(int)s->v] : -1;
}

static void variables_to_F(Law *L, int dim)
{
    Val F = F_value(L, dim, 0);
    L->g->line = L->energy_line;
    Val v = t_matmul(L, t_transpose(F), F);
    if (!strcmp(L->of, "E"))
        v = t_map2(L, SN_MUL, t_map2(L, SN_SUB, v, identity(L)), scalar(sg_const(L->g, 0.5)));
    substitute_results(L, input_of_F, &v);
}

/* A constant that is not finite in what the law computes (a division by zero, the inverse
 * of a singular constant tensor) is the model's error, at the line that computes it, not
 * the C compiler's on the generated code.  Returns 0, or -1 after reporting. */
static int finite_results(const SGraph *g, const MaterialDef *law, const double *params,
                          LawRoots *r)
{
    int *slots[LAW_MAX_RESULTS], roots[LAW_MAX_RESULTS];
    const int n = result_slots(r, 1, slots);
    for (int k = 0; k < n; k++)
        roots[k] = *slots[k];
    const int id = sg_first_nonfinite(g, roots, n);
    if (id < 0)
        return 0;
    const SNode *s = &g->nodes[id];
    SrcLoc loc = {s->file, s->line, 0};
    char values[512] = "";
    for (int k = 0, len = 0; params && k < law->nparams && len < (int)sizeof values - 64; k++)
        len += snprintf(values + len, sizeof values - (size_t)len, "%s%s = %g", k ? ", " : " with ",
                        law->params[k], params[k]);
    diag_error(loc, "material '%s' computes %s here%s (a division by zero, or the inverse of a "
                    "singular tensor)", law->name, isnan(s->v) ? "NaN" : "an infinite value", values);
    return -1;
}

/* The location of the law's energy statement at line (the law's or its tension block's). */
static SrcLoc energy_loc(const MaterialDef *law, int line)
{
    for (int i = 0; i < law->body.n; i++) {
        const MatStmt *s = &law->body.items[i];
        if (s->kind == MS_ENERGY && s->loc.line == line)
            return s->loc;
        for (int j = 0; s->kind == MS_BLOCK && j < s->body.n; j++)
            if (s->body.items[j].kind == MS_ENERGY && s->body.items[j].loc.line == line)
                return s->body.items[j].loc;
    }
    return (SrcLoc){law->loc.file, line, 0};
}

/* An energy is a function of the deformation and the state: one that reads the step of the
 * update dt or a rate other than through the state's end values (held, as for the derived
 * stress) is a modelling error, at its line.  Returns 0, or -1 after reporting. */
static int energy_reads_rate(Law *L)
{
    const struct { int psi, line, on; const char *what; } energies[] = {
        {L->out.psi, L->energy_line, 1, "energy"},
        {L->out.psip, L->tension_energy_line, L->out.has_tension, "tensile energy"},
    };
    static const char *const rates[][2] = {
        {LAW_INPUT_DT, "dt"},
        {LAW_INPUT_FDOT, "a rate (Fdot, Cdot or Edot)"},
    };
    for (int k = 0; k < 2; k++)
        for (int q = 0; q < 2 && energies[k].on; q++) {
            if (sg_input_reached(L->g, energies[k].psi, L->out.next, L->out.nslots,
                                 rates[q][0]) < 0)
                continue;
            diag_error(energy_loc(L->law, energies[k].line), "the %s of material '%s' reads %s: "
                       "an energy is a function of the deformation and the state; a rate enters "
                       "through the state's update (state Cv = ..., Cv = ... dt ...), whose end "
                       "value the energy may read, or a written stress", energies[k].what,
                       L->law->name, rates[q][1]);
            return -1;
        }
    return 0;
}

int law_reads(const SGraph *g, const LawRoots *r, const char *input)
{
    LawRoots copy = *r;
    int *slots[LAW_MAX_RESULTS];
    const int n = result_slots(&copy, copy.has_tension, slots);
    for (int k = 0; k < n; k++)
        if (sg_input_reached(g, *slots[k], NULL, 0, input) >= 0)
            return 1;
    return 0;
}

int law_build(SGraph *g, const Model *m, const MaterialDef *law, const BodyModel *b, int dim,
              int tension, LawRoots *out)
{
    Law L = {0};
    L.want_tension = tension;
    L.m = m;
    L.g = g;
    L.law = law;
    L.params = b ? b->law_args : NULL;
    L.rho0 = b ? b->rho0 : NAN;
    L.dim = dim;
    L.g->line = law->loc.line;
    L.g->file = law->loc.file;
    const int derived = !writes_stress(&law->body);
    const int derived_p = tension && derives_tension(law);
    L.of = energy_variable(law);
    if (L.of && !*L.of)
        return -1;
    if (L.of)
        bind(&L, L.of, L.var = symmetric_variable(&L, L.of));
    else
        bind(&L, "F", F_value(&L, dim, derived || derived_p));
    int bad = 0;
    for (int i = 0; i < law->body.n; i++)
        bad |= statement(&L, &law->body.items[i]) != 0;
    if (!bad && !(L.has_energy & 1)) {
        diag_error(law->loc, "material '%s' defines no 'energy'%s", law->name,
                   derived ? " (nor 'stress')" : "");
        bad = 1;
    }
    for (int v = 0; !bad && v < L.out.nstates; v++) { /* the state's values at the end */
        const LawState *st = &L.out.states[v];
        Val end = find_binding(&L, st->name)->v;
        for (int k = 0; k < st->size; k++)
            L.out.next[st->offset + k] = st->size == 1 ? end.s : end.t[k];
    }
    if (!bad)
        bad = energy_reads_rate(&L) != 0;
    if (!bad && (derived || (derived_p && L.out.has_tension)))
        bad = derive_stresses(&L, dim, derived, derived_p && L.out.has_tension) != 0;
    if (!bad && L.of)
        variables_to_F(&L, dim);
    if (!bad && dim == 2)
        fold_zero_state(&L);
    free(L.env);
    if (!bad && L.out.has_tension) {
        L.g->line = law->loc.line; /* the degradation is the law's as a whole */
        degrade(L.g, &L.out);
    }
    if (!bad)
        bad = finite_results(L.g, law, L.params, &L.out) != 0;
    if (!bad)
        *out = L.out;
    return bad ? -1 : 0;
}

int law_check(const Model *m, const MaterialDef *law)
{
    for (int i = 0; i < law->nparams; i++)
        for (int j = 0; j < i; j++)
            if (!strcmp(law->params[i], law->params[j])) {
                diag_error(law->param_locs[i], "parameter '%s' given twice", law->params[i]);
                return -1;
            }
    SGraph g;
    sg_init(&g);
    LawRoots roots;
    int r = law_build(&g, m, law, NULL, 3, 1, &roots);
    sg_free(&g);
    return r;
}
