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
 * a pair's force on j is minus that on i.  Here what one particle or one pair computes, for
 * both targets: the CPU's passes (body_quadratic_cpu.c; the half lists alone sum these
 * pairs, lower/layouts.c) and the device's, one thread a particle (body_cuda.cu). */
enum { @B@_QN = @DIM@ == 3 ? 6 : 3, @B@_QM = @DIM@ + @B@_QN, @B@_QR = @DIM@ == 3 ? 8 : 4 };

/* The monomial (the column of Aq and of qtab) whose coefficient gives d^2 u / dX_a dX_b: the
 * whole derivative for a != b, half of it for a == b (x^2's coefficient is half of
 * d^2 u / dx^2); runtime/pairs/quadratic.h's order: 3D x^2, y^2, z^2, xy, yz, xz; 2D x^2,
 * z^2, xz. */
SPH_FN int @B@_quad_monomial(int a, int b)
{
    if (a == b)
        return a;
    return @DIM@ == 2 ? 2 : a + b == 1 ? 3 : a + b == 3 ? 4 : 5;
}

/* One row of the fit: c = a M_i^{-1}, a = [a row of A, that row of Aq], Mi the particle's
 * inverse moment matrix (runtime/pairs/quadratic.h). */
SPH_FN void @B@_quad_solve(const double a[@B@_QM], const double *Mi, double c[@B@_QM])
{
    enum { M = @B@_QM };
    for (int m = 0; m < M; m++)
        c[m] = 0;
    for (int k = 0; k < M; k++)
        for (int m = 0; m < M; m++)
            c[m] += a[k] * Mi[k * M + m];
}

/* One particle's strain-gradient term: from F, its derivatives H[a] = dF/dX_a and the
 * law's P, the energy's derivative by the fit's coefficients, T = [Tl, Tq] (Tl = P + ...),
 * and the term's energy density, returned.  With G_a = dE/dX_a = sym(F^T H_a),
 * S_a = C0 : G_a and k = l^2 / 12: energy (k / 2) sum_a G_a : S_a, dE/dF = k sum_a H_a S_a,
 * dE/dH_a = k F S_a. */
SPH_FN double @B@_quad_term(const double F[@DIM@][@DIM@], const double H[@DIM@][@DIM@][@DIM@],
                           double k, double Tl[@DIM@][@DIM@], double Tq[@DIM@][@B@_QN])
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

/* Particle i's strain-gradient term after its stress (F in b->F, the law's P in b->Q, L
 * being I): from cq, the fit's second-derivative coefficients (row r, monomial m), and k =
 * l^2 / 12, the cell's second moment, @B@_quad_term's energy added to psi, and Q = T M^{-1}:
 * the linear part back into b->Q, the quadratic part into b->Qq for the momentum pass. */
SPH_FN void @B@_quad_stress_of(sph_body *b, int i, double k, const double cq[@DIM@][@B@_QN])
{
    enum { D = @DIM@, R = SPH_ROW(D), NQ = @B@_QN, M = @B@_QM };
    sph_real *Qqi = b->Qq + (size_t)i * NQ * R;
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
                H[a][r][c] = (a == c ? 2.0 : 1.0) * cq[r][@B@_quad_monomial(a, c)];
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

/* The momentum pass's pair term, (Q_i - Q_j)_quad q_ij / rho0 added to the pair's force f on
 * i, from the particles' Qq (columns of R entries) and the pair's monomials q (even in the
 * offset: the reversed pair's are the same).  The device's form; the CPU's half lists add the
 * same a column at a time in short vectors (@B@_quad_momentum, body_quadratic_cpu.c). */
SPH_FN void @B@_quad_pair_force(const sph_real *qi, const sph_real *qj, const sph_real *q,
                                sph_real inv_rho, sph_real f[@DIM@])
{
    enum { R = SPH_ROW(@DIM@) };
    for (int m = 0; m < @B@_QN; m++)
        for (int r = 0; r < @DIM@; r++)
            f[r] += (qi[m * R + r] - qj[m * R + r]) * (q[m] * inv_rho);
}
//@endif
