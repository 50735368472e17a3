/* Crack branching at test-suite resolution (crackbranch_coarse.sph): a plate with a notch
 * from x = -2 to 50 mm along z = 20 mm, pulled by 1 MPa on its top and bottom faces.
 *  - the crack starts: some particle's phase field drops below 0.5 (initiation), within
 *    5-25 us (the paper: about 14 us at 16 times the resolution);
 *  - where it starts: the first damaged particle lies at the notch tip (49 < x < 53 mm,
 *    |z - 20 mm| < 1 mm), and at 40 us every damaged particle lies ahead of the tip
 *    (x > 49 mm) within 5 mm of the notch plane: nothing at the loaded faces or along the
 *    notch's flanks;
 *  - irreversibility: the history field H (eq. 8) never decreases at any particle and step,
 *    and s stays in [0, 1];
 *  - the notch cuts the plate at set-up: no pair of the half lists joins a particle below
 *    z = 20 mm to one above it where the pair crosses at x < 50 mm, while pairs across the
 *    plane ahead of the tip are kept;
 *  - the fracture energy at 40 us is at least Gc times the crack's length beyond the notch
 *    tip, x_max - 50 mm over the damaged particles (the paper's criterion; at this
 *    resolution, with eps0 a quarter of dx, the discrete crack energy is about twice that). */
#define main generated_main
#include "crackbranch_coarse.c"
#undef main

#include <string.h>

#include "check.h"

enum { D = 2 };

static int damaged_outside(const sph_body *b, double *worst_x, double *worst_z)
{
    int bad = 0;
    for (int i = 0; i < b->n; i++) {
        if (b->s[i] >= 0.5)
            continue;
        const double x = b->X[i * D], z = b->X[i * D + 1];
        if (x <= 49e-3 || fabs(z - 20e-3) >= 5e-3) {
            bad++;
            *worst_x = x, *worst_z = z;
        }
    }
    return bad;
}

/* Pairs crossing z = 20 mm, behind (x < 50 mm where they cross) and ahead of the tip. */
static void pairs_across(const sph_body *b, long *behind, long *ahead)
{
    *behind = *ahead = 0;
    for (int i = 0; i < b->n; i++)
        for (int p = b->hb_start[i]; p < b->hb_start[i + 1]; p++) {
            const int j = b->hb[p];
            const double zi = b->X[i * D + 1] - 20e-3, zj = b->X[j * D + 1] - 20e-3;
            if (zi * zj >= 0)
                continue;
            const double x = b->X[i * D] + (b->X[j * D] - b->X[i * D]) * zi / (zi - zj);
            *(x < 50e-3 ? behind : ahead) += 1;
        }
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    long behind, ahead;
    pairs_across(b, &behind, &ahead);
    check_close("pairs across the notch", behind, 0, 0);
    check_close("pairs across the plane ahead of the tip > 0", ahead > 0, 1, 0);
    const check_fracture_run w = check_run_fracture(&sim, b);
    const double t_init = w.t_init;
    const double x_init = w.i_init < 0 ? NAN : b->X[w.i_init * D];
    const double z_init = w.i_init < 0 ? NAN : b->X[w.i_init * D + 1];
    int ndamaged = 0;
    double x_tip = 50e-3, x_max = x_tip;
    for (int i = 0; i < b->n; i++)
        if (b->s[i] < 0.5) {
            ndamaged++;
            x_max = fmax(x_max, b->X[i * D]);
        }
    double wx = 0, wz = 0;
    int outside = damaged_outside(b, &wx, &wz);
    double ef = sph_fracture_energy(b);
    printf("%ld steps to %.3g us: initiation at %.4g us at x = %.4g mm, z = %.4g mm; %d damaged "
           "particles; fracture energy %.4g J/m\n",
           sim.step, sim.t * 1e6, t_init * 1e6, x_init * 1e3, z_init * 1e3, ndamaged, ef);
    if (outside)
        printf("damaged particle outside the tip zone, e.g. x = %g mm, z = %g mm\n", wx * 1e3,
               wz * 1e3);
    check_close("initiation time (us), 5 to 25", t_init * 1e6, 15, 10);
    check_close("initiation x (mm), notch tip 49 to 53", x_init * 1e3, 51, 2);
    check_close("initiation z (mm), notch plane +- 1", z_init * 1e3, 20, 1);
    check_close("damaged particles outside the zone ahead of the tip", outside, 0, 0);
    check_fracture_bounds(&w);
    const double Gc = 3.0, length = x_max - x_tip;
    printf("crack length beyond the tip %.4g mm, Gc x length %.4g J/m\n", length * 1e3, Gc * length);
    check_close("crack length beyond the tip (mm) is positive", length > 0, 1, 0);
    check_close("fracture energy >= Gc x crack length", ef >= Gc * length, 1, 0);
    sph_sim_free(&sim);
    return check_result();
}
