/* ---- body @B@: internal forces ------------------------------------------------------
 * Pass 1, per particle: deformation gradient with corrected kernel gradients (eq. 53),
 * the material law (S, psi), P = F S (eq. 2), and the products the momentum pass gathers
 * from neighbours: Q = P L and, for artificial viscosity, Cv = cof(F) L = J F^-T L. */
static void @B@_stress_pass(sph_body *b)
{
    enum { D = @DIM@ };
    const int n = b->n;
    const int *restrict start = b->nb_start, *restrict nb = b->nb, *restrict nbk = b->nb_k;
    const double *restrict wtab = b->wtab, *restrict wsum = b->wsum;
    const double *restrict u = b->u, *restrict Lc = b->L;
    double *restrict Fs = b->F, *restrict Q = b->Q, *restrict psi = b->psi;
//@if VISCOSITY
    double *restrict Cv = b->Cv;
//@endif
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        /* A = sum_j V_j (u_j - u_i) (x) grad W_ij = sum_j u_j (x) w_ij - u_i (x) wsum_i;
         * F = I + A L^T  (eq. 53, corrected) */
        double A[D * D] = {0};
        for (int p = start[i]; p < start[i + 1]; p++) {
            const int j = nb[p];
            const double *w = wtab + (size_t)nbk[p] * D;
            for (int r = 0; r < D; r++)
                for (int c = 0; c < D; c++)
                    A[r * D + c] += u[j * D + r] * w[c];
        }
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++)
                A[r * D + c] -= u[i * D + r] * wsum[i * D + c];
        const double *L = Lc + (size_t)i * D * D;
        double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++) {
                double s = 0;
                for (int k = 0; k < D; k++)
                    s += A[r * D + k] * L[c * D + k];
                F[sph_axis(D, r) * 3 + sph_axis(D, c)] += s;
            }
        double S[9], e;
        @B@_material(F, S, &e);
        psi[i] = e;
        for (int k = 0; k < 9; k++)
            Fs[(size_t)i * 9 + k] = F[k];
        /* P = F S (eq. 2), in-plane block, then Q = P L */
        double P[D * D];
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++) {
                double s = 0;
                for (int k = 0; k < 3; k++)
                    s += F[sph_axis(D, r) * 3 + k] * S[k * 3 + sph_axis(D, c)];
                P[r * D + c] = s;
            }
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++) {
                double s = 0;
                for (int k = 0; k < D; k++)
                    s += P[r * D + k] * L[k * D + c];
                Q[(size_t)i * D * D + r * D + c] = s;
            }
//@if VISCOSITY
        /* cof(F) = J F^-T: the Piola transform of the viscous pressure (eq. 57) */
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++) {
                double s = 0;
                for (int k = 0; k < D; k++)
                    s += sph_cofactor(F, sph_axis(D, r), sph_axis(D, k)) * L[k * D + c];
                Cv[(size_t)i * D * D + r * D + c] = s;
            }
//@endif
    }
}

/* Pass 2, per particle: momentum balance (eq. 55) in the symmetric corrected form
 *   dv_i/dt = 1/rho0 sum_j V_j (P_i L_i + P_j L_j) grad W_ij
 *           = 1/rho0 (Q_i wsum_i + sum_j Q_j w_ij)
 * which conserves linear momentum (every pair force is equal and opposite), plus
 * artificial viscosity (eq. 57-60), symmetrised the same way, and body forces. */
static void @B@_momentum_pass(sph_body *b)
{
    enum { D = @DIM@ };
    const int n = b->n;
    const int *restrict start = b->nb_start, *restrict nb = b->nb, *restrict nbk = b->nb_k;
    const double *restrict wtab = b->wtab, *restrict wsum = b->wsum, *restrict Q = b->Q;
    double *restrict acc = b->a;
    const double inv_rho = 1.0 / b->rho0;
//@if VISCOSITY
    const double *restrict v = b->v, *restrict Cv = b->Cv, *restrict gtab = b->gtab;
//@endif
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++) {
        double f[D] = {0};
//@if VISCOSITY
        double fv[D] = {0}, pw[D] = {0};
//@endif
        for (int p = start[i]; p < start[i + 1]; p++) {
            const int j = nb[p], k = nbk[p];
            const double *w = wtab + (size_t)k * D;
            const double *Qj = Q + (size_t)j * D * D;
            for (int r = 0; r < D; r++)
                for (int c = 0; c < D; c++)
                    f[r] += Qj[r * D + c] * w[c];
//@if VISCOSITY
            /* G_ij (eq. 60; gtab holds h / (r^2 + 0.001 h^2) in the units of w) and the
             * viscous pressure pi_ij (eq. 58, times rho0), which resists relative motion
             * along the reference separation. */
            double vw = 0;
            for (int c = 0; c < D; c++)
                vw += (v[i * D + c] - v[j * D + c]) * w[c];
            const double G = gtab[k] * vw;
            double pi = -@BETA1@ * @C0@ * G;
//@if BETA2
            const double Gc = 0.5 * (G - fabs(G)); /* min(G, 0): beta2 acts on approach only */
            pi += @BETA2@ * Gc * Gc;
//@endif
            const double *Cj = Cv + (size_t)j * D * D;
            for (int c = 0; c < D; c++) {
                const double piw = pi * w[c];
                pw[c] += piw;
                for (int r = 0; r < D; r++)
                    fv[r] += Cj[r * D + c] * piw;
            }
//@endif
        }
        const double *Qi = Q + (size_t)i * D * D;
//@if VISCOSITY
        const double *Ci = Cv + (size_t)i * D * D;
//@endif
        for (int r = 0; r < D; r++) {
            double fr = f[r];
            for (int c = 0; c < D; c++)
                fr += Qi[r * D + c] * wsum[i * D + c];
            double ar = fr * inv_rho;
//@if VISCOSITY
            double vr = fv[r];
            for (int c = 0; c < D; c++)
                vr += Ci[r * D + c] * pw[c];
            ar -= 0.5 * vr;
//@endif
//@if GRAVITY
            ar += @B@_gravity[r];
//@endif
            acc[i * D + r] = ar;
        }
    }
}

static void @B@_forces(sph_body *b)
{
    @B@_stress_pass(b);
    @B@_momentum_pass(b);
}

/* Cauchy stress sigma = F S F^T / J for output (xx yy zz xy yz zx). */
static void @B@_stress_output(sph_body *b)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->n; i++) {
        const double *F = b->F + (size_t)i * 9;
        double S[9], e, FS[9], sig[9];
        @B@_material(F, S, &e);
        sph_mat3_mul(F, S, FS);
        sph_mat3_mul_bt(FS, F, sig);
        const double J = sph_det3(F);
        static const int idx[6] = {0, 4, 8, 1, 5, 2};
        for (int k = 0; k < 6; k++)
            b->sigma[(size_t)i * 6 + k] = sig[idx[k]] / J;
    }
}
