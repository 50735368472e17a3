/* The standard library's Drucker-Prager law (stdlib/druckerprager.sph; model dp3d.sph: a soil,
 * K = 50 MPa, mu = 23 MPa, c = 10 kPa, phi = 30 degrees), called at given deformations:
 *  - triaxial compression at confining mean stresses of -50, -100, -200 and -400 kPa: an
 *    isotropic compression to it, then axial compression at constant volume to 3 % (the
 *    mean stress stays about the confining one):
 *    wherever the particle flows its stress is on the cone, sqrt(J2) + eta p = xi c (the
 *    Kirchhoff stress; eta, xi of the outer Mohr-Coulomb cone), to 1e-4 of xi c - eta p
 *    (1e-5 measured: the return is the small-elastic-strain one); the four first yields lie
 *    on that line (slope and intercept to 2e-3 and 1e-3);
 *  - hydrostatic tension past the apex: the mean stress stays at the apex's, xi c / eta (to
 *    1e-3: 1.3e-4 measured, the volumetric energy's nonlinearity), with no deviatoric stress;
 *  - without dilatancy the plastic flow keeps the volume (det Cp = 1 to 1e-12); with
 *    associated flow (psi = phi) the plastic volume grows by etab times the plastic
 *    multiplier (to 1e-9), as sand dilates;
 *  - the plastic work grows at every step. */
#define main generated_main
#include "dp3d.c"
#undef main

#include "check.h"
#include "tensor_check.h"

static const double K = 50e6, COH = 10e3, PHI = 30 * 0.017453292519943295;
enum { NS = 11, EP = 9, WP = 10 };

typedef void (*Law)(const double F[9], const double *st, double *st_new, double S[9],
                    double *psi);

static double eta(void) { return 6 * sin(PHI) / (sqrt(3.0) * (3 - sin(PHI))); }
static double xi(void) { return 6 * cos(PHI) / (sqrt(3.0) * (3 - sin(PHI))); }

static void at_rest(double *st)
{
    memset(st, 0, NS * sizeof *st);
    st[0] = st[4] = st[8] = 1;
}

/* Triaxial compression from the mean stress p0: the worst distance from the cone where it
 * flows, the first yield (p, sqrt(J2)), the least plastic work of a step and det Cp. */
typedef struct {
    double cone, py, sjy, least_work, detcp;
} Triax;

static Triax triaxial(Law law, double p0)
{
    Triax t = {0, 0, 0, INFINITY, 0};
    const double lam = pow(1 + 2 * p0 / K, 1.0 / 6); /* 0.5 K (lam^6 - 1) = p0 */
    double st[NS], sn[NS], S[9], psi;
    at_rest(st);
    int yielded = 0;
    for (int k = 0; k <= 3000; k++) {
        const double a = 1 - 1e-5 * k, l = lam / sqrt(a); /* (the volume held) */
        const double F[9] = {lam * a, 0, 0, 0, l, 0, 0, 0, l};
        law(F, st, sn, S, &psi);
        const double dep = sn[EP] - st[EP];
        t.least_work = fmin(t.least_work, sn[WP] - st[WP]);
        memcpy(st, sn, sizeof st);
        if (dep <= 0)
            continue;
        double p, sj;
        t3_kirchhoff_invariants(F, S, &p, &sj);
        if (!yielded)
            t.py = p, t.sjy = sj, yielded = 1;
        t.cone = fmax(t.cone, fabs(sj + eta() * p - xi() * COH) / (xi() * COH - eta() * p));
    }
    t.detcp = t3_det(st);
    return t;
}

int main(void)
{
    static const double confining[4] = {-50e3, -100e3, -200e3, -400e3};
    Triax tx[4];
    for (int k = 0; k < 4; k++) {
        tx[k] = triaxial(soil_material, confining[k]);
        char what[160];
        printf("confining %g Pa: first yield at p = %.6g Pa, sqrt(J2) = %.6g Pa (the cone: "
               "%.6g); det Cp %.15g\n", confining[k], tx[k].py, tx[k].sjy,
               xi() * COH - eta() * tx[k].py, tx[k].detcp);
        snprintf(what, sizeof what, "confining %g: max |f| / (xi c - eta p) where it flows",
                 confining[k]);
        check_close(what, tx[k].cone, 0, 1e-4);
        snprintf(what, sizeof what, "confining %g: plastic work of every step >= 0", confining[k]);
        check_close(what, tx[k].least_work >= 0, 1, 0);
        snprintf(what, sizeof what, "confining %g, psi = 0: |det Cp - 1|", confining[k]);
        check_close(what, fabs(tx[k].detcp - 1), 0, 1e-12);
    }
    /* the first yields' line: slope -eta, intercept xi c (from the two extreme points) */
    const double slope = (tx[3].sjy - tx[0].sjy) / (tx[3].py - tx[0].py);
    const double icpt = tx[0].sjy - slope * tx[0].py;
    check_close("first yields: slope of sqrt(J2) against p, over -eta", slope / -eta(), 1, 2e-3);
    check_close("first yields: intercept, over xi c", icpt / (xi() * COH), 1, 1e-3);

    /* hydrostatic tension past the apex */
    double st[NS], sn[NS], S[9], psi, worst_p = 0, worst_s = 0;
    const double pa = xi() * COH / eta();
    at_rest(st);
    for (int k = 1; k <= 200; k++) {
        const double l = 1 + 2e-5 * k;
        const double F[9] = {l, 0, 0, 0, l, 0, 0, 0, l};
        soil_material(F, st, sn, S, &psi);
        memcpy(st, sn, sizeof st);
        double p, sj;
        t3_kirchhoff_invariants(F, S, &p, &sj);
        if (sn[EP] > 0)
            worst_p = fmax(worst_p, fabs(p - pa) / pa), worst_s = fmax(worst_s, sj / pa);
    }
    printf("hydrostatic tension: the apex's mean stress %.6g Pa, reached with ep %.4g\n", pa,
           st[EP]);
    check_close("apex: max |p - xi c / eta| / (xi c / eta)", worst_p, 0, 1e-3);
    check_close("apex: max sqrt(J2) / (xi c / eta)", worst_s, 0, 1e-9);
    check_close("apex: reached (ep > 0)", st[EP] > 0, 1, 0);

    /* associated flow dilates: d ln sqrt(det Cp) = etab dg, dep = dg sqrt(1/3 + 2 etab^2 / 9) */
    const double etab = eta(), lam = pow(1 - 2 * 100e3 / K, 1.0 / 6);
    double worst_v = 0;
    at_rest(st);
    for (int k = 0; k <= 3000; k++) {
        const double a = 1 - 1e-5 * k, l = lam / sqrt(a);
        const double F[9] = {lam * a, 0, 0, 0, l, 0, 0, 0, l};
        dilat_material(F, st, sn, S, &psi);
        const double dep = sn[EP] - st[EP];
        if (dep > 0) {
            const double dg = dep / sqrt(1.0 / 3 + 2 * etab * etab / 9);
            const double dv = 0.5 * log(t3_det(sn) / t3_det(st));
            worst_v = fmax(worst_v, fabs(dv - etab * dg) / (etab * dg));
        }
        memcpy(st, sn, sizeof st);
    }
    printf("associated flow: det Cp %.8g after 3 %% of axial compression at -100 kPa\n", t3_det(st));
    check_close("psi = phi: max |d ln sqrt(det Cp) - etab dg| / (etab dg)", worst_v, 0, 1e-9);
    check_close("psi = phi: the soil dilates (det Cp > 1.001)", t3_det(st) > 1.001, 1, 0);
    return check_result();
}
