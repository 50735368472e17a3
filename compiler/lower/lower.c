/* lower.c — from the checked model to per-body kernel plans: dead-feature elimination
 * (only what the body uses is switched on) and the material law folded for the body's
 * constants and dimension. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "plan.h"
#include "lang/bc_kinds.h"
#include "lang/builtins.h"
#include "util/diag.h"

/* The body's BCs of that pass that set something (in 2D, not only out-of-plane components). */
static int bcs_applied(const BodyModel *b, BcPass pass)
{
    int n = 0;
    for (int k = 0; k < b->nbcs; k++)
        n += BC_KIND[b->bcs[k].kind].pass == pass && b->bcs[k].comps;
    return n;
}

/* Whether the CPU's stress pass copies a block of particles' values entry by entry before
 * the law runs on them (templates/body_forces.c, STAGED), rather than reading the body's
 * arrays in the loop over particles.  Read in place, the compiler vectorises that loop for a
 * 2D law without state; it cannot for 3D tensors or a law's state (runs of 9, 11 or 12
 * values a particle), and there the copies pay: the 3D column's step took 0.89 of its time
 * so, the Taylor bar's 0.93 (laws that call exp, log or pow: their vector forms replace
 * several scalar calls), the 3D plate's stress pass 0.78-0.86 (SVK, sums and products
 * alone; GCC 12 and AVX-512: on an AVX2 machine with an older compiler its step had taken
 * 1.04).  A runtime routine (the 3D spectral split) is not vectorised at all. */
static int stress_staged(const Model *m, const LawRoots *r, const SGraph *law)
{
    if (m->dim == 2 && r->nslots == 0)
        return 0;
    int calls = 0;
    for (int id = 0; id < law->n; id++) {
        const SNode *nd = &law->nodes[id];
        if (nd->op == SN_EXT)
            return 0;
        calls |= (nd->op == SN_CALL && nd->fn != BI_sqrt) || nd->op == SN_POW;
    }
    return calls || m->dim == 3; /* (a 2D law with state and no calls: not measured) */
}

_Static_assert(BODY_NSETTINGS <= 32, "BodyPlan.terms has a bit per body setting");

/* The settings of body b that switch a term of its code on (BodyPlan.terms). */
static unsigned setting_terms(const BodyModel *b)
{
    unsigned terms = 0;
    for (int k = 0; k < BODY_NSETTINGS; k++)
        if (BODY_SETTING_ROWS[k].sw && body_setting_value(b, &BODY_SETTING_ROWS[k]) != 0)
            terms |= 1u << k;
    return terms;
}

/* Each row of PLAN_FEATURES (plan.h) for body b of model m, with its law's roots r, after
 * the terms of its settings. */
static void features(const Model *m, const BodyModel *b, const LawRoots *r, BodyPlan *p)
{
    p->terms = setting_terms(b);
#define PLAN_VALUE(member, name, sw, value) p->member = (value);
    PLAN_FEATURES(PLAN_VALUE)
#undef PLAN_VALUE
}

#define PLAN_ROW(member, key, value, when) +1
_Static_assert(0 PLAN_NUMBERS(PLAN_ROW) <= 32, "BodyPlan.numbers has a bit per row of PLAN_NUMBERS");
#undef PLAN_ROW

/* The factor (c0 / c)^2 on the squared stretch of the compression bound where the wave speed
 * c that body b's law gives at rest exceeds its c0 (the stress pass's factor, templates/
 * body_particle.c), 1 otherwise: the bound before the first stress pass. */
static double lam2_rest(const BodyModel *b, const BodyPlan *p)
{
    if (p->roots.wavespeed < 0 || p->roots.wavespeed >= p->law.n) /* (a law that did not build) */
        return 1;
    const double c = law_wavespeed_at_rest(&p->law, &p->roots);
    return isfinite(c) && c > b->c0 ? (b->c0 / c) * (b->c0 / c) : 1;
}

/* Each row of PLAN_NUMBERS (plan.h) that holds for body b, after its features. */
static void numbers(const Model *m, const BodyModel *b, BodyPlan *p)
{
    int k = 0;
#define PLAN_VALUE(member, key, value, when)                                                  \
    if (when) {                                                                                \
        p->member = (value);                                                                   \
        p->numbers |= 1u << k;                                                                 \
    }                                                                                          \
    k++;
    PLAN_NUMBERS(PLAN_VALUE)
#undef PLAN_VALUE
}

/* Whether body i is the first to use its law: a law's stress is checked against its energy
 * once, with that body's parameter values. */
static int first_use(const Model *m, int i)
{
    for (int j = 0; j < i; j++)
        if (m->bodies[j].law == m->bodies[i].law)
            return 0;
    return 1;
}

/* What body b's law cannot be combined with, once its features p are known: an error (or a
 * warning, for what only goes unused) at the setting that makes it so.  Returns whether an
 * error was reported. */
static int law_combinations(const Model *m, const BodyModel *b, const BodyPlan *p)
{
    int bad = 0;
    if (p->law_fdot && m->gradient == GRADIENT_QUADRATIC) {
        diag_error(m->gradient_loc, "'gradient quadratic' with a law that reads a rate (body "
                   "'%s', material '%s'): the rate of F comes from the linear corrected "
                   "gradient; 'gradient linear' serves it", b->name, b->law->name);
        bad = 1;
    }
    if (p->law_wave && p->fracture) {
        diag_error(b->fracture.loc, "fracture cannot be combined with material '%s', which "
                   "gives its wave speed (an equation of state)", b->law->name);
        bad = 1;
    }
    if (p->law_wave && !p->crush)
        diag_warning(b->loc, "'timestep undeformed' keeps the paper's time step "
                     "on the undeformed spacing: the wave speed material '%s' gives (body "
                     "'%s') does not bound it", b->law->name, b->name);
    if (p->roots.viscous_heat && !p->viscosity)
        diag_warning(b->loc, "material '%s' takes in the artificial viscosity's heat "
                     "(`viscousheat`), but body '%s' has no viscosity: its heat stays 0",
                     b->law->name, b->name);
    if (p->fracture && (p->law_dt || p->law_fdot)) {
        diag_error(b->fracture.loc, "fracture cannot be combined with material '%s', which "
                   "reads %s: the paper's phase field is for elastic materials (section "
                   "2.3.3, remark 3)", b->law->name, p->law_dt ? "dt" : "a rate");
        bad = 1;
    }
    return bad;
}

/* The operations of outputs o[0 .. no-1] of body p's law. */
static int outputs_operations(const BodyPlan *p, const LawOutput *o, int no)
{
    int roots[PLAN_MAX_ROOTS];
    return sg_operations(&p->law, roots, plan_output_roots(o, no, roots));
}

/* count over body p's law: its material function's outputs, and its fast path's where it has
 * one. */
static int over_law(const BodyPlan *p, int (*count)(const BodyPlan *, const LawOutput *, int))
{
    LawOutput o[LAW_MAX_OUTPUTS + 1];
    int n = count(p, o, plan_law_outputs(p, p->fracture, o));
    if (p->rare)
        n += count(p, o, plan_law_fast_outputs(p, o));
    return n;
}

int plan_law_operations(const BodyPlan *p)
{
    return over_law(p, outputs_operations);
}

/* The calls (pow and the built-in functions: exp, sqrt, ...) among the operations of outputs
 * o[0 .. no-1] of body p's law. */
static int outputs_calls(const BodyPlan *p, const LawOutput *o, int no)
{
    int roots[PLAN_MAX_ROOTS];
    const int nroots = plan_output_roots(o, no, roots);
    char *live = calloc((size_t)p->law.n + 1, 1);
    sg_mark_live(&p->law, roots, nroots, live);
    int calls = 0;
    for (int id = 0; id < p->law.n; id++)
        calls += live[id] && (p->law.nodes[id].op == SN_POW || p->law.nodes[id].op == SN_CALL);
    free(live);
    return calls;
}

int plan_law_calls(const BodyPlan *p)
{
    return over_law(p, outputs_calls);
}

/* A law with more operations for body b than limit: an error at the law's line, 1; 0
 * otherwise. */
static int law_too_large(const BodyModel *b, const BodyPlan *p, int limit, const char *whose)
{
    const int n = plan_law_operations(p);
    if (n <= limit)
        return 0;
    diag_error(b->law->loc, "material '%s' has %d operations for body '%s' (its material "
               "functions, constants folded), more than the %d a material law may have%s",
               b->law->name, n, b->name, limit, whose);
    return 1;
}

int plan_laws_beyond(const Plan *plan, int limit, const char *whose)
{
    int beyond = 0;
    for (int i = 0; i < plan->nbodies; i++)
        beyond |= law_too_large(&plan->model->bodies[i], &plan->bodies[i], limit, whose);
    return beyond;
}

int lower_model(const Model *m, Plan *plan)
{
    int bad = 0;
    const int errors = diag_error_count(); /* with --strict, warnings count too */
    plan->model = m;
    plan->nbodies = m->nbodies;
    plan->bodies = calloc((size_t)m->nbodies, sizeof *plan->bodies);
    plan->contact = model_has_contact(m);
    plan->fracture = 0;
    for (int i = 0; i < m->nbodies; i++) {
        const BodyModel *b = &m->bodies[i];
        BodyPlan *p = &plan->bodies[i];
        memset(p, 0, sizeof *p);
        sg_init(&p->law);
        int built =
            law_build(&p->law, m, b->law, b, m->dim, b->fracture.on, &p->roots) == 0;
        if (built && law_verify_finite(b, &p->law, &p->roots))
            built = 0;
        if (built && first_use(m, i))
            law_verify(m, b);
        if (built)
            law_verify_moduli(m, b);
        const double c = p->roots.heat_capacity;
        if (built && p->roots.temperature && !(c > 0 && isfinite(c))) {
            diag_error(b->loc, "body '%s': material '%s' gives a specific heat of %g J/(kg K): "
                       "it must be a positive number", b->name, b->law->name, c);
            built = 0;
        }
        bad |= !built;
        p->nstate = p->roots.nslots;
        /* the quadratic gradient's strain-gradient term is elastic (templates/body_quadratic.c):
         * where a law with state flows, it resists the flow's gradients */
        if (built && p->nstate > 0 && m->gradient == GRADIENT_QUADRATIC)
            diag_warning(m->gradient_loc, "'gradient quadratic' with a law that has state (body "
                         "'%s', material '%s'): the cells' strain-gradient term stays elastic "
                         "and resists plastic flow (the Taylor bar's foot 30 %% too narrow at "
                         "dp 1 mm, docs/verification.md); 'gradient linear' suits flow",
                         b->name, b->law->name);
        features(m, b, &p->roots, p);
        if (built && law_combinations(m, b, p))
            bad = 1;
        if (p->rare && law_fast(&p->law, &p->roots, &p->fast, &p->fast_flag))
            p->rare = 0;
        if (built && law_too_large(b, p, LAW_MAX_OPERATIONS, ""))
            bad = 1;
        numbers(m, b, p);
        plan->fracture |= p->fracture;
    }
    bad |= diag_error_count() > errors;
    if (bad)
        plan_free(plan);
    return bad ? -1 : 0;
}

void plan_free(Plan *plan)
{
    for (int i = 0; i < plan->nbodies; i++)
        sg_free(&plan->bodies[i].law);
    free(plan->bodies);
    plan->bodies = NULL;
    plan->nbodies = 0;
}

/* The outputs of the law with roots r (the law's, or its fast path's) and nstate state
 * values. */
static int roots_outputs(const LawRoots *r, int nstate, int degraded,
                         LawOutput out[LAW_MAX_OUTPUTS])
{
    if (degraded) {
        out[0] = (LawOutput){"S", "S", r->Sd, 9};
        out[1] = (LawOutput){"*psi", "psi", &r->psid, -1};
        out[2] = (LawOutput){"*psip", "psi+", &r->psip, -1};
    } else {
        out[0] = (LawOutput){"S", "S", r->S, 9};
        out[1] = (LawOutput){"*psi", "psi", &r->psi, -1};
        out[2] = (LawOutput){"st_new", "st_new", r->next, nstate};
        if (r->has_wavespeed) {
            out[3] = (LawOutput){"*cw", "c", &r->wavespeed, -1};
            return 4;
        }
    }
    return 3;
}

int plan_law_outputs(const BodyPlan *p, int degraded, LawOutput out[LAW_MAX_OUTPUTS])
{
    return roots_outputs(&p->roots, p->nstate, degraded, out);
}

int plan_law_fast_outputs(const BodyPlan *p, LawOutput out[LAW_MAX_OUTPUTS + 1])
{
    int no = roots_outputs(&p->fast, p->nstate, 0, out);
    out[no++] = (LawOutput){"*rare", "rare", &p->fast_flag, -1};
    return no;
}

int plan_output_roots(const LawOutput *o, int no, int roots[PLAN_MAX_ROOTS])
{
    int nroots = 0;
    for (int k = 0; k < no; k++)
        for (int q = 0; q < (o[k].n < 0 ? 1 : o[k].n); q++)
            roots[nroots++] = o[k].ids[q];
    return nroots;
}
