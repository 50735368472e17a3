/* layouts.c — which loop layout runs each pair pass of a body on the CPU, and why.
 *
 * The pair terms are written once (templates/physics/pairs.c); the layouts are the loops
 * that call them: the half lists (every body), the lattice stencil (2D: runs of particles
 * whose neighbours lie at the same offsets) and the offset blocks (3D: eight particles of a
 * lattice in the lanes of a vector).  A layout that cannot serve a body's features is a
 * decision made here, once, with its reason: the plan's switches (OFFSET_BLOCKS,
 * MOMENTUM_BLOCKS) follow from it, and --dump=plan prints it.  (Where a body's particles do
 * not fill a layout's lanes well enough, the run-time set-up keeps the lists:
 * runtime/pairs/offset_blocks.c, runtime/pairs/stencil.c; summary.json counts the pairs
 * each layout took.) */
#include <stdio.h>
#include <string.h>

#include "plan.h"

/* "pair terms (hourglass, ...)": the settings whose terms B_pair_terms adds, which the
 * blocks and the stencil do not call (they gather only the pair values of physics/pairs.c).
 * One buffer: the phrase is printed before the next is asked for. */
static const char *pair_terms(const BodyPlan *p)
{
    static char why[160];
    const char *sep = "pair terms (";
    why[0] = 0;
    for (int k = 0; k < BODY_NSETTINGS; k++)
        if (BODY_SETTING_ROWS[k].pair && (p->terms >> k & 1)) {
            snprintf(why + strlen(why), sizeof why - strlen(why), "%s%s", sep,
                     BODY_SETTING_ROWS[k].keyword);
            sep = ", ";
        }
    snprintf(why + strlen(why), sizeof why - strlen(why), ")");
    return why;
}

/* (the quadratic fit's pair sums ride with the lists' pairs: templates/body_quadratic.c) */
#define QUADRATIC "the quadratic gradient (its pair sums ride with the lists')"

/* (a law's `viscousheat`: each particle's share of its pairs' viscous heat, which the lists'
 * pairs give both particles) */
#define VHEAT "the law's viscous heat (the lists give each particle its pairs' share)"

/* (sphc --no-simd: the lists' scalar loops alone) */
#define NO_SIMD "--no-simd"

const char *layout_gradient_blocks_refused(const Model *m, const BodyPlan *p)
{
    if (m->no_simd)
        return NO_SIMD;
    if (m->dim != 3)
        return "2D (the lattice stencil serves 2D)";
    if (p->fracture)
        return "fracture (the phase field's Laplacian rides with the lists' pairs)";
    return p->quadratic ? QUADRATIC : NULL;
}

const char *layout_momentum_blocks_refused(const Model *m, const BodyPlan *p)
{
    if (m->no_simd)
        return NO_SIMD;
    if (m->dim != 3)
        return "2D (the lattice stencil serves 2D)";
    if (p->fracture)
        return "fracture";
    if (p->quadratic)
        return QUADRATIC;
    if (!p->viscosity)
        return "no viscosity (the blocks' break-even was measured with it)";
    if (p->vheat)
        return VHEAT;
    return p->pair_terms ? pair_terms(p) : NULL;
}

const char *layout_stencil_momentum_refused(const Model *m, const BodyPlan *p)
{
    if (m->no_simd)
        return NO_SIMD;
    if (m->dim != 2)
        return "3D";
    if (p->quadratic)
        return QUADRATIC;
    if (p->vheat)
        return VHEAT;
    return p->pair_terms ? pair_terms(p) : NULL;
}

static void line(FILE *out, const char *pass, const char *layout, const char *why)
{
    fprintf(out, "  %s pass (CPU): %s", pass, layout);
    if (why)
        fprintf(out, ", because %s", why);
    fputs("\n", out);
}

/* (the set-up measures how well the body's particles fill the blocks' lanes) */
#define BLOCKS "offset blocks if they fill their lanes well enough, else half lists"
#define STENCIL "lattice stencil on its runs, half lists for the rest"

void layouts_dump(const Model *m, const BodyPlan *p, FILE *out)
{
    if (m->dim == 2) {
        if (m->no_simd || p->quadratic)
            line(out, "gradient", "half lists", m->no_simd ? NO_SIMD : QUADRATIC);
        else
            line(out, "gradient", STENCIL, NULL);
        const char *why = layout_stencil_momentum_refused(m, p);
        line(out, "momentum", why ? "half lists" : STENCIL, why);
        return;
    }
    const char *gw = layout_gradient_blocks_refused(m, p);
    line(out, "gradient", gw ? "half lists" : BLOCKS, gw);
    const char *mw = layout_momentum_blocks_refused(m, p);
    line(out, "momentum", mw ? "half lists" : BLOCKS, mw);
}
