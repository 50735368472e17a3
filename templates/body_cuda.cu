/* ---- body @B@: internal forces on the device (CUDA target) --------------------------------
 * The passes of templates/body_forces.c with one thread per particle: b is the body's device
 * view (runtime/sph_cuda.h), whose full pair lists let every thread sum its own particle's
 * pairs, so no two threads write the same particle.  The pair terms are those of the CPU
 * passes, computed from both sides (w_ji = -w_ij).  Pair s of particle i is slot s of its
 * list (sph_slot): a warp reads its particles' pairs as consecutive words; on a lattice slot s
 * is one offset for every particle, and where a particle lacks it the slot holds a particle
 * near that offset with a zero table entry (a hole: sph_hole, sph_full_lists). */

/* Slot s of particle i: its neighbour (returned), its table entry (*k: ~k for the reversed
 * pair), V_j grad_i W_ij (w), and the pair's factor G_ij / ((v_i - v_j) . w) of eq. 60 (g)
 * and Laplacian weight of eq. 62 (l).  From the offset table: entry k, or ~k for the
 * reversed pair (w_ji = -w_ij), a few hundred entries that stay in the L1 cache.  Built with
 * -DSPH_CUDA_RECOMPUTE, from the reference positions instead, as the set-up computes the
 * table (runtime/run/setup.c): no table entry per pair but X_j and a kernel evaluation, the other
 * layout docs/cuda.md weighs (bench/cuda times both).  What a pass does not use of it the
 * compiler drops. */
SPH_FN int @B@_pair(const sph_body *b, int i, int s, int *k, sph_real w[@DIM@], sph_real *g,
                    sph_real *l)
{
    enum { D = @DIM@ };
    const int j = sph_slot(b, i, s, k);
#ifdef SPH_CUDA_RECOMPUTE
    double d[D], wd[D];
    for (int c = 0; c < D; c++)
        d[c] = b->X[i * D + c] - b->X[j * D + c];
    const double f = sph_pair_w(@KERNEL@, D, b->h, b->vol, d, wd); /* as table_entry, setup.c */
    for (int c = 0; c < D; c++)
        w[c] = (sph_real)wd[c];
    *g = (sph_real)sph_viscosity_factor(D, b->h, d, wd);
    *l = (sph_real)(2 * f);
#else
    const int e = *k < 0 ? ~*k : *k;
    const sph_real sg = *k < 0 ? (sph_real)-1 : (sph_real)1;
    for (int c = 0; c < D; c++)
        w[c] = sg * b->wtab[(size_t)e * SPH_ROW(D) + c];
    *g = b->gtab[e];
//@if FRACTURE
    *l = b->ltab[e];
//@else
    *l = 0;
//@endif
#endif
    return j;
}

//@if CLAMP
/* A clamp by mirror images (run/clamp_image.h, as the CPU's passes), a thread an image: at
 * the start of the step's passes each image takes minus its particle's u and v, after the
 * stress pass it carries no stress or energy, after the momentum pass its force acts on its
 * particle (without the gravity it got). */
static void @B@_clamp_images(sph_body *b)
{
    SPH_FOR(k, b->nimages, { sph_clamp_image_move(b, k); });
}

static void @B@_clamp_quiet(sph_body *b)
{
    SPH_FOR(k, b->nimages, { sph_clamp_image_quiet(b, k); });
}

static void @B@_clamp_reactions(sph_body *b)
{
    SPH_FOR(k, b->nimages, {
        const double g[3] = {@G0@, @G1@, @G2@};
        sph_clamp_image_reaction(b, k, g);
    });
}

//@endif
/* Pass 1-2, per particle: A_i = sum_j V_j (u_j - u_i) (x) grad W_ij over the particle's
 * full list, then F, the law, P L and cof(F) (@B@_particle_stress, body_particle.c).
//@if LAW_FDOT
 * Over the same pairs the velocity's gradient Ad_i, for the rate of F the law reads.
//@endif
//@if QUADRATIC
 * With the quadratic gradient (body_quadratic.c) the same pairs' Aq_i as well, the fit's
 * gradient in A (L being I) and its second derivatives' strain-gradient term after the law.
//@endif
//@if LAW_DT
 * law_dt: the time since the law's last evaluation (a value, or the device clock's).
//@endif
 */
static void @B@_stress_pass(sph_body *b
//@if LAW_DT
                            , sph_time law_dt
//@endif
                            )
{
    enum { D = @DIM@ };
//@if MPI
    /* on many processes the halo's u (v, s) first, staged through the host (sph_cuda.h) */
    const sph_cuda_field halo_in[] = {
        {b->u, sizeof *b->u, D, D, 1},
//@if PAIR_V
        {b->v, sizeof *b->v, D, D, 1},
//@endif
//@if FRACTURE
        {b->s, sizeof *b->s, 1, 1, 1},
//@endif
    };
    sph_cuda_halo(b, halo_in, sizeof halo_in / sizeof *halo_in);
//@endif
//@if CLAMP
    @B@_clamp_images(b); /* the clamp's images move with their particles */
//@endif
    const double *u = sph_cuda_components(b->u, b->us, b->n, D); /* u_x of all, u_y, ... */
//@if LAW_FDOT
    const double *v = sph_cuda_components(b->v, b->vs, b->n, D);
//@endif
//@if QUADRATIC
    const double quad_k = pow(b->vol, 2.0 / @DIM@) / 12.0; /* l^2 / 12, the cell's second moment */
//@endif
    SPH_FOR(i, b->nown, {
        const size_t n = (size_t)b->n;
        double A[D * D] = {0}, ui[D];
        for (int r = 0; r < D; r++)
            ui[r] = u[SPH_VEC(i, r, D, n)];
//@if LAW_FDOT
        double Ad[D * D] = {0}, vi[D];
        for (int r = 0; r < D; r++)
            vi[r] = v[SPH_VEC(i, r, D, n)];
//@endif
//@if FRACTURE
        double lap = 0; /* the Laplacian of the phase field (eq. 62) over the same pairs */
//@endif
//@if QUADRATIC
        double aq[D][@B@_QN] = {{0}}; /* sum_j (u_j - u_i) (x) q_ij */
//@endif
        for (int s = 0, slots = b->fb_count[i]; s < slots; s++) {
            sph_real w[D], g, l;
            int k;
            const int j = @B@_pair(b, i, s, &k, w, &g, &l);
            double d[D]; /* u_j - u_i */
            for (int r = 0; r < D; r++)
                d[r] = u[SPH_VEC(j, r, D, n)] - ui[r];
            @B@_gradient_term_d(A, d, w);
//@if QUADRATIC
            { /* the pair's monomials, the same both ways (even in the offset) */
                const sph_real *q = b->qtab + (size_t)(k < 0 ? ~k : k) * @B@_QR;
                for (int r = 0; r < D; r++)
                    for (int m = 0; m < @B@_QN; m++)
                        aq[r][m] += d[r] * (double)q[m];
            }
//@endif
//@if LAW_FDOT
            for (int r = 0; r < D; r++) /* v_j - v_i, the same term */
                d[r] = v[SPH_VEC(j, r, D, n)] - vi[r];
            @B@_gradient_term_d(Ad, d, w);
//@endif
//@if FRACTURE
            lap += l * (b->s[i] - b->s[j]);
//@endif
        }
//@if FRACTURE
        b->lap[i] = lap;
//@endif
//@if QUADRATIC
        const double *Mi = b->Mq + (size_t)i * @B@_QM * @B@_QM;
        for (int r = 0; r < D; r++) { /* the fit, row by row: A its gradient, aq the rest */
            double a[@B@_QM], c[@B@_QM];
            for (int k = 0; k < D; k++)
                a[k] = A[r * D + k];
            for (int k = 0; k < @B@_QN; k++)
                a[D + k] = aq[r][k];
            @B@_quad_solve(a, Mi, c);
            for (int k = 0; k < D; k++)
                A[r * D + k] = c[k];
            for (int k = 0; k < @B@_QN; k++)
                aq[r][k] = c[D + k];
        }
//@endif
        @B@_particle_stress(b, i, A
//@if LAW_FDOT
                            , Ad
//@endif
//@if LAW_DT
                            , (double)law_dt
//@endif
                            , 1);
//@if QUADRATIC
        @B@_quad_stress_of(b, i, quad_k, aq);
//@endif
    });
//@if CLAMP
    @B@_clamp_quiet(b);
//@endif
}

/* Pass 3, per particle: rho0 dv_i/dt = sum_j V_j (P_i L_i + P_j L_j) grad W_ij (eq. 55) plus
 * artificial viscosity (eq. 57-60) and gravity. */
static void @B@_momentum_pass(sph_body *b)
{
    enum { D = @DIM@ };
//@if MPI
    /* the halo's Q (cof F and Cs, F), entry by entry on the device (SPH_TENSOR: stride n) */
    const sph_cuda_field halo_in[] = {
        {b->Q, sizeof *b->Q, D * D, 1, (size_t)b->n},
//@if VISCOSITY
        {b->Cv, sizeof *b->Cv, D * D, 1, (size_t)b->n},
        {b->Cs, sizeof *b->Cs, 1, 1, 1},
//@endif
//@if PAIR_TERMS
        {b->F, sizeof *b->F, 9, 9, 1},
//@endif
//@if QUADRATIC
        {b->Qq, sizeof *b->Qq, @B@_QN * SPH_ROW(D), @B@_QN * SPH_ROW(D), 1},
//@endif
    };
    sph_cuda_halo(b, halo_in, sizeof halo_in / sizeof *halo_in);
//@endif
//@if VISCOSITY
    const double *v = sph_cuda_components(b->v, b->vs, b->n, D); /* v_x of all, v_y, ... */
    sph_cuda_zero(b->red + SPH_RED_VISC_RATE, 1);
    /* each thread returns its particle's share of the viscous power: one atomic per block */
    SPH_FOR_SUM(i, b->nown, b->red + SPH_RED_VISC_RATE, {
//@else
    SPH_FOR(i, b->nown, {
//@endif
        const sph_real inv_rho = (sph_real)(1.0 / b->rho0);
        const size_t n = (size_t)b->n;
        sph_real Qi[D * D]; /* Q and Cv entry by entry (SPH_TENSOR) */
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++)
                Qi[r * D + c] = b->Q[SPH_TENSOR(i, r, c, D, n)];
//@if VISCOSITY
        sph_real Ci[D * D];
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++)
                Ci[r * D + c] = b->Cv[SPH_TENSOR(i, r, c, D, n)];
        const sph_real Csi = b->Cs[i];
        double vi[D];
        for (int r = 0; r < D; r++)
            vi[r] = v[SPH_VEC(i, r, D, n)];
        sph_real pv = 0;
//@endif
        sph_real fi[D] = {0};
        for (int s = 0, slots = b->fb_count[i]; s < slots; s++) {
            sph_real w[D], g, l;
            int k;
            const int j = @B@_pair(b, i, s, &k, w, &g, &l);
            sph_real Qj[D * D], f[D];
            for (int r = 0; r < D; r++)
                for (int c = 0; c < D; c++)
                    Qj[r * D + c] = b->Q[SPH_TENSOR(j, r, c, D, n)];
            @B@_momentum_term_@RS@(Qi, Qj, w, inv_rho, f);
//@if VISCOSITY
            sph_real Cj[D * D], dv[D];
            for (int r = 0; r < D; r++) {
                for (int c = 0; c < D; c++)
                    Cj[r * D + c] = b->Cv[SPH_TENSOR(j, r, c, D, n)];
                dv[r] = (sph_real)(vi[r] - v[SPH_VEC(j, r, D, n)]);
            }
            pv += @B@_viscosity_term_@RS@(Ci, Cj, Csi + b->Cs[j], dv, w, g, f);
//@endif
//@if PAIR_TERMS
            @B@_pair_terms(b, i, j, k < 0 ? ~k : k, f); /* also with SPH_CUDA_RECOMPUTE */
//@endif
//@if QUADRATIC
            @B@_quad_pair_force(b->Qq + (size_t)i * @B@_QN * SPH_ROW(D),
                                b->Qq + (size_t)j * @B@_QN * SPH_ROW(D),
                                b->qtab + (size_t)(k < 0 ? ~k : k) * @B@_QR, inv_rho, f);
//@endif
            for (int r = 0; r < D; r++)
                fi[r] += f[r];
        }
        const double g[3] = {@G0@, @G1@, @G2@};
        for (int r = 0; r < D; r++)
            b->a[i * D + r] = g[r] + fi[r];
//@if VHEAT
        b->vq[i] = -0.5 * (double)pv; /* its half of its pairs' heat, per unit mass */
//@endif
//@if VISCOSITY
        return -0.5 * b->mass * (double)pv; /* each pair twice */
//@endif
    });
//@if CLAMP
    @B@_clamp_reactions(b);
//@endif
}

static void @B@_forces(sph_body *b
//@if LAW_DT
                       , sph_time law_dt
//@endif
                       )
{
    @B@_stress_pass(b
//@if LAW_DT
                    , law_dt
//@endif
                    );
    @B@_momentum_pass(b);
}

/* ---- body @B@: time integration on the device ----------------------------------------- */
SPH_FN double @B@_free_acc(const sph_body *b, int i, int k)
{
//@if VELOCITY_BCS
    if (b->fix[i] >> k & 1)
        return 0;
//@endif
    return b->a[i * @DIM@ + k];
}

//@if SYMPLECTIC
/* Symplectic predictor (Alg. 2, step 1), as templates/body_update.c. */
static void @B@_predict(sph_body *b, sph_time dt)
{
    enum { D = @DIM@ };
    SPH_FOR(i, b->nown, {
        for (int k = 0; k < D; k++) {
            b->work[i * D + k] = b->v[i * D + k];
            b->u[i * D + k] += 0.5 * dt * b->v[i * D + k];
            b->v[i * D + k] += 0.5 * dt * @B@_free_acc(b, i, k);
        }
//@if FRACTURE
        b->sd_n[i] = b->sd[i]; /* the phase field the same way */
        @B@_phase_move(&b->s[i], &b->sd[i], 0.5 * dt);
        b->sd[i] = @B@_phase_rate(b->sd[i], b->sdd[i], b->H[i], 0.5 * dt);
//@endif
    });
}
//@endif

/* The update that ends a step (Alg. 1 step 4 or the corrector of Alg. 2), with the max
 * |v|^2 and |a|^2 of eq. 65-66 over free components, reduced on the device. */
static void @B@_update(sph_body *b, sph_time dt)
{
    enum { D = @DIM@ };
    sph_cuda_zero(b->red + SPH_RED_VMAX2, 3);
    SPH_FOR_MAX3(i, b->nown, b->red + SPH_RED_VMAX2, {
//@if SYMPLECTIC
        const double *vn = b->work, du = 0.5 * dt;
//@else
        const double *vn = b->v, du = dt;
//@endif
        double v2 = 0, a2 = 0;
//@if FRACTURE
//@if SYMPLECTIC
        const double sdn = b->sd_n[i];
//@else
        const double sdn = b->sd[i];
//@endif
        b->sd[i] = @B@_phase_rate(sdn, b->sdd[i], b->H[i], dt);
        @B@_phase_move(&b->s[i], &b->sd[i], du);
//@endif
        for (int k = 0; k < D; k++) {
            const double ak = @B@_free_acc(b, i, k);
            b->v[i * D + k] = vn[i * D + k] + dt * ak;
            b->u[i * D + k] += du * b->v[i * D + k];
            v2 += b->v[i * D + k] * b->v[i * D + k];
            a2 += ak * ak;
        }
//@if VHEAT
        /* the artificial viscosity's heat of the step into the law's `viscousheat` state */
        b->state[(size_t)i * @NSTATE@ + @VHEAT_SLOT@] += b->rho0 * dt * b->vq[i];
//@endif
//@if CRUSH
        /* the compression bound (runtime/run/sim.c): 1 / lambda^2, infinite at lambda = 0 */
        return sph_max3{v2, a2, 1.0 / sph_bound_stretch2(b->lam2[i])};
//@else
        return sph_max3{v2, a2, 0.0};
//@endif
    });
    @B@_step_sums(b, dt); /* (body_sums.c) */
}

/* ---- body @B@: the stability monitor's sums on the device -------------------------------
 * The checks the monitor makes at every particle (runtime/run/monitor.c: a non-finite u, v or a,
 * det F <= 0, a speed above 10 c0), the body's strain + kinetic energy and its smallest
 * principal stretch, reduced on the device: a periodic check then copies a few numbers
 * instead of the state (sph_cuda_monitor_sums). */
static void @B@_monitor(sph_body *b)
{
    enum { D = @DIM@ };
    sph_cuda_zero(b->red + SPH_RED_BAD, 4);
    SPH_FOR_MAX3(i, b->nown, b->red + SPH_RED_BAD, {
        double v2 = 0, bad = 0;
        for (int k = 0; k < D; k++) {
            const double u = b->u[i * D + k], v = b->v[i * D + k], a = b->a[i * D + k];
            if (!isfinite(u) || !isfinite(v) || !isfinite(a))
                bad = 1;
            v2 += v * v;
        }
        const double *F = b->F + 9 * (size_t)i;
        if (!(sph_det3(F) > 0) || v2 > 100.0 * b->c0 * b->c0)
            bad = 1;
//@if CRUSH
        const double l2 = b->lam2[i]; /* the stress pass's, of the same F */
//@else
        const double l2 = sph_stretch2_min(F, D);
//@endif
        return sph_max3{bad, l2 < 1 ? 1 - l2 : 0.0, 0.0}; /* l2 <= 1: 1 - l2 >= 0 */
    });
    SPH_FOR_SUM(i, b->nown, b->red + SPH_RED_ENERGY, {
        double v2 = 0;
        for (int k = 0; k < D; k++)
            v2 += b->v[i * D + k] * b->v[i * D + k];
        return b->vol * b->psi[i] + 0.5 * b->mass * v2; /* as sph_body_energies */
    });
}
