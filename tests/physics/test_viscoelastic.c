/* The standard library's finite-strain viscoelastic laws (stdlib/viscoelastic.sph; model
 * viscoelastic3d.sph), called step by step at given deformations and time steps:
 *  - a held stretch (F = diag(1.3, 0.9, 0.95), applied at t = 0) relaxes exactly as
 *    Cv_i(t) = Cb + (I - Cb) exp(-t / tau_i) at any step lengths: S against its closed form
 *    2 dpsi/dC to 1e-11 of its largest entry, for one and three branches;
 *  - a held small shear (gamma = 1e-5) relaxes as the Prony series of linear
 *    viscoelasticity, sigma_xy / gamma = mu (1 - sum_i g_i (1 - exp(-t / tau_i))), to 1e-4;
 *  - along a path of finite deformations and uneven steps, the energy the law reports as
 *    dissipated grows at every step, and it is what the free energy lost at the current
 *    deformation: psi(F, Cv_n) - psi(F, Cv_n+1) = w_n+1 - w_n (to 1e-12 of mu);
 *  - with relaxation times far beyond the run the law is stdlib/neohookean's after steps: S
 *    and psi to 1e-12 (the two laws sum their terms in different orders: 1.2e-13 and 1e-13
 *    measured);
 *  - neo-Hookean written with J, rho0 and rho = rho0 / J (as an energy of C and of F) is
 *    stdlib/neohookean's, S and psi to 1e-12. */
#define main generated_main
#include "viscoelastic3d.c"
#undef main

#include "check.h"
#include "tensor_check.h"

static const double K = 5e6, MU = 1e6;

typedef void (*Law)(const double F[9], double dt, const double *st, double *st_new,
                    double S[9], double *psi);

typedef struct {
    const char *name;
    Law law;
    int branches;
    double g[3], tau[3];
} Case;

static const Case VE = {"viscoelastic", ve_material, 1, {0.6}, {1e-3}};
static const Case VE3 = {"viscoelastic3", ve3_material, 3, {0.3, 0.2, 0.1}, {1e-4, 1e-3, 1e-2}};

static double trace_of_product(const double A[9], const double B[9])
{
    double AB[9];
    t3_mul(A, B, AB);
    return AB[0] + AB[4] + AB[8];
}

static double largest(const double A[9])
{
    double m = 0;
    for (int k = 0; k < 9; k++)
        m = fmax(m, fabs(A[k]));
    return m;
}

/* The state at rest: each branch's Cv = I, nothing dissipated. */
static void at_rest(const Case *c, double *st)
{
    for (int k = 0; k < 9 * c->branches + 1; k++)
        st[k] = 0;
    for (int i = 0; i < c->branches; i++)
        st[9 * i] = st[9 * i + 4] = st[9 * i + 8] = 1;
}

/* S = 2 dpsi/dC of the law's energy with the branches' viscous metrics Cv[i]:
 * K/2 (J^2 - 1) C^-1 + mu_inf J^(-2/3) (I - tr(C)/3 C^-1)
 *   + sum_i mu_i det(Cv_i)^(1/3) J^(-2/3) (Cv_i^-1 - tr(C Cv_i^-1)/3 C^-1). */
static void closed_form(const Case *c, const double C[9], const double Cv[][9], double S[9])
{
    double Ci[9];
    t3_inv(C, Ci);
    const double J2 = t3_det(C), Jm23 = pow(J2, -1.0 / 3);
    double ginf = 1;
    for (int i = 0; i < c->branches; i++)
        ginf -= c->g[i];
    const double trC = C[0] + C[4] + C[8];
    for (int k = 0; k < 9; k++)
        S[k] = 0.5 * K * (J2 - 1) * Ci[k] + ginf * MU * Jm23 * ((k % 4 == 0) - trC / 3 * Ci[k]);
    for (int i = 0; i < c->branches; i++) {
        double Cvi[9];
        t3_inv(Cv[i], Cvi);
        const double w = c->g[i] * MU * cbrt(t3_det(Cv[i])) * Jm23, tr = trace_of_product(C, Cvi);
        for (int k = 0; k < 9; k++)
            S[k] += w * (Cvi[k] - tr / 3 * Ci[k]);
    }
}

/* Uneven steps: between 0.01 and 0.31 of the shortest relaxation time, in a fixed order. */
static double step_length(const Case *c, int n)
{
    return c->tau[0] * (0.01 + 0.3 * fmod(n * 0.6180339887498949, 1.0));
}

/* A stretch held from t = 0: S at the law's steps against the closed form. */
static void held_stretch(const Case *c)
{
    const double F[9] = {1.3, 0, 0, 0, 0.9, 0, 0, 0, 0.95};
    double Ft[9], C[9];
    t3_transpose(F, Ft);
    t3_mul(Ft, F, C);
    const double Jm23 = pow(t3_det(C), -1.0 / 3);
    double st[28], st_new[28], S[9], psi, worst = 0, t = 0, relaxed = 0, S0 = 0;
    at_rest(c, st);
    for (int n = 0; t < 10 * c->tau[c->branches - 1]; n++) {
        const double dt = n == 0 ? 0 : step_length(c, n); /* the first evaluation: dt = 0 */
        t += dt;
        c->law(F, dt, st, st_new, S, &psi);
        memcpy(st, st_new, sizeof st);
        double Cv[3][9], Sref[9], diff[9];
        for (int i = 0; i < c->branches; i++)
            for (int k = 0; k < 9; k++)
                Cv[i][k] = Jm23 * C[k] + ((k % 4 == 0) - Jm23 * C[k]) * exp(-t / c->tau[i]);
        closed_form(c, C, Cv, Sref);
        for (int k = 0; k < 9; k++)
            diff[k] = S[k] - Sref[k];
        worst = fmax(worst, largest(diff) / largest(Sref));
        if (n == 0)
            S0 = S[0];
        relaxed = S[0];
    }
    char what[160];
    printf("%s, held stretch diag(1.3, 0.9, 0.95) to t = %.3g s: S_xx from %.6g to %.6g Pa\n",
           c->name, t, S0, relaxed);
    snprintf(what, sizeof what, "%s: held stretch, max |S - closed form| / max |S|", c->name);
    check_close(what, worst, 0, 1e-11);
    snprintf(what, sizeof what, "%s: held stretch relaxes (S_xx falls by > 10 %%)", c->name);
    check_close(what, relaxed < 0.9 * S0, 1, 0);
}

/* A small shear held from t = 0: the Prony series of linear viscoelasticity. */
static void held_shear(const Case *c)
{
    const double gamma = 1e-5;
    const double F[9] = {1, gamma, 0, 0, 1, 0, 0, 0, 1};
    double st[28], st_new[28], S[9], psi, worst = 0, t = 0;
    at_rest(c, st);
    for (int n = 0; t < 10 * c->tau[c->branches - 1]; n++) {
        const double dt = n == 0 ? 0 : step_length(c, n);
        t += dt;
        c->law(F, dt, st, st_new, S, &psi);
        memcpy(st, st_new, sizeof st);
        double FS[9], Ft[9], sig[9];
        t3_mul(F, S, FS);
        t3_transpose(F, Ft);
        t3_mul(FS, Ft, sig);
        double G = 1;
        for (int i = 0; i < c->branches; i++)
            G -= c->g[i] * (1 - exp(-t / c->tau[i]));
        worst = fmax(worst, fabs(sig[1] / t3_det(F) / gamma / (MU * G) - 1));
    }
    char what[160];
    snprintf(what, sizeof what, "%s: held shear, |sigma_xy / (gamma G(t)) - 1|", c->name);
    check_close(what, worst, 0, 1e-4);
}

/* A path of finite deformations with uneven steps: the dissipated energy. */
static void dissipation(const Case *c)
{
    static const double M1[9] = {0.3, 0.2, -0.1, 0.05, -0.2, 0.15, -0.12, 0.08, 0.1};
    static const double M2[9] = {-0.1, 0.1, 0.2, -0.15, 0.25, 0.05, 0.1, -0.2, -0.3};
    const int nw = 9 * c->branches; /* the state value wv */
    double st[28], st_new[28], st0[28], S[9], psi0, psi1, least = INFINITY, mismatch = 0;
    at_rest(c, st);
    for (int n = 0; n < 400; n++) {
        double F[9];
        for (int k = 0; k < 9; k++)
            F[k] = (k % 4 == 0) + sin(0.05 * n) * M1[k] + sin(0.031 * n + 1) * M2[k];
        const double dt = step_length(c, n);
        c->law(F, 0, st, st0, S, &psi0); /* the free energy before the step's relaxation */
        c->law(F, dt, st, st_new, S, &psi1);
        const double dw = st_new[nw] - st[nw];
        least = fmin(least, dw);
        mismatch = fmax(mismatch, fabs(psi0 - psi1 - dw) / MU);
        memcpy(st, st_new, sizeof st);
    }
    char what[160];
    printf("%s: dissipated %.6g J/m^3 along the path; least step %.3g\n", c->name, st[nw], least);
    snprintf(what, sizeof what, "%s: dissipation of every step >= 0 (least / mu)", c->name);
    check_close(what, least >= -1e-12 * MU, 1, 0);
    snprintf(what, sizeof what, "%s: |psi before - psi after - dissipated| / mu", c->name);
    check_close(what, mismatch, 0, 1e-12);
    snprintf(what, sizeof what, "%s: the path dissipates (> 1e-3 mu)", c->name);
    check_close(what, st[nw] > 1e-3 * MU, 1, 0);
}

/* Relaxation times of 1e300 s: the law is neo-Hookean, at any state it reaches. */
static void elastic_limit(void)
{
    static const double M1[9] = {0.3, 0.2, -0.1, 0.05, -0.2, 0.15, -0.12, 0.08, 0.1};
    double st[28], st_new[28], worst = 0, worst_psi = 0;
    at_rest(&VE3, st);
    for (int n = 0; n < 50; n++) {
        double F[9], S[9], Sn[9], psi, psin, diff[9];
        for (int k = 0; k < 9; k++)
            F[k] = (k % 4 == 0) + sin(0.2 * n) * M1[k];
        ve_inf_material(F, 1e-4, st, st_new, S, &psi);
        memcpy(st, st_new, sizeof st);
        nh_material(F, Sn, &psin);
        for (int k = 0; k < 9; k++)
            diff[k] = S[k] - Sn[k];
        worst = fmax(worst, largest(diff) / fmax(largest(Sn), 1e-3 * MU)); /* (F = I: S = 0) */
        worst_psi = fmax(worst_psi, fabs(psi - psin) / fmax(fabs(psin), 1e-6 * MU));
    }
    check_close("tau = 1e300: max |S - S_neohookean| / max |S|", worst, 0, 1e-12);
    check_close("tau = 1e300: |psi - psi_neohookean| / psi", worst_psi, 0, 1e-12);
}

/* Neo-Hookean through what a law reads besides F: J, rho0 and rho. */
static void law_inputs(void)
{
    static const double M1[9] = {0.3, 0.2, -0.1, 0.05, -0.2, 0.15, -0.12, 0.08, 0.1};
    void (*const laws[2])(const double *, double *, double *) = {nh_c_material, nh_f_material};
    const char *names[2] = {"J, rho, rho0 in an energy of C", "J, rho, rho0 in an energy of F"};
    for (int l = 0; l < 2; l++) {
        double worst = 0, worst_psi = 0;
        for (int n = 1; n < 20; n++) {
            double F[9], S[9], Sn[9], psi, psin, diff[9];
            for (int k = 0; k < 9; k++)
                F[k] = (k % 4 == 0) + sin(0.2 * n) * M1[k];
            laws[l](F, S, &psi);
            nh_material(F, Sn, &psin);
            for (int k = 0; k < 9; k++)
                diff[k] = S[k] - Sn[k];
            worst = fmax(worst, largest(diff) / largest(Sn));
            worst_psi = fmax(worst_psi, fabs(psi - psin) / fabs(psin));
        }
        char what[160];
        snprintf(what, sizeof what, "%s: max |S - S_neohookean| / max |S|", names[l]);
        check_close(what, worst, 0, 1e-12);
        snprintf(what, sizeof what, "%s: |psi - psi_neohookean| / psi", names[l]);
        check_close(what, worst_psi, 0, 1e-12);
    }
}

int main(void)
{
    const Case *cases[] = {&VE, &VE3};
    for (int k = 0; k < 2; k++) {
        held_stretch(cases[k]);
        held_shear(cases[k]);
        dissipation(cases[k]);
    }
    elastic_limit();
    law_inputs();
    return check_result();
}
