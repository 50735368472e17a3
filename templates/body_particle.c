//@if FRACTURE
/* The phase field's rate over a step of length h from s'_0 with the undamped s'' of the
 * stress pass: s'_1 = s'_0 + h (s'' - gamma s'_1), the damping of eq. 61 taken at the end
 * of the step, gamma = 2 sqrt(4 eps0 H/Gc + 1) c / (2 eps0) (M of eq. 9).  Explicitly it would
 * need h gamma < 2, and gamma grows without bound with the history H of broken material;
 * this form is stable for any h and equals eq. 61 to O(h gamma). */
SPH_FN double @B@_phase_rate(double sd0, double sdd, double H, double h)
{
    const double gamma = sqrt(4 * @EPS0@ * H * (1.0 / @GC@) + 1) * (@C0@ / @EPS0@);
    return (sd0 + h * sdd) / (1 + h * gamma);
}

/* A step of the phase field s += h s', kept in [0, 1] (broken to intact); at a bound its
 * rate stops. */
SPH_FN void @B@_phase_move(double *s, double *sd, double h)
{
    const double x = *s + h * *sd;
    *s = x < 0 ? 0 : x > 1 ? 1 : x;
    if (x != *s)
        *sd = 0;
}

//@endif

/* ---- body @B@: one particle's stress ---------------------------------------------------
 * From A_i = sum_j V_j (u_j - u_i) (x) grad W_ij: F = I + A L^T (eq. 53 with the corrected
 * gradient), the material law (S, psi), P = F S (eq. 2), and what the momentum pass needs of
 * each particle: Q = P L and, for artificial viscosity, Cv = cof(F) = J F^-T.  Shared by
 * the CPU passes (body_forces.c) and the CUDA ones (body_cuda.cu).
//@if FRACTURE
 * With fracture: F = I where s <= s_l (eq. 63), the stress degraded by s (eq. 18), the
 * history H = max(H, psi+) (eq. 8) and the phase-field acceleration of eq. 61.
//@endif
 */
SPH_FN void @B@_particle_stress(sph_body *b, int i, const double *A)
{
    enum { D = @DIM@ };
    const double *L = b->L + (size_t)i * D * D;
    double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++) {
            double s = 0;
            for (int k = 0; k < D; k++)
                s += A[r * D + k] * L[c * D + k];
            F[sph_axis(D, r) * 3 + sph_axis(D, c)] += s;
        }
    double S[9], e;
//@if FRACTURE
    /* eq. 63: a broken particle carries no deformation (a select, not a branch: the
     * stress pass's loop over particles is vectorised where the law has no branches) */
    const int broken = b->s[i] <= @SLIMIT@;
    for (int k = 0; k < 9; k++)
        F[k] = broken ? (double)(k % 4 == 0) : F[k];
    double ep;
    @B@_material(F, b->s[i], S, &e, &ep);
    b->H[i] = sph_max(b->H[i], ep);
    /* eq. 61 without its damping term: s'' + gamma s' = c^2/(2 eps0) (2 eps0 lap s +
     * (1 - s)/(2 eps0) - 2 s H/Gc), c = c0; gamma s' is integrated by the update */
    b->sdd[i] = @PF_A@ * (2 * @EPS0@ * b->lap[i] + (1 - b->s[i]) * (0.5 / @EPS0@) -
                       2 * b->s[i] * b->H[i] * (1.0 / @GC@));
    b->lap[i] = 0; /* ready for the next step's gradient pass */
//@else
//@if STATE
    /* the law's state (plasticity) advances once per step, here */
    double *st = b->state + (size_t)i * @NSTATE@, st_new[@NSTATE@];
    @B@_material(F, st, st_new, S, &e);
    for (int k = 0; k < @NSTATE@; k++)
        st[k] = st_new[k];
//@else
    @B@_material(F, S, &e);
//@endif
//@endif
    b->psi[i] = e;
    for (int r = 0; r < D; r++) /* the out-of-plane entries of a 2D F never change */
        for (int c = 0; c < D; c++)
            b->F[(size_t)i * 9 + sph_axis(D, r) * 3 + sph_axis(D, c)] =
                F[sph_axis(D, r) * 3 + sph_axis(D, c)];
//@if CRUSH
    /* the smallest principal stretch squared, for the time step where the body is
     * compressed (timestep auto: eq. 65 on the current spacing; runtime/sim.c) */
    b->lam2[i] = sph_stretch2_min(F, D);
//@endif
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
            b->Q[SPH_TENSOR(i, r, c, D, b->n)] = (sph_real)s;
        }
//@if VISCOSITY
    /* cof(F) = J F^-T: the Piola transform of the viscous pressure (eq. 57), without the
     * gradient correction L, so that the pair's direction (cof F_i + cof F_j) grad W turns
     * exactly with the pair under a rigid rotation (docs/stability.md) */
//@if FRACTURE
    /* degraded like the elastic stress, so that a crack does not carry viscous stress
     * either (its faces would otherwise be held back as they separate) */
    const double vdeg = b->s[i] * b->s[i];
//@endif
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++) {
            const double s = sph_cofactor(F, sph_axis(D, r), sph_axis(D, c));
//@if FRACTURE
            b->Cv[SPH_TENSOR(i, r, c, D, b->n)] = (sph_real)(s * vdeg);
//@else
            b->Cv[SPH_TENSOR(i, r, c, D, b->n)] = (sph_real)s;
//@endif
        }
//@endif
}

//@if HOURGLASS
/* Hourglass control (Ganzenmueller 2015) of the pair (i, j) with offset table entry k: the
 * pair's separation predicted by F_i and by F_j, minus the actual one, projected on the
 * current direction, is pushed back by a penalty alpha E V_i V_j W / (2 r0^2); subtracted
 * from the pair force f on i (the same from j's side, with the signs of the reversed pair). */
SPH_FN void @B@_hourglass(const sph_body *b, int i, int j, int k, sph_real *f)
{
    enum { D = @DIM@ };
    double Xij[D], xij[D], r2 = 0;
    for (int c = 0; c < D; c++) {
        Xij[c] = b->X[j * D + c] - b->X[i * D + c];
        xij[c] = Xij[c] + b->u[j * D + c] - b->u[i * D + c];
        r2 += xij[c] * xij[c];
    }
    double delta = 0;
    for (int r = 0; r < D; r++) {
        double pred = 0;
        for (int c = 0; c < D; c++)
            pred += (b->F[(size_t)i * 9 + sph_axis(D, r) * 3 + sph_axis(D, c)] +
                     b->F[(size_t)j * 9 + sph_axis(D, r) * 3 + sph_axis(D, c)]) * Xij[c];
        delta += (pred - 2 * xij[r]) * xij[r];
    }
    /* delta/r times 1/r; r2 = 0 only for the empty slots of the device's lists */
    const double hg = r2 > 0 ? @HG@ * b->htab[k] * delta / r2 : 0;
    for (int r = 0; r < D; r++)
        f[r] -= (sph_real)(hg * xij[r]);
}
//@endif
//@if PAIR_TERMS

/* The terms body @B@ adds to the force f on particle i of the pair (i, j), offset table
 * entry k, in both targets' momentum passes (the same from j's side with the reversed
 * pair).  A new pair term is a function above and a line here, under its switch. */
SPH_FN void @B@_pair_terms(const sph_body *b, int i, int j, int k, sph_real *f)
{
//@if HOURGLASS
    @B@_hourglass(b, i, j, k, f);
//@endif
}
//@endif
