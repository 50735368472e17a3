//@if QUADRATIC
/* ---- body @B@: the corrected gradient exact for quadratic fields -----------------------
 * The scene's `gradient quadratic` (docs/language.md; docs/verification.md for why): each
 * particle fits the displacement's gradient and second derivatives to its pairs by least
 * squares, weighted as the first-order correction is (runtime/pairs/quadratic.h):
 *   c_i = [A_i, Aq_i] M_i^{-1},   A_i = sum_j (u_j - u_i) (x) w_ij,  Aq_i = sum_j (u_j - u_i) (x) q_ij,
 * so F_i = I + (the first D columns of c_i), exact for a bent plate's displacement at its
 * surfaces, where the first-order gradient of eq. 63 is a quarter low at 4-5 particles
 * through the thickness.  The other columns give dF/dX_a, and the particle's energy is
 * integrated over its cell to second order: with F linear across the cell,
 *   int_cell psi = V (psi(F_i) + (l^2 / 24) sum_a dE/dX_a : C0 : dE/dX_a),   l^3 = V (3D),
 * E = (F^T F - I) / 2 (objective), C0 the body's small-strain moduli, which takes out the
 * one-point rule's 1/n^2 of the bending stiffness and the zero-energy modes it leaves.
 * The forces are the exact derivative of the particles' energies: with T_i the energy's
 * derivative by c_i and Q_i = T_i M_i^{-1},
 *   rho0 dv_i/dt = sum_j (Q_i + Q_j)_lin w_ij + (Q_i - Q_j)_quad q_ij,
 * the first term the momentum pass's (Q_lin in b->Q), the second added pair by pair here;
 * a pair's force on j is minus that on i.  The lists alone sum these pairs
 * (lower/layouts.c). */
enum { @B@_QN = @DIM@ == 3 ? 6 : 3, @B@_QM = @DIM@ + @B@_QN, @B@_QR = @DIM@ == 3 ? 8 : 4 };
/* a row of Aq or an entry of qtab (the monomials, padded with zeros) in one short vector */
SPH_VECTOR(@B@_qvec, @B@_QR);

/* The monomial (the column of Aq and of qtab) whose coefficient gives d^2 u / dX_a dX_b: the
 * whole derivative for a != b, half of it for a == b (x^2's coefficient is half of
 * d^2 u / dx^2); runtime/pairs/quadratic.h's order: 3D x^2, y^2, z^2, xy, yz, xz; 2D x^2,
 * z^2, xz. */
static inline int @B@_quad_monomial(int a, int b)
{
    if (a == b)
        return a;
    return @DIM@ == 2 ? 2 : a + b == 1 ? 3 : a + b == 3 ? 4 : 5;
}

/* A pair's share of the fit's sums, Aq_i += (u_j - u_i) (x) q_ij row by row, into t; j's is
 * the same with the opposite sign (q_ij is even in the offset, u_j - u_i odd). */
static inline void @B@_quad_pair(const sph_body *b, int k, const double *uj, const double *ui,
                                 @B@_qvec t[@DIM@])
{
    const @B@_qvec q = *(const @B@_qvec *)(b->qtab + (size_t)k * @B@_QR);
    for (int r = 0; r < @DIM@; r++)
        t[r] = (sph_real)(uj[r] - ui[r]) * q;
}

/* Particle i's summed pairs aq added to its Aq. */
static inline void @B@_quad_add_to(sph_body *b, int i, const @B@_qvec aq[@DIM@])
{
    @B@_qvec *Aqi = (@B@_qvec *)(b->Aq + (size_t)i * @DIM@ * @B@_QR);
    for (int r = 0; r < @DIM@; r++)
        Aqi[r] += aq[r];
}

/* After the gradient pass: each particle's fit c = [A, Aq] M^{-1}, its gradient back into A
 * (read by the stress pass as F = I + A, L being I) and its second-derivative
 * coefficients into Aq (read by @B@_quad_stress). */
static void @B@_quad_fit(sph_body *b)
{
    enum { D = @DIM@, R = SPH_ROW(D), NQ = @B@_QN, QR = @B@_QR, M = @B@_QM };
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        sph_real *Ai = b->A + (size_t)i * D * R, *Aqi = b->Aq + (size_t)i * D * QR;
        const double *Mi = b->Mq + (size_t)i * M * M;
        for (int r = 0; r < D; r++) {
            double a[M], c[M] = {0};
            for (int k = 0; k < D; k++)
                a[k] = Ai[r * R + k];
            for (int k = 0; k < NQ; k++)
                a[D + k] = Aqi[r * QR + k];
            for (int k = 0; k < M; k++)
                for (int m = 0; m < M; m++)
                    c[m] += a[k] * Mi[k * M + m];
            for (int k = 0; k < D; k++)
                Ai[r * R + k] = (sph_real)c[k];
            for (int k = 0; k < NQ; k++)
                Aqi[r * QR + k] = (sph_real)c[D + k];
        }
    }
}

/* One particle's strain-gradient term: from F, its derivatives H[a] = dF/dX_a and the
 * law's P, the energy's derivative by the fit's coefficients, T = [Tl, Tq] (Tl = P + ...),
 * and the term's energy density, returned.  With G_a = dE/dX_a = sym(F^T H_a),
 * S_a = C0 : G_a and k = l^2 / 12: energy (k / 2) sum_a G_a : S_a, dE/dF = k sum_a H_a S_a,
 * dE/dH_a = k F S_a. */
static inline double @B@_quad_term(const double F[@DIM@][@DIM@],
                                   const double H[@DIM@][@DIM@][@DIM@], double k,
                                   double Tl[@DIM@][@DIM@], double Tq[@DIM@][@B@_QN])
{
    enum { D = @DIM@ };
    double e = 0;
    for (int a = 0; a < D; a++) {
        double G[D][D], S[D][D], tr = 0;
        for (int p = 0; p < D; p++)
            for (int q = 0; q < D; q++) {
                double g = 0;
                for (int r = 0; r < D; r++)
                    g += F[r][p] * H[a][r][q] + H[a][r][p] * F[r][q];
                G[p][q] = 0.5 * g;
            }
        for (int p = 0; p < D; p++)
            tr += G[p][p];
        for (int p = 0; p < D; p++)
            for (int q = 0; q < D; q++) {
                S[p][q] = 2.0 * @QMU@ * G[p][q] + (p == q ? @QLAMBDA@ * tr : 0.0);
                e += 0.5 * k * G[p][q] * S[p][q];
            }
        for (int r = 0; r < D; r++)
            for (int q = 0; q < D; q++) {
                double hs = 0, fs = 0;
                for (int p = 0; p < D; p++)
                    hs += H[a][r][p] * S[p][q], fs += F[r][p] * S[p][q];
                Tl[r][q] += k * hs;
                Tq[r][@B@_quad_monomial(a, q)] += (a == q ? 2.0 : 1.0) * k * fs;
            }
    }
    return e;
}

/* After the stress pass: each particle's strain-gradient term (@B@_quad_term) from its F,
 * the fit's second derivatives (Aq, cleared for the next step) and the law's P (b->Q, L
 * being I), its energy added to psi, and Q = T M^{-1}: the linear part back into b->Q, the
 * quadratic part into b->Qq for the momentum pass. */
static void @B@_quad_stress(sph_body *b)
{
    enum { D = @DIM@, R = SPH_ROW(D), NQ = @B@_QN, QR = @B@_QR, M = @B@_QM };
    const double k = pow(b->vol, 2.0 / D) / 12.0; /* l^2 / 12, the cell's second moment */
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        sph_real *Aqi = b->Aq + (size_t)i * D * QR, *Qqi = b->Qq + (size_t)i * NQ * R;
        const double *Mi = b->Mq + (size_t)i * M * M;
        double F[D][D], H[D][D][D], Tl[D][D], Tq[D][NQ] = {{0}};
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++) {
                F[r][c] = b->F[(size_t)i * 9 + sph_axis(D, r) * 3 + sph_axis(D, c)];
                Tl[r][c] = b->Q[SPH_TENSOR(i, r, c, D, b->n)];
            }
        for (int a = 0; a < D; a++)
            for (int r = 0; r < D; r++)
                for (int c = 0; c < D; c++)
                    H[a][r][c] = (a == c ? 2.0 : 1.0) * Aqi[r * QR + @B@_quad_monomial(a, c)];
        for (int m = 0; m < D * QR; m++)
            Aqi[m] = 0; /* ready for the next step's gradient pass */
        b->psi[i] += @B@_quad_term(F, H, k, Tl, Tq);
        for (int r = 0; r < D; r++)
            for (int m = 0; m < M; m++) {
                double s = 0;
                for (int c = 0; c < D; c++)
                    s += Tl[r][c] * Mi[c * M + m];
                for (int c = 0; c < NQ; c++)
                    s += Tq[r][c] * Mi[(D + c) * M + m];
                if (m < D)
                    b->Q[SPH_TENSOR(i, r, m, D, b->n)] = (sph_real)s;
                else
                    Qqi[(m - D) * R + r] = (sph_real)s; /* column m - D, like Q's */
            }
    }
}

/* The momentum pass's pair term: (Q_i - Q_j)_quad q_ij / rho0 added to the pair's force f on
 * i, column by column (a column of Qq in a short vector, like Q's). */
static inline void @B@_quad_momentum(const sph_body *b, int i, int j, int k, sph_real inv_rho,
                                     @B@_vec *f)
{
    enum { NQ = @B@_QN };
    const @B@_vec *qi = (const @B@_vec *)b->Qq + (size_t)i * NQ;
    const @B@_vec *qj = (const @B@_vec *)b->Qq + (size_t)j * NQ;
    const sph_real *q = b->qtab + (size_t)k * @B@_QR;
    for (int m = 0; m < NQ; m++)
        *f += (qi[m] - qj[m]) * (q[m] * inv_rho);
}
//@endif
