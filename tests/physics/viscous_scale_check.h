/* viscous_scale_check.h — the body of test_viscous_scale2d.c and test_viscous_scale3d.c: the
 * artificial viscosity's approach rate G_ij is eq. 60's, measured in the pair's reference
 * length whatever the deformation.
 *
 * The block (viscous2d.sph, viscous3d.sph: viscosity beta1 only) is given a homogeneous
 * deformation, F = diag(a, a, c) in 3D and diag(a, c) in the x-z plane in 2D (u = (F - I) X,
 * which the corrected gradient reproduces exactly, boundary particles included), and the
 * velocity v = -rate Z e_z: every pair approaches along z at the same rate in the reference
 * configuration, so by eq. 60 each pair's G, and so its viscous pressure pi (eq. 58), is that
 * of the undeformed block.  The viscous force acts along cof(F) grad W (eq. 57), whose z
 * component cof(F)_zz (a^2 in 3D, a in plane strain) scales the power it takes from the
 * motion: the deformed block's viscous power is cof(F)_zz times the undeformed block's, to
 * round-off, also after a rotation of the whole.  A G measured along cof(F) grad W itself, in
 * the pair's current length, would give cof(F)_zz^2.  z is the most compressed direction in
 * each state (c < a): elsewhere sphc's G is below eq. 60's (docs/stability.md).
 *
 * Expects DIM and FORCES (the generated body's force passes). */
#include "check.h"

/* The viscous power of the block under F = diag(a, a, c) and v = -rate Z e_z, turned by
 * `angle` about x (3D) or y (2D). */
static double viscous_power(sph_body *b, double a, double c, double angle)
{
    enum { D = DIM, Z = DIM - 1 };
    const double rate = 50, cs = cos(angle), sn = sin(angle);
    for (int i = 0; i < b->n; i++) {
        const double *X = b->X + (size_t)i * D;
        double x[D], v[D] = {0};
        for (int k = 0; k < D; k++)
            x[k] = (k == Z ? c : a) * X[k];
        v[Z] = -rate * X[Z];
        /* the rotation in the plane of the last two components */
        const double y = x[Z - 1], vy = v[Z - 1];
        x[Z - 1] = cs * y - sn * x[Z], x[Z] = sn * y + cs * x[Z];
        v[Z - 1] = cs * vy - sn * v[Z], v[Z] = sn * vy + cs * v[Z];
        for (int k = 0; k < D; k++) {
            b->u[(size_t)i * D + k] = x[k] - X[k];
            b->v[(size_t)i * D + k] = v[k];
        }
    }
    FORCES(b);
    return b->visc_rate;
}

/* cof(F)_zz of F = diag(a, a, c) (3D) or diag(a, 1, c) (plane strain) */
static double cof_zz(double a)
{
    return DIM == 3 ? a * a : a;
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    sph_body *b = &sim.bodies[0];
    const double p0 = viscous_power(b, 1, 1, 0);
    printf("undeformed block (%dD): viscous power %.6g W\n", DIM, p0);
    check_close("the viscosity dissipates (power > 0)", p0 > 0, 1, 0);
    check_close("stretched laterally, a = 1.2: power / undeformed power / cof(F)_zz",
                viscous_power(b, 1.2, 1, 0) / p0 / cof_zz(1.2), 1, 1e-12);
    check_close("a = 1.2 and crushed to c = 0.5 along z: power / ... / cof(F)_zz",
                viscous_power(b, 1.2, 0.5, 0) / p0 / cof_zz(1.2), 1, 1e-12);
    check_close("compressed, a = 0.8, c = 0.6: power / ... / cof(F)_zz",
                viscous_power(b, 0.8, 0.6, 0) / p0 / cof_zz(0.8), 1, 1e-12);
    check_close("a = 1.2, c = 0.5, turned by 40 degrees: power / ... / cof(F)_zz",
                viscous_power(b, 1.2, 0.5, 0.7) / p0 / cof_zz(1.2), 1, 1e-12);
    sph_sim_free(&sim);
    return check_result();
}
