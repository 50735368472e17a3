/* The hyperelastic laws of the standard library written as energies (stdlib/mooneyrivlin,
 * yeoh, gent, ogden; model hyperelastic3d.sph), called at given deformations: the stress
 * sphc derives against the closed forms of isochoric uniaxial stretch and simple shear, pure
 * dilatation, objectivity, the small-strain limit (linear elasticity with mu and K) and the
 * neo-Hookean and Mooney-Rivlin special cases. */
#define main generated_main
#include "hyperelastic3d.c"
#undef main

#include "check.h"

typedef void (*Law)(const double F[9], double S[9], double *psi);

/* The parameters of hyperelastic3d.sph. */
enum { NLAWS = 3 };
static const double K = 5e6, MU = 1e6; /* the small-strain shear modulus of all but og */
static const double C10 = 0.3e6, C01 = 0.2e6;                    /* mr */
static const double Y10 = 0.5e6, Y20 = -0.05e6, Y30 = 0.01e6;    /* yeoh_b */
static const double JM = 20;                                     /* gent_b, mu = MU */
static const double OG_MU[3] = {0.63e6, 0.0012e6, -0.01e6};     /* og, Treloar's rubber */
static const double OG_ALPHA[3] = {1.3, 5.0, -2.0};

/* dW/dI1bar and dW/dI2bar of each law's isochoric energy, and that energy, at I1, I2. */
typedef struct {
    const char *name;
    Law law;
    void (*derivs)(double I1, double I2, double *W1, double *W2, double *W);
    double mu; /* small-strain shear modulus */
} LawCase;

static void mr_derivs(double I1, double I2, double *W1, double *W2, double *W)
{
    *W1 = C10, *W2 = C01;
    *W = C10 * (I1 - 3) + C01 * (I2 - 3);
}

static void yeoh_derivs(double I1, double I2, double *W1, double *W2, double *W)
{
    (void)I2;
    const double d = I1 - 3;
    *W1 = Y10 + 2 * Y20 * d + 3 * Y30 * d * d;
    *W2 = 0;
    *W = Y10 * d + Y20 * d * d + Y30 * d * d * d;
}

static void gent_derivs(double I1, double I2, double *W1, double *W2, double *W)
{
    (void)I2;
    *W1 = 0.5 * MU * JM / (JM - I1 + 3);
    *W2 = 0;
    *W = -0.5 * MU * JM * log(1 - (I1 - 3) / JM);
}

static const LawCase LAWS[NLAWS] = {
    {"Mooney-Rivlin", mr_material, mr_derivs, 1e6},
    {"Yeoh", yeoh_b_material, yeoh_derivs, 1e6},
    {"Gent", gent_b_material, gent_derivs, 1e6},
};
/* mu = (mu1 alpha1 + mu2 alpha2 + mu3 alpha3) / 2 */
static const LawCase OGDEN = {"Ogden", og_material, NULL, 0.4225e6};

static void matmul(const double A[9], const double B[9], double AB[9])
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            AB[r * 3 + c] = A[r * 3] * B[c] + A[r * 3 + 1] * B[3 + c] + A[r * 3 + 2] * B[6 + c];
}

static double det3(const double A[9])
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

/* Cauchy stress sigma = F S F^T / J (eq. 2 with P = F S). */
static void cauchy(const double F[9], const double S[9], double sig[9])
{
    double FS[9], Ft[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            Ft[r * 3 + c] = F[c * 3 + r];
    matmul(F, S, FS);
    matmul(FS, Ft, sig);
    const double J = det3(F);
    for (int k = 0; k < 9; k++)
        sig[k] /= J;
}

/* The largest |a_k - b_k| over the largest |b_k|. */
static double rel_diff(const double a[9], const double b[9])
{
    double d = 0, s = 0;
    for (int k = 0; k < 9; k++)
        d = fmax(d, fabs(a[k] - b[k])), s = fmax(s, fabs(b[k]));
    return d / s;
}

/* sigma of an isochoric deformation (J = 1) of an invariant-based energy:
 * sigma = dev(2 (W1 + I1 W2) b - 2 W2 b^2), b = F F^T. */
static void isochoric_sigma(const LawCase *lc, const double F[9], double sig[9], double *W)
{
    double Ft[9], b[9], b2[9], W1, W2;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            Ft[r * 3 + c] = F[c * 3 + r];
    matmul(F, Ft, b);
    matmul(b, b, b2);
    const double I1 = b[0] + b[4] + b[8];
    const double I2 = 0.5 * (I1 * I1 - (b2[0] + b2[4] + b2[8]));
    lc->derivs(I1, I2, &W1, &W2, W);
    for (int k = 0; k < 9; k++)
        sig[k] = 2 * (W1 + I1 * W2) * b[k] - 2 * W2 * b2[k];
    const double p = (sig[0] + sig[4] + sig[8]) / 3;
    for (int k = 0; k < 9; k += 4)
        sig[k] -= p;
}

/* Uniaxial isochoric stretch F = diag(l, l^-1/2, l^-1/2): sigma11 - sigma22 against
 * 2 (l^2 - 1/l)(W1 + W2 / l), the whole sigma and psi against the closed form. */
static void uniaxial(const LawCase *lc, double l)
{
    const double F[9] = {l, 0, 0, 0, 1 / sqrt(l), 0, 0, 0, 1 / sqrt(l)};
    double S[9], sig[9], want[9], psi, W, W1, W2;
    lc->law(F, S, &psi);
    cauchy(F, S, sig);
    isochoric_sigma(lc, F, want, &W);
    const double I1 = l * l + 2 / l, I2 = 2 * l + 1 / (l * l);
    lc->derivs(I1, I2, &W1, &W2, &W);
    const double diff = 2 * (l * l - 1 / l) * (W1 + W2 / l);
    char what[96];
    snprintf(what, sizeof what, "%s uniaxial l = %g: sigma11 - sigma22 (rel)", lc->name, l);
    check_close(what, (sig[0] - sig[4]) / diff - 1, 0, 1e-10);
    snprintf(what, sizeof what, "%s uniaxial l = %g: whole sigma (rel)", lc->name, l);
    check_close(what, rel_diff(sig, want), 0, 1e-10);
    snprintf(what, sizeof what, "%s uniaxial l = %g: psi (rel)", lc->name, l);
    check_close(what, psi / W - 1, 0, 1e-10);
}

/* Simple shear F = I + g e1 (x) e2: sigma12 = 2 g (W1 + W2), sigma11 - sigma22 =
 * 2 g^2 (W1 + W2), sigma22 - sigma33 = -2 g^2 W2 (I1 = I2 = 3 + g^2). */
static void simple_shear(const LawCase *lc, double g)
{
    const double F[9] = {1, g, 0, 0, 1, 0, 0, 0, 1};
    double S[9], sig[9], want[9], psi, W, W1, W2;
    lc->law(F, S, &psi);
    cauchy(F, S, sig);
    isochoric_sigma(lc, F, want, &W);
    lc->derivs(3 + g * g, 3 + g * g, &W1, &W2, &W);
    const double s12 = 2 * g * (W1 + W2);
    char what[96];
    snprintf(what, sizeof what, "%s shear g = %g: sigma12 (rel)", lc->name, g);
    check_close(what, sig[1] / s12 - 1, 0, 1e-10);
    snprintf(what, sizeof what, "%s shear g = %g: sigma11 - sigma22 (rel)", lc->name, g);
    check_close(what, (sig[0] - sig[4]) / (g * s12) - 1, 0, 1e-10);
    snprintf(what, sizeof what, "%s shear g = %g: sigma22 - sigma33 (rel sigma12)", lc->name, g);
    check_close(what, (sig[4] - sig[8] + 2 * g * g * W2) / s12, 0, 1e-10);
    snprintf(what, sizeof what, "%s shear g = %g: whole sigma (rel)", lc->name, g);
    check_close(what, rel_diff(sig, want), 0, 1e-10);
}

/* Pure dilatation F = a I: the isochoric part vanishes and sigma = U'(J) I,
 * U'(J) = K/2 (J - 1/J) (eq. 22), J = a^3. */
static void dilatation(const LawCase *lc, double a)
{
    const double F[9] = {a, 0, 0, 0, a, 0, 0, 0, a};
    double S[9], sig[9], psi;
    lc->law(F, S, &psi);
    cauchy(F, S, sig);
    const double J = a * a * a, p = 0.5 * K * (J - 1 / J);
    const double want[9] = {p, 0, 0, 0, p, 0, 0, 0, p};
    char what[96];
    snprintf(what, sizeof what, "%s dilatation a = %g: sigma = U'(J) I (rel)", lc->name, a);
    check_close(what, rel_diff(sig, want), 0, 1e-10);
    snprintf(what, sizeof what, "%s dilatation a = %g: psi = U(J) (rel)", lc->name, a);
    check_close(what, psi / (0.5 * K * (0.5 * (J * J - 1) - log(J))) - 1, 0, 1e-10);
}

static unsigned seed = 11;
static double uniform(void) /* in [-0.5, 0.5) */
{
    seed = seed * 1103515245u + 12345u;
    return (double)(seed >> 8) / 16777216.0 - 0.5;
}

/* A rotation by angle t about the unit axis n (Rodrigues). */
static void rotation(const double n[3], double t, double Q[9])
{
    const double c = cos(t), s = sin(t);
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++)
            Q[r * 3 + k] = c * (r == k) + (1 - c) * n[r] * n[k];
    Q[1] -= s * n[2], Q[2] += s * n[1];
    Q[3] += s * n[2], Q[5] -= s * n[0];
    Q[6] -= s * n[1], Q[7] += s * n[0];
}

/* Objectivity: S(Q F) = S(F) and psi(Q F) = psi(F) at 100 random F (stretches and shears
 * of up to 30 %) and rotations. */
static void objectivity(const LawCase *lc)
{
    double worst_S = 0, worst_psi = 0;
    for (int trial = 0; trial < 100; trial++) {
        double F[9], Q[9], QF[9], n[3], S[9], SQ[9], psi, psiQ;
        for (int k = 0; k < 9; k++)
            F[k] = (k % 4 == 0) + 0.6 * uniform();
        for (int k = 0; k < 3; k++)
            n[k] = uniform();
        const double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; k++)
            n[k] /= len;
        rotation(n, 6.2 * (uniform() + 0.5), Q);
        matmul(Q, F, QF);
        lc->law(F, S, &psi);
        lc->law(QF, SQ, &psiQ);
        worst_S = fmax(worst_S, rel_diff(SQ, S));
        worst_psi = fmax(worst_psi, fabs(psiQ - psi) / fabs(psi));
    }
    char what[96];
    snprintf(what, sizeof what, "%s objectivity: S(QF) vs S(F) (rel)", lc->name);
    check_close(what, worst_S, 0, 1e-12);
    snprintf(what, sizeof what, "%s objectivity: psi(QF) vs psi(F) (rel)", lc->name);
    check_close(what, worst_psi, 0, 1e-12);
}

/* Small strain: at F = I + eps H (H symmetric, eps = 1e-6), S = K tr(e) I + 2 mu dev(e),
 * e = eps H, with mu = 2 (c10 + c01), 2 c10, mu, (sum mu_p alpha_p) / 2. */
static void small_strain(const LawCase *lc)
{
    const double eps = 1e-6;
    double worst = 0;
    for (int trial = 0; trial < 20; trial++) {
        double H[9], F[9], S[9], want[9], psi;
        for (int r = 0; r < 3; r++)
            for (int c = r; c < 3; c++)
                H[r * 3 + c] = H[c * 3 + r] = 2 * uniform();
        for (int k = 0; k < 9; k++)
            F[k] = (k % 4 == 0) + eps * H[k];
        lc->law(F, S, &psi);
        const double tr = eps * (H[0] + H[4] + H[8]);
        for (int k = 0; k < 9; k++)
            want[k] = 2 * lc->mu * (eps * H[k] - (k % 4 == 0) * tr / 3) + (k % 4 == 0) * K * tr;
        worst = fmax(worst, rel_diff(S, want));
    }
    char what[96];
    snprintf(what, sizeof what, "%s eps = 1e-6: S vs linear elasticity (rel)", lc->name);
    check_close(what, worst, 0, 1e-4);
}

/* Ogden's Kirchhoff principal stresses tau_k = sum_p mu_p l_k^alpha_p and energy
 * sum_p mu_p / alpha_p (l1^alpha_p + l2^alpha_p + l3^alpha_p - 3) at stretches l (J = 1). */
static double ogden_tau(const double l[3], double tau[3])
{
    double W = 0;
    for (int k = 0; k < 3; k++)
        tau[k] = 0;
    for (int p = 0; p < 3; p++) {
        for (int k = 0; k < 3; k++)
            tau[k] += OG_MU[p] * pow(l[k], OG_ALPHA[p]);
        W += OG_MU[p] / OG_ALPHA[p] *
             (pow(l[0], OG_ALPHA[p]) + pow(l[1], OG_ALPHA[p]) + pow(l[2], OG_ALPHA[p]) - 3);
    }
    return W;
}

/* The isochoric sigma = dev(sum_k tau_k n_k n_k^T) for Eulerian principal directions n_k
 * (unit columns of N). */
static void ogden_sigma(const double tau[3], const double N[9], double sig[9])
{
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            sig[r * 3 + c] = 0;
            for (int k = 0; k < 3; k++)
                sig[r * 3 + c] += tau[k] * N[r * 3 + k] * N[c * 3 + k];
        }
    const double p = (sig[0] + sig[4] + sig[8]) / 3;
    for (int k = 0; k < 9; k += 4)
        sig[k] -= p;
}

/* Ogden, uniaxial isochoric stretch: sigma11 - sigma22 = sum_p mu_p (l^alpha_p -
 * l^(-alpha_p/2)), the whole sigma and psi. */
static void ogden_uniaxial(double l)
{
    const double F[9] = {l, 0, 0, 0, 1 / sqrt(l), 0, 0, 0, 1 / sqrt(l)};
    const double N[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, ls[3] = {l, 1 / sqrt(l), 1 / sqrt(l)};
    double S[9], sig[9], want[9], tau[3], psi, diff = 0;
    OGDEN.law(F, S, &psi);
    cauchy(F, S, sig);
    const double W = ogden_tau(ls, tau);
    ogden_sigma(tau, N, want);
    for (int p = 0; p < 3; p++)
        diff += OG_MU[p] * (pow(l, OG_ALPHA[p]) - pow(l, -OG_ALPHA[p] / 2));
    char what[96];
    snprintf(what, sizeof what, "Ogden uniaxial l = %g: sigma11 - sigma22 (rel)", l);
    check_close(what, (sig[0] - sig[4]) / diff - 1, 0, 1e-10);
    snprintf(what, sizeof what, "Ogden uniaxial l = %g: whole sigma (rel)", l);
    check_close(what, rel_diff(sig, want), 0, 1e-10);
    snprintf(what, sizeof what, "Ogden uniaxial l = %g: psi (rel)", l);
    check_close(what, psi / W - 1, 0, 1e-10);
}

/* Ogden, simple shear F = I + g e1 (x) e2: principal stretches l, 1/l, 1 with
 * l - 1/l = g, Eulerian directions turned by theta, tan 2 theta = 2 / g, so
 * sigma12 = (tau1 - tau2) / sqrt(g^2 + 4); the whole sigma and psi. */
static void ogden_shear(double g)
{
    const double F[9] = {1, g, 0, 0, 1, 0, 0, 0, 1};
    const double l = 0.5 * (g + sqrt(g * g + 4)), ls[3] = {l, 1 / l, 1};
    const double th = 0.5 * atan2(2, g), c = cos(th), s = sin(th);
    const double N[9] = {c, -s, 0, s, c, 0, 0, 0, 1};
    double S[9], sig[9], want[9], tau[3], psi;
    OGDEN.law(F, S, &psi);
    cauchy(F, S, sig);
    const double W = ogden_tau(ls, tau);
    ogden_sigma(tau, N, want);
    char what[96];
    snprintf(what, sizeof what, "Ogden shear g = %g: sigma12 (rel)", g);
    check_close(what, sig[1] / ((tau[0] - tau[1]) / sqrt(g * g + 4)) - 1, 0, 1e-10);
    snprintf(what, sizeof what, "Ogden shear g = %g: whole sigma (rel)", g);
    check_close(what, rel_diff(sig, want), 0, 1e-10);
    snprintf(what, sizeof what, "Ogden shear g = %g: psi (rel)", g);
    check_close(what, psi / W - 1, 0, 1e-10);
}

/* A law with parameters that make it another law (Mooney-Rivlin or Yeoh with mu = 2 c10:
 * neo-Hookean; Ogden with alpha1 = 2: neo-Hookean, with alpha1 = 2, alpha2 = -2:
 * Mooney-Rivlin) against that law at 100 random deformations. */
static void is_law(const char *name, Law law, Law other)
{
    double worst = 0;
    for (int trial = 0; trial < 100; trial++) {
        double F[9], S[9], Snh[9], psi, psinh;
        for (int k = 0; k < 9; k++)
            F[k] = (k % 4 == 0) + 0.6 * uniform();
        law(F, S, &psi);
        other(F, Snh, &psinh);
        worst = fmax(worst, rel_diff(S, Snh));
        worst = fmax(worst, fabs(psi - psinh) / fabs(psinh));
    }
    char what[96];
    snprintf(what, sizeof what, "%s: S, psi (rel)", name);
    check_close(what, worst, 0, 1e-9);
}

int main(void)
{
    const double stretches[] = {0.7, 1.3, 2.0}, shears[] = {0.3, 1.0};
    for (int i = 0; i < NLAWS; i++) {
        const LawCase *lc = &LAWS[i];
        for (int k = 0; k < 3; k++)
            uniaxial(lc, stretches[k]);
        for (int k = 0; k < 2; k++)
            simple_shear(lc, shears[k]);
        dilatation(lc, 0.9);
        dilatation(lc, 1.1);
        objectivity(lc);
        small_strain(lc);
    }
    const double og_stretches[] = {0.7, 1.3, 2.0, 3.0};
    for (int k = 0; k < 4; k++)
        ogden_uniaxial(og_stretches[k]);
    for (int k = 0; k < 2; k++)
        ogden_shear(shears[k]);
    dilatation(&OGDEN, 0.9);
    dilatation(&OGDEN, 1.1);
    objectivity(&OGDEN);
    small_strain(&OGDEN);
    is_law("Mooney-Rivlin c01 = 0 vs neo-Hookean", mr_nh_material, nh_material);
    is_law("Yeoh c20 = c30 = 0 vs neo-Hookean", yeoh_nh_material, nh_material);
    is_law("Ogden alpha1 = 2 vs neo-Hookean", og_nh_material, nh_material);
    is_law("Ogden alpha1 = 2, alpha2 = -2 vs Mooney-Rivlin", og_mr_material, mr_material);
    return check_result();
}
