/* ---- body @B@: time integration ------------------------------------------------------
 * The acceleration a component is integrated with: zero where the velocity is prescribed
 * (the prescribed value is held through the step; a keeps the full force for measurement). */
static inline double @B@_free_acc(const sph_body *b, int i, int k)
{
//@if VELOCITY_BCS
    if (b->fix[i] >> k & 1)
        return 0;
//@endif
    return b->a[i * @DIM@ + k];
}

//@if SYMPLECTIC
/* Symplectic predictor (Alg. 2, step 1): v_{n+1/2} = v_n + dt/2 a_{n-1/2},
 * u_{n+1/2} = u_n + dt/2 v_n; v_n is kept in work for the corrector. */
static void @B@_predict(sph_body *b, double dt)
{
    enum { D = @DIM@ };
    double *restrict u = b->u, *restrict v = b->v, *restrict vn = b->work;
//@if FRACTURE
    double *restrict s = b->s, *restrict sd = b->sd, *restrict sdn = b->sd_n;
    const double *restrict sdd = b->sdd, *restrict H = b->H;
//@endif
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        for (int k = 0; k < D; k++) {
            vn[i * D + k] = v[i * D + k];
            u[i * D + k] += 0.5 * dt * v[i * D + k];
            v[i * D + k] += 0.5 * dt * @B@_free_acc(b, i, k);
        }
//@if FRACTURE
        sdn[i] = sd[i]; /* the phase field the same way */
        @B@_phase_move(&s[i], &sd[i], 0.5 * dt);
        sd[i] = @B@_phase_rate(sd[i], sdd[i], H[i], 0.5 * dt);
//@endif
    }
}
//@endif

/* The update that ends a step, with the max |v|^2 and |a|^2 of eq. 65-66 over free
 * components:
//@if SYMPLECTIC
 *   symplectic corrector (Alg. 2): v_{n+1} = v_n + dt a_{n+1/2},  u_{n+1} = u_{n+1/2} + dt/2 v_{n+1}
//@else
 *   Verlet (Alg. 1, step 4):      v_{n+1} = v_n + dt a_n,        u_{n+1} = u_n + dt v_{n+1}
//@endif
 */
static void @B@_update(sph_body *b, double dt)
{
    enum { D = @DIM@ };
    double *restrict u = b->u, *restrict v = b->v;
//@if SYMPLECTIC
    const double *restrict vn = b->work, du = 0.5 * dt;
//@else
    const double du = dt;
//@endif
    /* max |v|^2 and |a|^2; and their sums, which are not a number exactly where some |v|^2
     * or |a|^2 is not: the maximum of such a state is infinite, which stops the run */
    double vmax2 = 0, amax2 = 0, vsum2 = 0, asum2 = 0;
//@if FRACTURE
    /* the phase field with the same scheme (Alg. 1-2): s' from s'', then s */
    double *restrict s = b->s, *restrict sd = b->sd;
    const double *restrict sdd = b->sdd, *restrict H = b->H;
//@if SYMPLECTIC
    const double *restrict sdn = b->sd_n;
//@endif
//@endif
//@if CRUSH
    const double *restrict lam2 = b->lam2;
    double lam2min = 1; /* the smallest principal stretch squared (stress pass) */
//@endif
//@if VHEAT
    /* the artificial viscosity's heat of the step into the law's `viscousheat` state [J/m^3]:
     * its rate per unit mass (the momentum pass's) times rho0 dt */
    double *restrict heat = b->state + @VHEAT_SLOT@;
    const double *restrict vq = b->vq;
    const double rho0_dt = b->rho0 * dt;
//@endif
    /* simd: the particles are independent, and the loop has no branches (selects), so that
     * the compiler does several in one vector instruction (crack branching's update took
     * about half its time so) */
//@if CRUSH
#pragma omp parallel for@OMP_SIMD@ schedule(static) reduction(max : vmax2, amax2) \
    reduction(+ : vsum2, asum2) reduction(min : lam2min)
//@else
#pragma omp parallel for@OMP_SIMD@ schedule(static) reduction(max : vmax2, amax2) \
    reduction(+ : vsum2, asum2)
//@endif
    for (int i = 0; i < b->nown; i++) {
        double v2 = 0, a2 = 0;
//@if CRUSH
        const double l2 = sph_bound_stretch2(lam2[i]);
        lam2min = l2 < lam2min ? l2 : lam2min;
//@endif
//@if FRACTURE
//@if SYMPLECTIC
        double sdi = @B@_phase_rate(sdn[i], sdd[i], H[i], dt), si = s[i];
//@else
        double sdi = @B@_phase_rate(sd[i], sdd[i], H[i], dt), si = s[i];
//@endif
        @B@_phase_move(&si, &sdi, du);
        s[i] = si, sd[i] = sdi;
//@endif
        for (int k = 0; k < D; k++) {
            const double ak = @B@_free_acc(b, i, k);
//@if SYMPLECTIC
            const double vk = vn[i * D + k] + dt * ak;
//@else
            const double vk = v[i * D + k] + dt * ak;
//@endif
            v[i * D + k] = vk;
            u[i * D + k] += du * vk;
            v2 += vk * vk;
            a2 += ak * ak;
        }
//@if VHEAT
        heat[(size_t)i * @NSTATE@] += rho0_dt * vq[i];
//@endif
        vmax2 = v2 > vmax2 ? v2 : vmax2;
        amax2 = a2 > amax2 ? a2 : amax2;
        vsum2 += v2;
        asum2 += a2;
    }
    b->vmax2 = vsum2 == vsum2 ? vmax2 : INFINITY;
    b->amax2 = asum2 == asum2 ? amax2 : INFINITY;
//@if CRUSH
    b->lam2min = lam2min;
//@endif
    @B@_step_sums(b, dt); /* (body_sums.c) */
}
