//@if VERLET
/* ---- body @B@: Verlet update (Alg. 1, step 4) ----------------------------------------
 * v_{n+1} = v_n + dt a_n,  u_{n+1} = u_n + dt v_{n+1}.  Components with a prescribed
 * velocity keep it.  Also reduces max |v|^2 and |a|^2 over free components for eq. 65-66. */
static void @B@_update(sph_body *b, double dt)
{
    enum { D = @DIM@ };
    const int n = b->n;
    double *restrict u = b->u, *restrict v = b->v;
    const double *restrict a = b->a;
//@if VELOCITY_BCS
    const uint8_t *restrict fix = b->fix;
//@endif
    double vmax2 = 0, amax2 = 0;
#pragma omp parallel for schedule(static) reduction(max : vmax2, amax2)
    for (int i = 0; i < n; i++) {
        double v2 = 0, a2 = 0;
        for (int k = 0; k < D; k++) {
            double ak = a[i * D + k];
//@if VELOCITY_BCS
            if (fix[i] >> k & 1)
                ak = 0;
//@endif
            v[i * D + k] += dt * ak;
            u[i * D + k] += dt * v[i * D + k];
            v2 += v[i * D + k] * v[i * D + k];
            a2 += ak * ak;
        }
        vmax2 = v2 > vmax2 ? v2 : vmax2;
        amax2 = a2 > amax2 ? a2 : amax2;
    }
    b->vmax2 = vmax2;
    b->amax2 = amax2;
}
//@endif
//@if SYMPLECTIC
/* ---- body @B@: symplectic update (Alg. 2) ---------------------------------------------
 * Predictor: v_{n+1/2} = v_n + dt/2 a_{n-1/2}, u_{n+1/2} = u_n + dt/2 v_n (v_n kept in work).
 * Corrector: v_{n+1} = v_n + dt a_{n+1/2},  u_{n+1} = u_{n+1/2} + dt/2 v_{n+1}. */
static void @B@_predict(sph_body *b, double dt)
{
    enum { D = @DIM@ };
    double *restrict u = b->u, *restrict v = b->v, *restrict vn = b->work;
    const double *restrict a = b->a;
//@if VELOCITY_BCS
    const uint8_t *restrict fix = b->fix;
//@endif
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->n; i++)
        for (int k = 0; k < D; k++) {
            double ak = a[i * D + k];
//@if VELOCITY_BCS
            if (fix[i] >> k & 1)
                ak = 0;
//@endif
            vn[i * D + k] = v[i * D + k];
            u[i * D + k] += 0.5 * dt * v[i * D + k];
            v[i * D + k] += 0.5 * dt * ak;
        }
}

static void @B@_update(sph_body *b, double dt)
{
    enum { D = @DIM@ };
    const int n = b->n;
    double *restrict u = b->u, *restrict v = b->v;
    const double *restrict a = b->a, *restrict vn = b->work;
//@if VELOCITY_BCS
    const uint8_t *restrict fix = b->fix;
//@endif
    double vmax2 = 0, amax2 = 0;
#pragma omp parallel for schedule(static) reduction(max : vmax2, amax2)
    for (int i = 0; i < n; i++) {
        double v2 = 0, a2 = 0;
        for (int k = 0; k < D; k++) {
            double ak = a[i * D + k];
//@if VELOCITY_BCS
            if (fix[i] >> k & 1)
                ak = 0;
//@endif
            v[i * D + k] = vn[i * D + k] + dt * ak;
            u[i * D + k] += 0.5 * dt * v[i * D + k];
            v2 += v[i * D + k] * v[i * D + k];
            a2 += ak * ak;
        }
        vmax2 = v2 > vmax2 ? v2 : vmax2;
        amax2 = a2 > amax2 ? a2 : amax2;
    }
    b->vmax2 = vmax2;
    b->amax2 = amax2;
}
//@endif
