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

/* G += A L^T: a pair sum of the gradient pass (D x D, row by row) corrected by the particle's
 * L (eq. 53, 63), into the in-plane entries of the 3x3 G. */
SPH_FN void @B@_add_corrected(const double *A, const double *L, double G[9])
{
    enum { D = @DIM@ };
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++) {
            double a = 0;
            for (int k = 0; k < D; k++)
                a += A[r * D + k] * L[c * D + k];
            G[sph_axis(D, r) * 3 + sph_axis(D, c)] += a;
        }
}

/* ---- body @B@: one particle's stress ---------------------------------------------------
 * From A_i = sum_j V_j (u_j - u_i) (x) grad W_ij and the particle's correction L_i: F = I +
 * A L^T (eq. 53 with the corrected gradient), the material law (S, psi), P = F S (eq. 2), and
 * what the momentum pass needs of each particle: Q = P L and, for artificial viscosity,
 * Cv = cof(F) = J F^-T and Cs = 1 / its largest singular value.  Arithmetic on its arguments
 * alone (no array of the body's), so that the CPU's stress pass can run it on several
 * particles in one vector instruction (body_forces.c); @B@_particle_stress below calls it for
 * particle i of the body.  D x D tensors row by row; Fp gets F's in-plane block (the
 * out-of-plane entries of a 2D F never change).
//@if FRACTURE
 * With fracture: F = I where s <= s_l (eq. 63), the stress degraded by s (eq. 18), the
 * history H = max(H, psi+) (eq. 8) and the phase-field acceleration sdd of eq. 61 from the
 * Laplacian lap of eq. 62.
//@endif
//@if STATE
 * The law's state st (plasticity) advances once per step, here: st_new.
//@endif
//@if LAW_FDOT
 * Ad = sum_j V_j (v_j - v_i) (x) grad W_ij gives the rate Fd = dF/dt the law reads (Fdp: its
 * in-plane block, out).
//@endif
//@if LAW_DT
 * dt: the time since the law's last evaluation (its state's step).
//@endif
 */
SPH_FLAT void @B@_stress_of(const double *A, const double *L,
//@if FRACTURE
                            double s, double lap, double *H, double *sdd,
//@endif
//@if LAW_FDOT
                            const double *Ad, double *Fdp,
//@endif
//@if LAW_DT
                            double dt,
//@endif
//@if STATE
                            const double *st, double *st_new,
//@endif
//@if CRUSH
                            double *lam2,
//@endif
                            double *psi, double *Fp, double *Q
//@if VISCOSITY
                            , double *Cv, double *Cs
//@endif
//@if RARE
                            , int fast, double *rare
//@endif
                            )
{
    enum { D = @DIM@ };
    double F[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    @B@_add_corrected(A, L, F);
//@if LAW_FDOT
    /* dF/dt = Ad L^T, the velocity's corrected gradient as F's of the displacement */
    double Fd[9] = {0};
    @B@_add_corrected(Ad, L, Fd);
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++)
            Fdp[r * D + c] = Fd[sph_axis(D, r) * 3 + sph_axis(D, c)];
//@endif
    double S[9], e;
//@if LAW_WAVE
    double cw; /* the law's wave speed */
//@endif
//@if FRACTURE
    /* eq. 63: a broken particle carries no deformation (a select, not a branch, like
     * everything here: a branch would keep the compiler from vectorising the CPU's loop) */
    const int broken = s <= @SLIMIT@;
    for (int k = 0; k < 9; k++)
        F[k] = broken ? (double)(k % 4 == 0) : F[k];
    double ep;
    @B@_material(F, s, S, &e, &ep);
    *H = sph_max(*H, ep);
    /* eq. 61 without its damping term: s'' + gamma s' = c^2/(2 eps0) (2 eps0 lap s +
     * (1 - s)/(2 eps0) - 2 s H/Gc), c = c0; gamma s' is integrated by the update */
    *sdd = @PF_A@ * (2 * @EPS0@ * lap + (1 - s) * (0.5 / @EPS0@) - 2 * s * *H * (1.0 / @GC@));
//@else
//@if STATE
//@if RARE
    /* fast: the law without its rare `if` blocks, *rare whether one was due */
    if (fast)
        @B@_material_fast(F, @LAW_ARGS@st, st_new, S, &e@LAW_OUTS@, rare);
    else
        @B@_material(F, @LAW_ARGS@st, st_new, S, &e@LAW_OUTS@);
//@else
    @B@_material(F, @LAW_ARGS@st, st_new, S, &e@LAW_OUTS@);
//@endif
//@else
    @B@_material(F, @LAW_ARGS@S, &e@LAW_OUTS@);
//@endif
//@endif
    *psi = e;
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++)
            Fp[r * D + c] = F[sph_axis(D, r) * 3 + sph_axis(D, c)];
//@if CRUSH
    /* the smallest principal stretch squared, for the time step where the body is
     * compressed (timestep auto: eq. 65 on the current spacing; runtime/run/sim.c) */
    *lam2 = sph_stretch2_min(F, D);
//@if LAW_WAVE
    /* where the law's wave speed exceeds the body's c0 (an equation of state under
     * compression), the bound follows it as it follows the spacing: the Courant number on
     * the spacing lambda h at the speed cw is that on lambda (c0 / cw) h at c0 */
    *lam2 *= cw > @C0@ ? (@C0@ / cw) * (@C0@ / cw) : 1.0;
//@endif
//@endif
    /* P = F S (eq. 2), in-plane block, then Q = P L */
    double P[D * D];
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++) {
            double a = 0;
            for (int k = 0; k < 3; k++)
                a += F[sph_axis(D, r) * 3 + k] * S[k * 3 + sph_axis(D, c)];
            P[r * D + c] = a;
        }
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++) {
            double a = 0;
            for (int k = 0; k < D; k++)
                a += P[r * D + k] * L[k * D + c];
            Q[r * D + c] = a;
        }
//@if VISCOSITY
    /* cof(F) = J F^-T: the Piola transform of the viscous pressure (eq. 57), without the
     * gradient correction L, so that the pair's direction (cof F_i + cof F_j) grad W turns
     * exactly with the pair under a rigid rotation (docs/stability.md) */
//@if FRACTURE
    /* degraded like the elastic stress, so that a crack does not carry viscous stress
     * either (its faces would otherwise be held back as they separate) */
    const double vdeg = s * s;
//@else
    const double vdeg = 1;
//@endif
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++)
            Cv[r * D + c] = sph_cofactor(F, sph_axis(D, r), sph_axis(D, c)) * vdeg;
    /* lambda_min / J: a pair's approach rate along (cof F_i + cof F_j) grad W, times this,
     * is in the pair's reference length, as eq. 60 takes it (body_forces.c) */
    *Cs = sph_viscous_scale(F, D);
//@endif
}

//@if ONE_PARTICLE
/* One particle's stress (@B@_stress_of) from A_i and the body's arrays, the results into
 * them: the CUDA target's thread of a particle, and the CPU's stress pass where it runs over
 * the body's arrays themselves (body_forces.c).  F is stored where store_F (a constant at
 * each call, so that the CPU's loop is built once with the store and once without).
//@if LAW_FDOT
 * Ad: the particle's sum of the velocity's gradient (D x D), for the rate of F.
//@endif
//@if LAW_DT
 * dt: the time since the law's last evaluation.
//@endif
 */
SPH_FLAT void @B@_particle_stress(sph_body *b, int i, const double *A
//@if LAW_FDOT
                                  , const double *Ad
//@endif
//@if LAW_DT
                                  , double dt
//@endif
                                  , int store_F)
{
    enum { D = @DIM@ };
    double F[D * D], Q[D * D];
//@if VISCOSITY
    double Cv[D * D], Cs;
//@endif
//@if STATE
    double *st = b->state + (size_t)i * @NSTATE@, st_new[@NSTATE@];
//@endif
//@if LAW_FDOT
    double Fdp[D * D];
//@endif
    @B@_stress_of(A, b->L + (size_t)i * D * D,
//@if FRACTURE
                  b->s[i], b->lap[i], &b->H[i], &b->sdd[i],
//@endif
//@if LAW_FDOT
                  Ad, Fdp,
//@endif
//@if LAW_DT
                  dt,
//@endif
//@if STATE
                  st, st_new,
//@endif
//@if CRUSH
                  &b->lam2[i],
//@endif
                  &b->psi[i], F, Q
//@if VISCOSITY
                  , Cv, &Cs
//@endif
//@if RARE
                  , 0, NULL
//@endif
                  );
//@if STATE
    for (int k = 0; k < @NSTATE@; k++)
        st[k] = st_new[k];
//@endif
//@if FRACTURE
    b->lap[i] = 0;
//@endif
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++) {
            if (store_F)
                b->F[(size_t)i * 9 + sph_axis(D, r) * 3 + sph_axis(D, c)] = F[r * D + c];
//@if LAW_FDOT
            b->Fd[(size_t)i * 9 + sph_axis(D, r) * 3 + sph_axis(D, c)] = Fdp[r * D + c];
//@endif
            b->Q[SPH_TENSOR(i, r, c, D, b->n)] = (sph_real)Q[r * D + c];
//@if VISCOSITY
            b->Cv[SPH_TENSOR(i, r, c, D, b->n)] = (sph_real)Cv[r * D + c];
//@endif
        }
//@if VISCOSITY
    b->Cs[i] = (sph_real)Cs;
//@endif
}
//@endif

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
