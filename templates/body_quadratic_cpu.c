//@if QUADRATIC
/* ---- body @B@: the quadratic gradient's passes on the CPU ------------------------------
 * body_quadratic.c's fit and strain-gradient term over the own particles, and its pair sums
 * in the half lists' pairs (body_forces.c), a row of Aq or an entry of qtab (the monomials,
 * padded with zeros) in one short vector. */
SPH_VECTOR(@B@_qvec, @B@_QR);

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

/* After the gradient pass: each particle's fit c = [A, Aq] M^{-1} (@B@_quad_solve), its
 * gradient back into A (read by the stress pass as F = I + A, L being I) and its
 * second-derivative coefficients into Aq (read by @B@_quad_stress). */
static void @B@_quad_fit(sph_body *b)
{
    enum { D = @DIM@, R = SPH_ROW(D), NQ = @B@_QN, QR = @B@_QR, M = @B@_QM };
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        sph_real *Ai = b->A + (size_t)i * D * R, *Aqi = b->Aq + (size_t)i * D * QR;
        const double *Mi = b->Mq + (size_t)i * M * M;
        for (int r = 0; r < D; r++) {
            double a[M], c[M];
            for (int k = 0; k < D; k++)
                a[k] = Ai[r * R + k];
            for (int k = 0; k < NQ; k++)
                a[D + k] = Aqi[r * QR + k];
            @B@_quad_solve(a, Mi, c);
            for (int k = 0; k < D; k++)
                Ai[r * R + k] = (sph_real)c[k];
            for (int k = 0; k < NQ; k++)
                Aqi[r * QR + k] = (sph_real)c[D + k];
        }
    }
}

/* After the stress pass: each particle's strain-gradient term and Q, Qq
 * (@B@_quad_stress_of) from the fit's second derivatives in Aq, which are cleared for the
 * next step's gradient pass. */
static void @B@_quad_stress(sph_body *b)
{
    enum { D = @DIM@, NQ = @B@_QN, QR = @B@_QR };
    const double k = pow(b->vol, 2.0 / D) / 12.0; /* l^2 / 12, the cell's second moment */
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        sph_real *Aqi = b->Aq + (size_t)i * D * QR;
        double cq[D][NQ];
        for (int r = 0; r < D; r++)
            for (int m = 0; m < NQ; m++)
                cq[r][m] = Aqi[r * QR + m];
        for (int m = 0; m < D * QR; m++)
            Aqi[m] = 0; /* ready for the next step's gradient pass */
        @B@_quad_stress_of(b, i, k, cq);
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
