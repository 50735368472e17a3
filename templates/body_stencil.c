//@if STENCIL
/* ---- body @B@: the pair passes on the lattice stencil's runs ------------------------------
 * Particles of a run (runtime/pairs/stencil.c; 2D bodies) have their neighbours at i + o and
 * i - o for the stencil's offsets o, at the same table entries: a pair sum over them is a
 * sum over the offsets, and for one offset the same arithmetic on consecutive particles,
 * the table entry a constant.  The gradient pass leaves their A_i (and Laplacian) to the
 * stress pass, which takes them from the stencil (@B@_stencil_gradient); the momentum pass
 * does their half lists four offsets at a time (@B@_stencil_momentum).  The sums are the
 * lists' sums in another order (the program's --no-stencil keeps the lists' order;
 * tests/physics/run_stencil.cmake compares the two).  Four particles a step, in vectors of
 * eight doubles, which the particles' x, y pairs fill as they lie in memory (the compiler
 * vectorises such loops only with gathers, and no faster than the lists); in single
 * precision one particle at a time.  A step of crack branching took 0.62 of its time with
 * the lists, the flyer plates' 0.75, the beam's 0.61 (docs/architecture.md). */

/* A_i of particle i of a run: the pair (i, i + o) adds (u_{i+o} - u_i) (x) w to A_i and the
 * pair (i - o, i) adds (u_i - u_{i-o}) (x) w, so A_i is the sum over the offsets of
 * (u_{i+o} - u_{i-o}) (x) w.
//@if FRACTURE
 * And the Laplacian of eq. 62 alike: the sum of ltab (2 s_i - s_{i+o} - s_{i-o}).
//@endif
//@if LAW_FDOT
 * And the velocity's gradient Ad alike from v (the law reads a rate).
//@endif
 * Entry by entry: with the pair helpers of body_pairs.c here, GCC 12 built the table entry's
 * vector of the four-particle loop below (@B@_stencil_gradient_run, which this ends) on the
 * stack and loaded it back whole every offset, and the flyer plates' stress pass took 1.8
 * times as long (so it did with that vector made by a shuffle of one two-double load).
 */
static void @B@_stencil_gradient_one(sph_body *b, int i)
{
    enum { D = @DIM@, R = SPH_ROW(D) };
    const double *restrict u = b->u;
    sph_real a[D * D] = {0};
//@if FRACTURE
    const double *restrict sf = b->s;
    double lapi = 0;
//@endif
//@if LAW_FDOT
    const double *restrict v = b->v;
    sph_real ad[D * D] = {0};
//@endif
    for (int q = 0; q < b->st_m; q++) {
        const int jp = i + b->st_o[q], jm = i - b->st_o[q], k = b->st_k[q];
        const sph_real *w = b->wtab + (size_t)k * R;
        for (int r = 0; r < D; r++) {
            const sph_real d = (sph_real)(u[(size_t)jp * D + r] - u[(size_t)jm * D + r]);
            for (int c = 0; c < D; c++)
                a[r * D + c] += d * w[c];
//@if LAW_FDOT
            const sph_real dv = (sph_real)(v[(size_t)jp * D + r] - v[(size_t)jm * D + r]);
            for (int c = 0; c < D; c++)
                ad[r * D + c] += dv * w[c];
//@endif
        }
//@if FRACTURE
        lapi += b->ltab[k] * (2 * sf[i] - sf[jp] - sf[jm]);
//@endif
    }
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++) {
            b->A[(size_t)i * D * R + r * R + c] = a[r * D + c];
//@if LAW_FDOT
            b->Ad[(size_t)i * D * R + r * R + c] = ad[r * D + c];
//@endif
        }
//@if FRACTURE
    b->lap[i] = lapi;
//@endif
}

#ifndef SPH_SINGLE
/* (@B@_v8, eight doubles: templates/physics/pairs.c) */
typedef double @B@_v4 __attribute__((vector_size(32), aligned(8), may_alias));
#endif

/* Particles a .. e - 1 of a run: @B@_stencil_gradient_one's sums, four particles at a time
 * where vectors are (the rest one by one).  The difference u_{i+o} - u_{i-o} of four
 * particles is one vector (x, y, x, y, ...); A_i's entries (r, c), row by row, are its
 * x and y each twice, times (w0, w1) twice. */
static void @B@_stencil_gradient_run(sph_body *b, int a, int e)
{
    int i = a;
#ifndef SPH_SINGLE
    typedef @B@_v8 v8;
    const double *restrict u = b->u;
    const int *restrict so = b->st_o, *restrict sk = b->st_k;
//@if FRACTURE
    typedef @B@_v4 v4;
    const double *restrict sf = b->s;
//@endif
//@if LAW_FDOT
    const double *restrict v = b->v;
//@endif
    for (; i + 4 <= e; i += 4) {
        v8 a01 = {0}, a23 = {0}; /* A of particles i, i + 1 and of i + 2, i + 3 */
//@if LAW_FDOT
        v8 ad01 = {0}, ad23 = {0}; /* and their Ad */
//@endif
//@if FRACTURE
        v4 lap = {0};
        const v4 s2 = 2 * *(const v4 *)(sf + i);
//@endif
        for (int q = 0; q < b->st_m; q++) {
            const int o = so[q], k = sk[q];
            const v8 d = *(const v8 *)(u + 2 * (i + o)) - *(const v8 *)(u + 2 * (i - o));
            const double w0 = b->wtab[2 * k], w1 = b->wtab[2 * k + 1];
            const v8 w = {w0, w1, w0, w1, w0, w1, w0, w1};
            a01 += __builtin_shufflevector(d, d, 0, 0, 1, 1, 2, 2, 3, 3) * w;
            a23 += __builtin_shufflevector(d, d, 4, 4, 5, 5, 6, 6, 7, 7) * w;
//@if LAW_FDOT
            const v8 dv = *(const v8 *)(v + 2 * (i + o)) - *(const v8 *)(v + 2 * (i - o));
            ad01 += __builtin_shufflevector(dv, dv, 0, 0, 1, 1, 2, 2, 3, 3) * w;
            ad23 += __builtin_shufflevector(dv, dv, 4, 4, 5, 5, 6, 6, 7, 7) * w;
//@endif
//@if FRACTURE
            lap += b->ltab[k] * (s2 - *(const v4 *)(sf + i + o) - *(const v4 *)(sf + i - o));
//@endif
        }
        *(v8 *)(b->A + 4 * (size_t)i) = a01;
        *(v8 *)(b->A + 4 * (size_t)i + 8) = a23;
//@if LAW_FDOT
        *(v8 *)(b->Ad + 4 * (size_t)i) = ad01;
        *(v8 *)(b->Ad + 4 * (size_t)i + 8) = ad23;
//@endif
//@if FRACTURE
        *(v4 *)(b->lap + i) = lap;
//@endif
    }
#endif
    for (; i < e; i++)
        @B@_stencil_gradient_one(b, i);
}

/* The stress pass's block i0 .. i1 - 1: A_i and the Laplacian of its run particles. */
static void @B@_stencil_gradient(sph_body *b, int i0, int i1)
{
    for (int r = sph_run_after(b, i0); r < b->nruns && b->st_run[2 * r] < i1; r++) {
        const int a = b->st_run[2 * r] > i0 ? b->st_run[2 * r] : i0;
        const int e = b->st_run[2 * r + 1] < i1 ? b->st_run[2 * r + 1] : i1;
        @B@_stencil_gradient_run(b, a, e);
    }
}

//@if STENCIL_MOMENTUM
/* The momentum pass (eq. 55, 57-60; templates/physics/pairs.c has the physics) on
 * the half lists of run particles a .. a + 4 t - 1 (at most @B@_STENCIL particles; the rest
 * of a run goes by the lists), four particles a step: Q_i + Q_j of two particles fill a
 * vector (column 0, column 1, column 0, column 1), times (w0, w0, w1, w1, ...) the columns'
 * shares, whose sums two shuffles pair up into the forces' (x, y, x, y, ...), the layout of
 * v and the accelerations.
 *
 * The offsets go in groups of four (the last few one by one): a step loads the four
 * particles' own values once for the group's four offsets and adds the four forces to
 * their accelerations in registers; after the group each offset's forces are subtracted
 * from their j = i + o, as the lists do.  Offset by offset, each step loaded the own values
 * again and read and wrote the accelerations: the flyer plates' momentum pass took 1.1 times
 * as long.  The order of the sums is the groups' (the same on any number of threads). */
enum { @B@_STENCIL = 64, @B@_GROUP = 4 };

#ifndef SPH_SINGLE
/* Four run particles' own values, for every offset of a group. */
typedef struct {
    @B@_v8 q0, q1; /* Q of particles 0, 1 and of 2, 3 (columns side by side) */
//@if VISCOSITY
    @B@_v8 c0, c1, v; /* cof F alike; v (x, y of each) */
    @B@_v4 cs;        /* Cs */
//@endif
} @B@_stencil_own;

/* The four pairs (i, j), ..., (i + 3, j + 3) of one offset: their forces on i into *force
 * (x and y of each side by side; a pointer: a returned vector would change the ABI where
 * vectors of eight are not), and their viscous power added to *pv. */
SPH_FLAT void @B@_stencil_pairs(const sph_body *b, const @B@_stencil_own *own, int j,
                                @B@_v8 w, double g, double inv_rho, @B@_v8 *pv,
                                @B@_v8 *force)
{
    typedef @B@_v8 v8;
    const double *restrict Q = b->Q;
    const v8 q0 = (own->q0 + *(const v8 *)(Q + 4 * j)) * w;
    const v8 q1 = (own->q1 + *(const v8 *)(Q + 4 * j + 8)) * w;
    v8 f = (__builtin_shufflevector(q0, q1, 0, 1, 4, 5, 8, 9, 12, 13) +
            __builtin_shufflevector(q0, q1, 2, 3, 6, 7, 10, 11, 14, 15)) *
           inv_rho;
//@if VISCOSITY
    typedef @B@_v4 v4;
    const double *restrict Cv = b->Cv, *restrict Cs = b->Cs, *restrict v = b->v;
    const v8 c0 = (own->c0 + *(const v8 *)(Cv + 4 * j)) * w;
    const v8 c1 = (own->c1 + *(const v8 *)(Cv + 4 * j + 8)) * w;
    const v8 fv = __builtin_shufflevector(c0, c1, 0, 1, 4, 5, 8, 9, 12, 13) +
                  __builtin_shufflevector(c0, c1, 2, 3, 6, 7, 10, 11, 14, 15);
    const v8 p = (own->v - *(const v8 *)(v + 2 * j)) * fv;
    const v8 vw = p + __builtin_shufflevector(p, p, 1, 0, 3, 2, 5, 4, 7, 6);
    const v4 cs4 = own->cs + *(const v4 *)(Cs + j);
    const v8 cs = __builtin_shufflevector(cs4, cs4, 0, 0, 1, 1, 2, 2, 3, 3);
    /* half the viscous pressure, each pair's in its x and y lanes (eq. 58-60,
     * templates/physics/pairs.c) */
    const v8 hpi = @B@_viscous_pressure_v8(g, cs, vw);
    f -= hpi * fv;
    *pv -= hpi * vw;
//@else
    (void)g, (void)pv;
//@endif
    *force = f;
}

/* Offsets q .. q + n - 1 (n a constant at each call: its loops unroll) of the run
 * particles a .. a + t - 1. */
SPH_FLAT void @B@_stencil_group(sph_body *b, int a, int t, int q, const int n,
                                double inv_rho, @B@_v8 *pv)
{
    typedef @B@_v8 v8;
    double *restrict acc = b->a;
    double f_run[@B@_GROUP][2 * @B@_STENCIL]; /* each offset's forces on i, x and y */
    int o[@B@_GROUP];
    v8 w[@B@_GROUP];
    double g[@B@_GROUP] = {0};
    for (int u = 0; u < n; u++) {
        const int k = b->st_k[q + u];
        const double w0 = b->wtab[2 * k], w1 = b->wtab[2 * k + 1];
        o[u] = b->st_o[q + u];
        w[u] = (v8){w0, w0, w1, w1, w0, w0, w1, w1};
//@if VISCOSITY
        g[u] = b->gtab[k];
//@endif
    }
    for (int i = a; i < a + t; i += 4) {
        @B@_stencil_own own;
        own.q0 = *(const v8 *)(b->Q + 4 * i), own.q1 = *(const v8 *)(b->Q + 4 * i + 8);
//@if VISCOSITY
        own.c0 = *(const v8 *)(b->Cv + 4 * i), own.c1 = *(const v8 *)(b->Cv + 4 * i + 8);
        own.v = *(const v8 *)(b->v + 2 * i);
        own.cs = *(const @B@_v4 *)(b->Cs + i);
//@endif
        v8 ai = *(const v8 *)(acc + 2 * i);
        for (int u = 0; u < n; u++) {
            v8 f;
            @B@_stencil_pairs(b, &own, i + o[u], w[u], g[u], inv_rho, pv, &f);
            ai += f;
            *(v8 *)(f_run[u] + 2 * (i - a)) = f;
        }
        *(v8 *)(acc + 2 * i) = ai;
    }
    for (int u = 0; u < n; u++) {
        double *restrict acc_j = acc + 2 * (a + o[u]);
        for (int c = 0; c < 2 * t; c += 8)
            *(v8 *)(acc_j + c) -= *(const v8 *)(f_run[u] + c);
    }
}
#endif

/* Returns the number of particles done (none in single precision) and adds the pairs'
 * f_visc . (v_i - v_j) to *power. */
static int @B@_stencil_momentum(sph_body *b, int a, int e, double *power)
{
#ifdef SPH_SINGLE
    (void)b, (void)a, (void)e, (void)power;
    return 0;
#else
    const int t = (e - a) / 4 * 4 < @B@_STENCIL ? (e - a) / 4 * 4 : @B@_STENCIL;
    /* (divided once here: in the loop the compiler divided every four pairs, unable to tell
     * that the stores to the accelerations leave b->rho0 as it was) */
    const double inv_rho = 1.0 / b->rho0;
    @B@_v8 pv = {0}; /* (each pair's twice: x and y lanes) */
    int q = 0;
    for (; q + @B@_GROUP <= b->st_m; q += @B@_GROUP)
        @B@_stencil_group(b, a, t, q, @B@_GROUP, inv_rho, &pv);
    for (; q < b->st_m; q++)
        @B@_stencil_group(b, a, t, q, 1, inv_rho, &pv);
//@if VISCOSITY
    double sum = 0;
    for (int c = 0; c < 8; c++)
        sum += pv[c];
    *power += 0.5 * sum;
//@else
    (void)power, (void)pv;
//@endif
    return t;
#endif
}

//@endif
//@endif
