/* plan.h — the third stage's product: the lowered kernel plan of each body, which features
 * its code needs and its material law as a folded scalar graph.  Computed once from the
 * checked model (lower.c); the emitters only read it. */
#ifndef SPHC_PLAN_H
#define SPHC_PLAN_H

#include <stdio.h>

#include "model/model.h"
#include "ir/law.h"

/* The features of a body's code, one row each:
 *
 *   X(member, name in --dump=plan (NULL: not listed), switch in templates/, value)
 *
 * The value is computed by lower.c from the model m, the body b and its law's roots r.  The
 * plan has an int member for each; a template's //@if SWITCH keeps its lines where the
 * member is nonzero (//@else where it is zero), and --dump=plan prints name=member in this
 * order.  A new feature is one row here; a body setting's term is a row of the settings'
 * table instead (model/body_settings.h: `terms` below). */
#define PLAN_FEATURES(X)                                                                           \
    X(viscosity, "viscosity", VISCOSITY, b->beta1 > 0 || b->beta2 > 0) /* eq. 57-60 */             \
    X(beta2, "beta2", BETA2, b->beta2 > 0) /* the quadratic term of eq. 58 */                      \
    X(gravity, "gravity", GRAVITY, m->gravity[0] || m->gravity[1] || m->gravity[2])                \
    X(velocity_bcs, "velocity_bcs", VELOCITY_BCS, bcs_applied(b, BC_VELOCITY) > 0)                 \
    X(force_bcs, "force_bcs", FORCE_BCS, bcs_applied(b, BC_FORCE) > 0)                             \
    X(fracture, "fracture", FRACTURE, b->fracture.on) /* phase field, eq. 6-9, 61-63 */            \
    X(restrict_phase, "restrict", RESTRICT, b->fracture.restrict_expr != NULL)                     \
    X(state, "state", STATE, r->nslots > 0) /* its law has state (plasticity) */                   \
    X(vheat, NULL, VHEAT, r->viscous_heat > 0 && p->viscosity) /* the viscosity's heat to it */ \
    X(law_dt, NULL, LAW_DT, law_reads(&p->law, r, LAW_INPUT_DT)) /* its law reads dt */      \
    X(law_fdot, NULL, LAW_FDOT, law_reads(&p->law, r, LAW_INPUT_FDOT)) /* ... and Fdot */   \
    X(law_wave, NULL, LAW_WAVE, r->has_wavespeed) /* it gives its wave speed */             \
    X(contact, "contact", CONTACT, model_has_contact(m)) /* between the scene's bodies */          \
    X(crush, "crush", CRUSH, model_has_crush(m)) /* time step bound on compression */              \
    X(measure, "measure", MEASURE, b->nmeasures > 0) /* measurement planes */                      \
    X(bc_fns, "bc_fns", BC_FNS, bcs_applied(b, BC_VELOCITY) + bcs_applied(b, BC_FORCE))            \
    X(quadratic, "quadratic", QUADRATIC, m->gradient == GRADIENT_QUADRATIC) /* body_quadratic.c */ \
    X(clamp, NULL, CLAMP, b->has_clamp) /* a clamp by mirror images (runtime/run/clamp.c) */    \
    X(symplectic, NULL, SYMPLECTIC, m->integrator == INTEGRATOR_SYMPLECTIC) /* else Verlet */      \
    X(pair_terms, NULL, PAIR_TERMS, plan_has_pair_terms(p)) /* any term of B_pair_terms */       \
    X(pair_v, NULL, PAIR_V, /* pairs read v of a neighbour */                                 \
      p->viscosity || p->pair_terms || p->law_fdot)                                            \
    X(f_every_step, NULL, F_EVERY_STEP, /* its steps read F (the hourglass term, the fit) */  \
      p->pair_terms || p->quadratic)                                                           \
    X(dim3, NULL, DIM3, m->dim == 3) /* else 2D (plane strain) */                               \
    X(simd, NULL, SIMD, !m->no_simd) /* loops over particles vectorised (not --no-simd) */      \
    X(stencil, NULL, STENCIL, m->dim == 2 && !m->no_simd) /* 2D: the lattice stencil's code */ \
    X(staged, NULL, STAGED, stress_staged(m, r, &p->law)) /* the CPU's stress pass by blocks */ \
    X(rare, NULL, RARE, p->staged && !p->fracture && r->nrare > 0) /* and its law's fast path */ \
    X(stencil_momentum, NULL, STENCIL_MOMENTUM, /* the CPU's 2D momentum pass by the stencil */ \
      !layout_stencil_momentum_refused(m, p))                                                  \
    X(offset_blocks, NULL, OFFSET_BLOCKS, /* the CPU's gradient by offset blocks */            \
      !layout_gradient_blocks_refused(m, p))                                                   \
    X(momentum_blocks, NULL, MOMENTUM_BLOCKS, /* and momentum pass (layouts.c) */              \
      !layout_momentum_blocks_refused(m, p))

/* The numbers of a body's code that the templates read, one row each:
 *
 *   X(member, key in templates/, value, when)
 *
 * computed by lower.c where `when` holds (from m, b and its features p); a template reads
 * the member's value as @KEY@ (a key not bound is an error where a template uses it). */
#define PLAN_NUMBERS(X)                                                                            \
    X(beta1, BETA1, b->beta1, 1) /* eq. 58 */                                                      \
    X(beta2_value, BETA2, b->beta2, 1)                                                             \
    X(c0, C0, b->c0, 1) /* eq. 59 */                                                               \
    X(lam2_rest, LAM2_REST, lam2_rest(b, p), p->law_wave) /* the bound's stretch at rest (desc) */  \
    X(vheat_slot, VHEAT_SLOT, p->roots.viscous_heat - 1, p->vheat) /* its state value */        \
    X(hg, HG, 0.5 * b->hourglass * b->E, 1) /* alpha E / 2 */                                      \
    X(g0, G0, m->gravity[0], 1) /* gravity, compact components */                                  \
    X(g1, G1, m->dim == 2 ? m->gravity[2] : m->gravity[1], 1)                                      \
    X(g2, G2, m->dim == 2 ? 0.0 : m->gravity[2], 1)                                                \
    X(gc, GC, b->fracture.Gc, p->fracture)                                                         \
    X(eps0, EPS0, b->fracture.eps0, p->fracture)                                                   \
    X(slimit, SLIMIT, b->fracture.limit, p->fracture) /* s_l of eq. 63 */                          \
    X(pf_a, PF_A, b->c0 * b->c0 / (2 * b->fracture.eps0), p->fracture) /* c^2 / (2 eps0) */ \
    X(qlambda, QLAMBDA, b->lambda, p->quadratic) /* the strain-gradient term's moduli */           \
    X(qmu, QMU, b->mu, p->quadratic)

typedef struct {
#define PLAN_MEMBER(member, name, sw, value) int member;
    PLAN_FEATURES(PLAN_MEMBER)
#undef PLAN_MEMBER
#define PLAN_NUMBER(member, key, value, when) double member;
    PLAN_NUMBERS(PLAN_NUMBER)
#undef PLAN_NUMBER
    unsigned numbers;   /* bit k: row k of PLAN_NUMBERS holds (its `when`) */
    /* bit k: row k of the body settings' table (model/body_settings.h) has a switch and the
     * body's value is nonzero: its template switch is on and its key holds the value */
    unsigned terms;
    int nstate;         /* state values per particle of its law (plasticity); 0: none */
    SGraph law;         /* the material law, constants folded, for this body's dimension */
    LawRoots roots;
    LawRoots fast;      /* with `rare`: the law as if no rare `if` were taken (law_fast) */
    int fast_flag;      /* and the node that says one should have been */
} BodyPlan;

/* The plan of a whole scene. */
typedef struct {
    const Model *model;
    BodyPlan *bodies;   /* model->nbodies plans */
    int nbodies;
    int contact;        /* contact between the bodies (model_has_contact) */
    int fracture;       /* some body has phase-field fracture */
} Plan;

/* Whether a setting of body p switches on a pair term (BodyPlan.terms; a pair row of
 * model/body_settings.h). */
static inline int plan_has_pair_terms(const BodyPlan *p)
{
    for (int k = 0; k < BODY_NSETTINGS; k++)
        if (BODY_SETTING_ROWS[k].pair && (p->terms >> k & 1))
            return 1;
    return 0;
}

/* Why the CPU's offset blocks cannot run body p's gradient or momentum pass, or the 2D
 * lattice stencil its momentum pass (a phrase for --dump=plan), or NULL where they can; the
 * features above that follow from them are computed first (layouts.c). */
const char *layout_gradient_blocks_refused(const Model *m, const BodyPlan *p);
const char *layout_momentum_blocks_refused(const Model *m, const BodyPlan *p);
const char *layout_stencil_momentum_refused(const Model *m, const BodyPlan *p);
/* The layout of each of body p's pair passes on the CPU, with its reason (--dump=plan; the
 * CUDA target's passes go by the device's full lists). */
void layouts_dump(const Model *m, const BodyPlan *p, FILE *out);

/* Returns 0, or -1 after reporting (and freeing what it built). */
int lower_model(const Model *m, Plan *plan);
void plan_free(Plan *plan);

/* An output of a body's material function: `c_name[k] = ids[k]` for k < n in the generated
 * function (`c_name = ids[0]` for n = -1), shown as `label` in --dump=plan. */
typedef struct {
    const char *c_name, *label;
    const int *ids;
    int n;
} LawOutput;

enum { LAW_MAX_OUTPUTS = 4 };
/* The most graph nodes the outputs of a material function hold (S, psi, the state, the wave
 * speed, a flag). */
enum { PLAN_MAX_ROOTS = 9 + 1 + LAW_MAX_SLOTS + 1 + 1 };

/* The outputs of body p's material function in the order of its arguments: S, psi, the
 * state at the end of the step and the wave speed (a law that gives it); degraded (fracture,
 * eq. 7 and 18): S, psi and psi+.  Returns their number. */
int plan_law_outputs(const BodyPlan *p, int degraded, LawOutput out[LAW_MAX_OUTPUTS]);
/* The outputs of its fast path (a body with `rare`): S, psi, the state and `*rare`, the flag
 * that a rare `if` was due. */
int plan_law_fast_outputs(const BodyPlan *p, LawOutput out[LAW_MAX_OUTPUTS + 1]);
/* The graph nodes of outputs o[0 .. no-1], in order, into roots; returns their number.  (The
 * graph computing them is printed by graph_print.h.) */
int plan_output_roots(const LawOutput *o, int no, int roots[PLAN_MAX_ROOTS]);

/* The operations of body p's material functions, constants folded (their outputs'
 * sg_operations): its law's, and its fast path's where it has one. */
int plan_law_operations(const BodyPlan *p);
/* How many of them are calls: pow and the built-in functions (exp, sqrt, ...). */
int plan_law_calls(const BodyPlan *p);
/* The most operations a body's material functions may have (plan_law_operations): the C
 * compiler's time grows with it, linearly once the law is printed in
 * pieces (graph_print.h); a larger law is an error at its line.  nvcc takes some 3 ms an
 * operation where gcc takes 0.15 ms: the CUDA target's limit is lower. */
enum { LAW_MAX_OPERATIONS = 200000, LAW_MAX_OPERATIONS_CUDA = 16000 };
/* Each body whose law has more than limit operations: an error at the law's line, the limit
 * `whose` (" on the CUDA target", or ""); whether there was one. */
int plan_laws_beyond(const Plan *plan, int limit, const char *whose);

/* Print the plan (sphc --dump=plan): each body's features and its law's graph. */
void plan_dump(const Plan *plan, FILE *out);

#endif
