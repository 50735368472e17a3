/* ---- body @B@: internal forces ------------------------------------------------------
 * Pass 1, over pairs (each once): A_i = sum_j V_j (u_j - u_i) (x) grad W_ij.  The pair adds
 * the same tensor to A_j (w_ji = -w_ij), so half the pairs do all the work.  Stripes of one
 * colour never share a particle (see sph_body), so they run in parallel.  Statically: each
 * thread takes a run of consecutive stripes of each colour, about the particles the static
 * particle loops (stress, update) give it, so what one pass writes is in the cache of the
 * thread that reads it next (docs/architecture.md: with dynamic scheduling a step of crack
 * branching took 1.8 times as long on two threads). */

//@if MPI
/* On many processes, after the pass over the half lists: each own particle's pairs with the
 * halo, i's share only (the other process computes j's); nothing where there is no halo. */
static void @B@_gradient_halo_pairs(sph_body *b)
{
    enum { D = @DIM@, R = SPH_ROW(D) };
    const int *restrict xs = b->xb_start, *restrict xb = b->xb, *restrict xk = b->xb_k;
    if (!xs)
        return;
    const @B@_vec *restrict wtab = (const @B@_vec *)b->wtab;
    const double *restrict u = b->u;
    sph_real *restrict A = b->A;
//@if LAW_FDOT
    const double *restrict v = b->v;
    sph_real *restrict Ad = b->Ad;
//@endif
//@if FRACTURE
    const double *restrict sf = b->s;
    const sph_real *restrict ltab = b->ltab;
    double *restrict lap = b->lap;
//@endif
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        if (xs[i] == xs[i + 1])
            continue;
        @B@_tensor Ai = {0}, t;
        double ui[D]; /* (read once for all of i's pairs) */
        for (int r = 0; r < D; r++)
            ui[r] = u[(size_t)i * D + r];
//@if LAW_FDOT
        @B@_tensor Adi = {0}; /* the velocity's gradient the same way */
        double vi[D];
        for (int r = 0; r < D; r++)
            vi[r] = v[(size_t)i * D + r];
//@endif
//@if QUADRATIC
        @B@_qvec aqi[D] = {{0}}, qt[D]; /* the quadratic fit's sums, i's share */
//@endif
//@if FRACTURE
        double lapi = 0;
//@endif
        for (int p = xs[i]; p < xs[i + 1]; p++) {
            const int j = xb[p];
//@if QUADRATIC
            @B@_quad_pair(b, xk[p], u + (size_t)j * D, ui, qt);
            for (int r = 0; r < D; r++)
                aqi[r] += qt[r];
//@endif
//@if FRACTURE
            lapi += ltab[xk[p]] * (sf[i] - sf[j]);
//@endif
            @B@_pair_tensor(u + (size_t)j * D, ui, wtab[xk[p]], &t);
            @B@_tensor_add(&Ai, &t);
//@if LAW_FDOT
            @B@_pair_tensor(v + (size_t)j * D, vi, wtab[xk[p]], &t);
            @B@_tensor_add(&Adi, &t);
//@endif
        }
        @B@_tensor_add_to(A + (size_t)i * D * R, &Ai);
//@if LAW_FDOT
        @B@_tensor_add_to(Ad + (size_t)i * D * R, &Adi);
//@endif
//@if QUADRATIC
        @B@_quad_add_to(b, i, aqi);
//@endif
//@if FRACTURE
        lap[i] += lapi;
//@endif
    }
}

//@endif
/* Particle i's pairs p0 .. p1 - 1 (neighbour hb[p], entry hk[p]), each added to both
 * particles: (u_j - u_i) (x) w_ij to A_i and to A_j (w_ji = -w_ij). */
static inline void @B@_gradient_pairs(sph_body *b, int i, int p0, int p1,
                                      const int *restrict hb, const int *restrict hk)
{
    enum { D = @DIM@, R = SPH_ROW(D) };
    const @B@_vec *restrict wtab = (const @B@_vec *)b->wtab;
    const double *restrict u = b->u;
    sph_real *restrict A = b->A; /* A_i from A + i D R, row by row; zero on entry: the stress
                                  * pass clears what it read */
//@if FRACTURE
    /* the Laplacian of the phase field (eq. 62), a symmetric pair sum, rides along */
    const double *restrict sf = b->s;
    const sph_real *restrict ltab = b->ltab;
    double *restrict lap = b->lap; /* zero on entry, like A */
//@endif
    @B@_tensor Ai = {0}, t;
    double ui[D]; /* (read once for all of i's pairs) */
    for (int r = 0; r < D; r++)
        ui[r] = u[(size_t)i * D + r];
//@if LAW_FDOT
    /* the velocity's gradient, for a law that reads the rate of F: the same pair sum of v */
    const double *restrict v = b->v;
    sph_real *restrict Ad = b->Ad; /* zero on entry, like A */
    @B@_tensor Adi = {0};
    double vi[D];
    for (int r = 0; r < D; r++)
        vi[r] = v[(size_t)i * D + r];
//@endif
//@if QUADRATIC
    @B@_qvec aqi[D] = {{0}};
//@endif
//@if FRACTURE
    double lapi = 0;
//@endif
    for (int p = p0; p < p1; p++) {
        const int j = hb[p];
//@if FRACTURE
        const double lij = ltab[hk[p]] * (sf[i] - sf[j]);
        lapi += lij;
        lap[j] -= lij;
//@endif
        @B@_pair_tensor(u + (size_t)j * D, ui, wtab[hk[p]], &t);
        @B@_tensor_add(&Ai, &t);
        @B@_tensor_add_to(A + (size_t)j * D * R, &t);
//@if LAW_FDOT
        @B@_pair_tensor(v + (size_t)j * D, vi, wtab[hk[p]], &t);
        @B@_tensor_add(&Adi, &t);
        @B@_tensor_add_to(Ad + (size_t)j * D * R, &t);
//@endif
//@if QUADRATIC
        { /* the quadratic fit's sums (body_quadratic.c) */
            @B@_qvec qt[D], *aqj = (@B@_qvec *)(b->Aq + (size_t)j * D * @B@_QR);
            @B@_quad_pair(b, hk[p], u + (size_t)j * D, ui, qt);
            for (int r = 0; r < D; r++)
                aqi[r] += qt[r], aqj[r] -= qt[r];
        }
//@endif
    }
    @B@_tensor_add_to(A + (size_t)i * D * R, &Ai);
//@if LAW_FDOT
    @B@_tensor_add_to(Ad + (size_t)i * D * R, &Adi);
//@endif
//@if QUADRATIC
    @B@_quad_add_to(b, i, aqi);
//@endif
//@if FRACTURE
    lap[i] += lapi;
//@endif
}

//@if OFFSET_BLOCKS
/* 3D, on a lattice: the own pairs' sums by the body's offset blocks (runtime/pairs/offset_blocks.c)
 * instead of the half lists.  Block B's particles i0 .. i0 + 7 in the lanes of vectors of
 * eight; a task of the block is one offset j - i and one table entry w, the same for the
 * lanes of its mask, so u_j - u_i is one unaligned vector load from u by component (copied
 * into b->ob_u first) less u_i, and its product with w (@B@_gradient_term_v8) nine
 * multiply-adds into A's nine entries, which stay in registers over the block's tasks and
 * are written once (a lane not in the mask adds zeros).  Each pair is summed from both of
 * its particles, the full lists, and nothing is written to j: no stripes.  Overwrites A_i
 * of own particles with the sums of their own pairs (the sums of the lists, in another
 * order).  The Taylor bar's stress pass (this in it) took 0.6 of its time with the half
 * lists, its step 0.84 (one thread).  Where the law reads a rate, the velocity's gradient
 * Ad the same way from v by component (b->ob_v), in the same tasks: the Taylor bar with a
 * law that reads one, its stress pass 0.65 of the lists' time. */
static void @B@_gradient_blocks(sph_body *b)
{
    typedef @B@_v8 dv8;
    typedef @B@_v8m lv8;
    enum { D = 3, R = SPH_ROW(D) };
    const int n = b->nown, S = b->ob_stride;
    const double *restrict u = b->u;
    double *restrict U = b->ob_u + b->ob_pad; /* u_i^r at U[r S + i] */
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++)
        for (int r = 0; r < D; r++)
            U[(size_t)r * S + i] = u[(size_t)i * D + r];
    const sph_ob_task *restrict ob = b->ob;
    const int *restrict os = b->ob_start;
    const sph_real *restrict wtab = b->wtab;
    sph_real *restrict A = b->A;
//@if LAW_FDOT
    /* the velocity's gradient the same way, from v by component (its law reads a rate) */
    const double *restrict v = b->v;
    double *restrict V = b->ob_v + b->ob_pad;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < n; i++)
        for (int r = 0; r < D; r++)
            V[(size_t)r * S + i] = v[(size_t)i * D + r];
    sph_real *restrict Ad = b->Ad;
//@endif
    const lv8 lane = {1, 2, 4, 8, 16, 32, 64, 128};
#pragma omp parallel for schedule(static)
    for (int B = 0; B < b->nob; B++) {
        const int i0 = SPH_OB_LANES * B;
        dv8 ui[D], a[D * D] = {0};
        for (int r = 0; r < D; r++)
            ui[r] = *(const dv8 *)(U + (size_t)r * S + i0);
//@if LAW_FDOT
        dv8 vi[D], ad[D * D] = {0};
        for (int r = 0; r < D; r++)
            vi[r] = *(const dv8 *)(V + (size_t)r * S + i0);
//@endif
        for (int t = os[B]; t < os[B + 1]; t++) {
            const sph_real *wk = wtab + (size_t)(ob[t].key >> 8) * R;
            const double w[D] = {wk[0], wk[1], wk[2]};
            const lv8 in = (lane & (long long)(ob[t].key & 255)) != 0;
            const double *uj = U + i0 + ob[t].off;
            dv8 d[D]; /* u_j - u_i, zero in the lanes without the pair */
            for (int r = 0; r < D; r++)
                d[r] = (dv8)((lv8)(*(const dv8 *)(uj + (size_t)r * S) - ui[r]) & in);
            @B@_gradient_term_v8(a, d, w);
//@if LAW_FDOT
            const double *vj = V + i0 + ob[t].off;
            for (int r = 0; r < D; r++)
                d[r] = (dv8)((lv8)(*(const dv8 *)(vj + (size_t)r * S) - vi[r]) & in);
            @B@_gradient_term_v8(ad, d, w);
//@endif
        }
        for (int l = 0; l < SPH_OB_LANES && i0 + l < n; l++)
            for (int r = 0; r < D; r++)
                for (int c = 0; c < D; c++) {
                    A[(size_t)(i0 + l) * D * R + r * R + c] = (sph_real)a[r * D + c][l];
//@if LAW_FDOT
                    Ad[(size_t)(i0 + l) * D * R + r * R + c] = (sph_real)ad[r * D + c][l];
//@endif
                }
    }
}

//@endif
/* The own pairs' sums by the half lists, stripe by stripe (the colours in turn). */
static void @B@_gradient_lists(sph_body *b)
{
    const int *restrict hs = b->hb_start, *restrict hb = b->hb, *restrict hk = b->hb_k;
    for (int colour = 0; colour < b->ncolours; colour++) {
#pragma omp parallel for schedule(static)
        for (int s = colour; s < b->nstripes; s += b->ncolours) {
//@if DIM3
//@else
            /* With the lattice stencil, only what its runs leave (the rest lists,
             * runtime/pairs/stencil.c): the stress pass takes the run particles' sums from
             * the stencil, and overwrites what the pairs here add to them (body_stencil.c). */
            if (b->rest) {
                for (int c = sph_rest_after(b, b->stripe[s]);
                     c < b->nrest && b->rest[c] < b->stripe[s + 1]; c++)
                    @B@_gradient_pairs(b, b->rest[c], b->rest_start[c], b->rest_start[c + 1],
                                       b->rest_j, b->rest_k);
                continue;
            }
//@endif
            for (int i = b->stripe[s]; i < b->stripe[s + 1]; i++)
                @B@_gradient_pairs(b, i, hs[i], hs[i + 1], hb, hk);
        }
    }
}

static void @B@_gradient_pass(sph_body *b)
{
//@if CLAMP
    sph_clamp_images(b); /* the clamp's images move with their particles (run/clamp.c) */
//@endif
//@if MPI
    enum { D = @DIM@ };
    /* On many processes the halo's values are on their way while the pairs of own particles
     * are summed; the pairs with the halo follow (docs/mpi.md).  What the pair passes read of
     * a neighbour: u here, and v for the viscosity and the pair terms of the momentum pass
     * (unchanged until then) and for the velocity's gradient here, the phase field for its
     * Laplacian. */
    const sph_field halo_in[] = {
        SPH_FIELD(b->u, D),
//@if PAIR_V
        SPH_FIELD(b->v, D),
//@endif
//@if FRACTURE
        SPH_FIELD(b->s, 1),
//@endif
    };
    const int nhalo_in = sizeof halo_in / sizeof *halo_in;
    b->par->post(b, halo_in, nhalo_in);
//@endif
//@if OFFSET_BLOCKS
    if (b->ob)
        @B@_gradient_blocks(b);
    else
//@endif
        @B@_gradient_lists(b);
//@if MPI
    b->par->wait(b, halo_in, nhalo_in);
    @B@_gradient_halo_pairs(b);
//@endif
//@if QUADRATIC
    @B@_quad_fit(b);
//@endif
}

//@if VISCOSITY
/* Cs_i also in the padding entry of cof F_i's first column where the columns have one (3D:
 * four entries for three), which the momentum pass loads with the column: read from b->Cs,
 * it would be one more cache line a pair, and cost the 3D pass a third of its time. */
static inline void @B@_spare_Cs(sph_body *b, int i)
{
    enum { D = @DIM@, R = SPH_ROW(D) };
    if (R > D)
        b->Cv[SPH_TENSOR(i, R - 1, 0, D, b->n)] = b->Cs[i];
}

//@endif
/* Pass 2, per particle: F, the law, P L and cof(F) (@B@_stress_of), in blocks of particles
 * the threads take in order (static: the runs of particles the pair passes' stripes give
 * them).  Within a block no particle depends on another, and where the loop over its
 * particles has no branches (the law and its helpers use selects) and only unit-stride
 * runs or short groups of values a particle, the compiler does several particles in one
 * vector instruction: crack branching's stress pass took 0.55 of its time so. */
enum { @B@_BLOCK = 32 };

/* Whether this step's stress pass stores F: where something reads it after the step (the
 * monitor, an output, a checkpoint: sph_body.want_F), or always where the body's own steps
 * read it.  Its store every step took a fifth of crack branching's stress pass. */
static inline int @B@_store_F(const sph_body *b)
{
//@if F_EVERY_STEP
    (void)b;
    return 1; /* (the hourglass term or the quadratic fit reads it every step) */
//@else
    return b->want_F;
//@endif
}

//@if STAGED
/* This body's law calls exp, log or pow, but its particles' values come in runs of 9, 11 or
 * 12 (3D tensors, the law's state), which the compiler does not vectorise in place: the
 * block's values are first copied entry by entry (entry k of its particle q at [k][q]) into
 * a stage on the stack, the loop over the block's particles reads and writes that alone,
 * and the results go back (compiler/lower/lower.c, stress_staged). */
typedef struct {
    double A[@DIM@ * @DIM@][@B@_BLOCK], L[@DIM@ * @DIM@][@B@_BLOCK], psi[@B@_BLOCK];
    double F[@DIM@ * @DIM@][@B@_BLOCK], Q[@DIM@ * @DIM@][@B@_BLOCK];
//@if VISCOSITY
    double Cv[@DIM@ * @DIM@][@B@_BLOCK], Cs[@B@_BLOCK];
//@endif
//@if FRACTURE
    double s[@B@_BLOCK], lap[@B@_BLOCK], H[@B@_BLOCK], sdd[@B@_BLOCK];
//@endif
//@if STATE
    double st[@NSTATE@][@B@_BLOCK], st_new[@NSTATE@][@B@_BLOCK];
//@endif
//@if CRUSH
    double lam2[@B@_BLOCK];
//@endif
//@if LAW_FDOT
    double Ad[@DIM@ * @DIM@][@B@_BLOCK], Fd[@DIM@ * @DIM@][@B@_BLOCK];
//@endif
//@if LAW_DT
    double dt; /* the time since the law's last evaluation */
//@endif
} @B@_stage;

/* Particle q of a stage through @B@_stress_of.  With fast (RARE), its law's fast path
 * (@B@_material_fast); returns whether a rare branch should have been taken, and then
 * the particle's results are not the law's (0 otherwise). */
SPH_FLAT int @B@_stress_lane(@B@_stage *g, int q, int fast)
{
    enum { T = @DIM@ * @DIM@ };
    double a[T], l[T], f[T], qq[T];
    for (int k = 0; k < T; k++)
        a[k] = g->A[k][q], l[k] = g->L[k][q];
//@if LAW_FDOT
    double ad[T], fd[T];
    for (int k = 0; k < T; k++)
        ad[k] = g->Ad[k][q];
//@endif
//@if VISCOSITY
    double cv[T];
//@endif
//@if STATE
    double sq[@NSTATE@], snq[@NSTATE@];
    for (int k = 0; k < @NSTATE@; k++)
        sq[k] = g->st[k][q];
//@endif
    double rare = 0;
    @B@_stress_of(a, l,
//@if FRACTURE
                  g->s[q], g->lap[q], &g->H[q], &g->sdd[q],
//@endif
//@if LAW_FDOT
                  ad, fd,
//@endif
//@if LAW_DT
                  g->dt,
//@endif
//@if STATE
                  sq, snq,
//@endif
//@if CRUSH
                  &g->lam2[q],
//@endif
                  &g->psi[q], f, qq
//@if VISCOSITY
                  , cv, &g->Cs[q]
//@endif
//@if RARE
                  , fast, &rare
//@endif
                  );
    for (int k = 0; k < T; k++) {
        g->F[k][q] = f[k], g->Q[k][q] = qq[k];
//@if LAW_FDOT
        g->Fd[k][q] = fd[k];
//@endif
//@if VISCOSITY
        g->Cv[k][q] = cv[k];
//@endif
    }
//@if STATE
    for (int k = 0; k < @NSTATE@; k++)
        g->st_new[k][q] = snq[k];
//@endif
    (void)fast;
    return rare != 0;
}

//@if RARE
/* The block's particles through the law's fast path, which leaves out its rare `if`
 * blocks (a return map's correction, @B@_material_fast).  Where one of them should have
 * taken one (a particle that yields), the whole law for the whole block, again, and for the
 * next 8 steps without the fast path first (b->rare_hint of the block's first particle
 * counts them down): the yielding part of a body.  The results are the law's either way.
 * (The whole law for the flagged particles alone is the same work: the compiler makes that
 * loop a masked vector loop over all of them.)  The flyer plates' stress pass, none of
 * their particles yielding, takes 0.77 of the whole law's time; the Taylor bar's, a third
 * of its blocks yielding, 0.96. */
static void @B@_stress_lanes(sph_body *b, @B@_stage *g, int i0, int m)
{
    if (b->rare_hint[i0] == 0 && !sph_fast_law_off) {
        int nrare = 0;
        for (int q = 0; q < m; q++)
            nrare += @B@_stress_lane(g, q, 1);
        if (nrare == 0)
            return;
        b->rare_hint[i0] = 9;
    }
    b->rare_hint[i0] -= b->rare_hint[i0] > 0;
    for (int q = 0; q < m; q++)
        @B@_stress_lane(g, q, 0);
}
//@else
static void @B@_stress_lanes(sph_body *b, @B@_stage *g, int i0, int m)
{
    (void)b, (void)i0;
    for (int q = 0; q < m; q++)
        @B@_stress_lane(g, q, 0);
}
//@endif

static void @B@_stress_block(sph_body *b, int i0, int m)
{
    enum { D = @DIM@, R = SPH_ROW(D), T = D * D };
    @B@_stage g;
//@if LAW_DT
    g.dt = b->law_dt;
//@endif
    sph_real *restrict Ab = b->A + (size_t)i0 * D * R;
    const double *restrict Lb = b->L + (size_t)i0 * T;
//@if STATE
    enum { NS = @NSTATE@ };
    double *restrict stb = b->state + (size_t)i0 * NS;
//@endif
//@if STENCIL
    @B@_stencil_gradient(b, i0, i0 + m); /* (the run particles' A and Laplacian) */
//@endif
    for (int q = 0; q < m; q++) {
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++)
                g.A[r * D + c][q] = Ab[q * D * R + r * R + c];
        for (int k = 0; k < D * R; k++)
            Ab[q * D * R + k] = 0; /* ready for the next step's gradient pass */
        for (int k = 0; k < T; k++)
            g.L[k][q] = Lb[q * T + k];
//@if LAW_FDOT
        sph_real *Adq = b->Ad + (size_t)(i0 + q) * D * R;
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++)
                g.Ad[r * D + c][q] = Adq[r * R + c];
        for (int k = 0; k < D * R; k++)
            Adq[k] = 0;
//@endif
//@if FRACTURE
        g.s[q] = b->s[i0 + q], g.lap[q] = b->lap[i0 + q], g.H[q] = b->H[i0 + q];
        b->lap[i0 + q] = 0; /* ready for the next step's gradient pass */
//@endif
//@if STATE
        for (int k = 0; k < NS; k++)
            g.st[k][q] = stb[q * NS + k];
//@endif
    }
    @B@_stress_lanes(b, &g, i0, m);
    const int store_F = @B@_store_F(b);
    double *restrict Fb = b->F + (size_t)i0 * 9;
    sph_real *restrict Qb = b->Q;
//@if VISCOSITY
    sph_real *restrict Cb = b->Cv;
//@endif
    for (int q = 0; q < m; q++) {
        const size_t i = (size_t)(i0 + q);
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++) {
                if (store_F)
                    Fb[q * 9 + sph_axis(D, r) * 3 + sph_axis(D, c)] = g.F[r * D + c][q];
//@if LAW_FDOT
                b->Fd[i * 9 + (size_t)(sph_axis(D, r) * 3 + sph_axis(D, c))] = g.Fd[r * D + c][q];
//@endif
                Qb[SPH_TENSOR(i, r, c, D, b->n)] = (sph_real)g.Q[r * D + c][q];
//@if VISCOSITY
                Cb[SPH_TENSOR(i, r, c, D, b->n)] = (sph_real)g.Cv[r * D + c][q];
//@endif
            }
        b->psi[i] = g.psi[q];
//@if VISCOSITY
        b->Cs[i] = (sph_real)g.Cs[q];
        @B@_spare_Cs(b, (int)i);
//@endif
//@if FRACTURE
        b->H[i] = g.H[q], b->sdd[i] = g.sdd[q];
//@endif
//@if CRUSH
        b->lam2[i] = g.lam2[q];
//@endif
//@if STATE
        for (int k = 0; k < NS; k++)
            stb[q * NS + k] = g.st_new[k][q];
//@endif
    }
}

static void @B@_stress_pass(sph_body *b)
{
    const int n = b->nown;
    @B@_gradient_pass(b);
#pragma omp parallel for schedule(static)
    for (int i0 = 0; i0 < n; i0 += @B@_BLOCK)
        @B@_stress_block(b, i0, n - i0 < @B@_BLOCK ? n - i0 : @B@_BLOCK);
//@if QUADRATIC
    @B@_quad_stress(b);
//@endif
//@if CLAMP
    sph_clamp_quiet(b);
//@endif
}
//@else
/* Particles i0 .. i1 - 1 of the stress pass, with F stored or not (store_F a constant at
 * each call: the loop is built twice, each vectorised). */
SPH_FLAT void @B@_stress_run(sph_body *b, int i0, int i1, int store_F)
{
    enum { D = @DIM@, R = SPH_ROW(D) };
    sph_real *restrict Ac = b->A;
SPH_IVDEP /* particle i reads and writes entry i of arrays that never overlap */
    for (int i = i0; i < i1; i++) {
        sph_real *Ai = Ac + (size_t)i * D * R;
        double A[D * D];
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++)
                A[r * D + c] = Ai[r * R + c];
        for (int k = 0; k < D * R; k++)
            Ai[k] = 0; /* ready for the next step's gradient pass */
//@if LAW_FDOT
        sph_real *Adi = b->Ad + (size_t)i * D * R; /* the velocity's, the same way */
        double Ad[D * D];
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++)
                Ad[r * D + c] = Adi[r * R + c];
        for (int k = 0; k < D * R; k++)
            Adi[k] = 0;
//@endif
        @B@_particle_stress(b, i, A
//@if LAW_FDOT
                            , Ad
//@endif
//@if LAW_DT
                            , b->law_dt
//@endif
                            , store_F);
//@if VISCOSITY
        @B@_spare_Cs(b, i);
//@endif
    }
}

static void @B@_stress_pass(sph_body *b)
{
    const int n = b->nown;
    @B@_gradient_pass(b);
    const int store_F = @B@_store_F(b);
#pragma omp parallel for schedule(static)
    for (int i0 = 0; i0 < n; i0 += @B@_BLOCK) {
        const int i1 = n - i0 < @B@_BLOCK ? n : i0 + @B@_BLOCK;
//@if STENCIL
        @B@_stencil_gradient(b, i0, i1); /* (the run particles' A and Laplacian) */
//@endif
        if (store_F)
            @B@_stress_run(b, i0, i1, 1);
        else
            @B@_stress_run(b, i0, i1, 0);
    }
//@if QUADRATIC
    @B@_quad_stress(b);
//@endif
//@if CLAMP
    sph_clamp_quiet(b);
//@endif
}
//@endif

/* Pass 3, over pairs (each once): momentum balance (eq. 55) in the symmetric corrected form
 *   rho0 dv_i/dt = sum_j V_j (P_i L_i + P_j L_j) grad W_ij
 * plus artificial viscosity (eq. 57-60) symmetrised the same way.  Each pair force is added
 * to i and subtracted from j, so linear momentum is conserved to round-off.
 * The pairs p0 .. p1 - 1 of particle i (neighbour hb[p], table entry hk[p]): their forces on
 * i into *force (a pointer: a returned vector would change the ABI), and with `both` (the
 * half lists, each pair visited once) each pair's force on j subtracted from acc; without
 * (pairs with the halo of a run on many processes) only i's share, the other process
 * computing j's.  *power gets the pairs' f_visc . (v_i - v_j), half of it without `both`;
 * with a law's viscous heat, half of each pair's -f_visc . (v_i - v_j) goes to b->vq of i
 * (and of j with `both`): the heating rate of each particle, per unit mass. */
static inline void @B@_momentum_pairs(const sph_body *b, int i, int p0, int p1,
                                      const int *restrict hb, const int *restrict hk, int both,
                                      double *restrict acc, @B@_vec *force, sph_real *power)
{
    enum { D = @DIM@, R = SPH_ROW(D) };
    typedef @B@_vec vec;
    const sph_real *restrict wtab = b->wtab;
    const vec *restrict Q = (const vec *)b->Q; /* column c of Q_i at Q[i*D + c] */
    const sph_real inv_rho = (sph_real)(1.0 / b->rho0);
    const vec *Qi = Q + (size_t)i * D;
//@if VISCOSITY
    const double *restrict v = b->v;
    const vec *restrict Cv = (const vec *)b->Cv;
    const sph_real *restrict gtab = b->gtab, *restrict Cs = b->Cs;
    const vec *Ci = Cv + (size_t)i * D;
    const sph_real Csi = Cs[i];
    sph_real pv = 0;
//@endif
//@if VHEAT
    double *vq = b->vq;
    double qi = 0;
//@endif
    vec fi = {0};
    for (int p = p0; p < p1; p++) {
        const int j = hb[p], k = hk[p];
        const sph_real *w = wtab + (size_t)k * R;
        const vec *Qj = Q + (size_t)j * D;
        vec f = {0}; /* (Q_i + Q_j) w, column by column */
        for (int c = 0; c < D; c++)
            f += (Qi[c] + Qj[c]) * w[c];
        f *= inv_rho;
//@if QUADRATIC
        @B@_quad_momentum(b, i, j, k, inv_rho, &f);
//@endif
//@if VISCOSITY
        /* The viscosity of eq. 57-60 as @B@_viscosity_term (templates/physics/pairs.c, which
         * has its reasons), with a tensor's columns in short vectors: the viscous direction
         * fv = (cof F_i + cof F_j) w and its approach rate vw = (v_i - v_j) . fv. */
        const vec *Cj = Cv + (size_t)j * D;
        vec fv = {0};
        for (int c = 0; c < D; c++)
            fv += (Ci[c] + Cj[c]) * w[c];
        /* (v_i - v_j) . fv, x and y with one vector load of v_j (sph_double2) */
        const sph_double2 dv = *(const sph_double2 *)(v + i * D) - *(const sph_double2 *)(v + j * D);
        const sph_double2 dvf = dv * (sph_double2){fv[0], fv[1]};
        sph_real vw = (sph_real)(dvf[0] + dvf[1]);
        for (int r = 2; r < D; r++)
            vw += (sph_real)(v[i * D + r] - v[j * D + r]) * fv[r];
        /* Cs_i + Cs_j, in 3D from the columns' padding entries (@B@_spare_Cs; fv's padding
         * entry, and so f's, is not a number anything reads) */
        const sph_real cs = R > D ? (Ci[0] + Cj[0])[R - 1] : Csi + Cs[j];
        /* half the viscous pressure (eq. 58-60; templates/physics/pairs.c) */
        const sph_real hpi = @B@_viscous_pressure_@RS@(gtab[k], cs, vw);
        f -= hpi * fv;
        pv -= hpi * vw;
//@endif
//@if VHEAT
        const double hq = 0.5 * (double)(hpi * vw); /* each particle's half of the heat */
        qi += hq;
        if (both)
            vq[j] += hq;
//@endif
//@if PAIR_TERMS
        sph_real fh[D];
        for (int r = 0; r < D; r++)
            fh[r] = f[r];
        @B@_pair_terms(b, i, j, k, fh);
        for (int r = 0; r < D; r++)
            f[r] = fh[r];
//@endif
        fi += f;
        /* j's share, x and y as one vector read-modify-write: written component by component,
         * the loads and stores (with those of v_j above) took a fifth of the 2D pass and a
         * sixth of the 3D one */
        if (both) {
            *(sph_double2 *)(acc + j * D) -= (sph_double2){f[0], f[1]};
            for (int r = 2; r < D; r++)
                acc[j * D + r] -= f[r];
        }
    }
//@if VHEAT
    vq[i] += qi;
//@endif
//@if VISCOSITY
    *power = both ? pv : (sph_real)0.5 * pv;
//@else
    (void)power;
//@endif
    *force = fi;
}

//@if MPI
/* On many processes, after the half lists: each own particle's pairs with the halo, i's
 * share only, in the stripes of i (the viscous power too); nothing where there is no halo. */
static void @B@_momentum_halo_pairs(sph_body *b)
{
    enum { D = @DIM@ };
    typedef @B@_vec vec;
    const int *restrict xs = b->xb_start, *restrict xb = b->xb, *restrict xk = b->xb_k;
    if (!xs)
        return;
    double *restrict acc = b->a;
#pragma omp parallel for schedule(static)
    for (int s = 0; s < b->nstripes; s++)
        for (int i = b->stripe[s]; i < b->stripe[s + 1]; i++) {
            if (xs[i] == xs[i + 1])
                continue;
            sph_real pv;
            vec fi;
            @B@_momentum_pairs(b, i, xs[i], xs[i + 1], xb, xk, 0, acc, &fi, &pv);
            for (int r = 0; r < D; r++)
                acc[i * D + r] += fi[r];
//@if VISCOSITY
            b->stripe_sum[s] += pv;
//@endif
        }
}

//@endif
//@if STENCIL_MOMENTUM
/* Run particles a .. e - 1 of the lattice stencil (runtime/pairs/stencil.c): by the stencil in
 * vectors (@B@_stencil_momentum, body_stencil.c), and the last few, fewer than a vector's
 * four, pair by pair along the stencil's offsets (not their half lists, whose cache lines
 * nothing else has loaded).  Adds their pairs' viscous power to *power. */
static void @B@_stencil_momentum_run(sph_body *b, int a, int e, double *power)
{
    enum { D = @DIM@ };
    while (a < e) {
        const int done = @B@_stencil_momentum(b, a, e, power);
        if (!done)
            break;
        a += done;
    }
    for (int i = a; i < e; i++)
        for (int q = 0; q < b->st_m; q++) {
            const int j = i + b->st_o[q];
            sph_real pv = 0;
            @B@_vec fi;
            @B@_momentum_pairs(b, i, 0, 1, &j, b->st_k + q, 1, b->a, &fi, &pv);
            for (int c = 0; c < D; c++)
                b->a[i * D + c] += fi[c];
            *power += pv;
        }
}

//@endif
/* The pairs of stripe s's particles (their half lists); returns their viscous power,
 * f_visc . (v_i - v_j) summed over them. */
static double @B@_momentum_stripe(sph_body *b, int s)
{
    enum { D = @DIM@ };
    const int *restrict hs = b->hb_start, *restrict hb = b->hb, *restrict hk = b->hb_k;
    double *restrict acc = b->a;
    double power = 0;
    const int end = b->stripe[s + 1];
//@if STENCIL_MOMENTUM
    /* with the lattice stencil: its runs by the stencil, the rest by the rest lists */
    int r = sph_run_after(b, b->stripe[s]), c = b->rest ? sph_rest_after(b, b->stripe[s]) : 0;
//@endif
    for (int i = b->stripe[s]; i < end; i++) {
        int p0, p1;
        const int *lj = hb, *lk = hk;
//@if STENCIL_MOMENTUM
        while (r < b->nruns && b->st_run[2 * r + 1] <= i)
            r++;
        if (r < b->nruns && b->st_run[2 * r] <= i) {
            const int e = b->st_run[2 * r + 1] < end ? b->st_run[2 * r + 1] : end;
            @B@_stencil_momentum_run(b, i, e, &power);
            i = e - 1;
            continue;
        }
        /* (the half lists' start read only where they are the lists: read for every run
         * as well, it missed the cache there and took a twentieth of crack branching's
         * run) */
        if (b->rest) { /* (every particle not in a run has its rest list) */
            while (b->rest[c] < i)
                c++;
            p0 = b->rest_start[c], p1 = b->rest_start[c + 1], lj = b->rest_j, lk = b->rest_k;
        } else {
            p0 = hs[i], p1 = hs[i + 1];
        }
//@else
        p0 = hs[i], p1 = hs[i + 1];
//@endif
        sph_real pv = 0;
        @B@_vec fi;
        @B@_momentum_pairs(b, i, p0, p1, lj, lk, 1, acc, &fi, &pv);
        for (int k = 0; k < D; k++)
            acc[i * D + k] += fi[k];
        power += pv;
    }
    return power;
}

//@if MOMENTUM_BLOCKS
/* 3D, on a lattice: the own pairs by the momentum pass's offset blocks
 * (runtime/pairs/offset_blocks.c) instead of the half lists, stripe by stripe as they go.
 * Block B's particles i .. i + 7 in the lanes of vectors of eight, as the gradient's blocks;
 * a task is one offset j - i and one table entry for the lanes of its mask, over the half
 * lists (each pair once): Q, cof F, Cs and v of the 8 j are unaligned loads from their
 * copies by component (b->mb_soa, @B@_momentum_copy), the block's own values and its
 * three sums stay in registers over its tasks, and j's share is subtracted from j's sums by
 * component, as the lists do.  The pair terms are those of every layout
 * (templates/physics/pairs.c, _v8: eight pairs in a vector); a lane not in the mask adds
 * zeros (its Cs_i + Cs_j and force masked).  The Taylor bar's momentum pass took about 0.8
 * of the lists' time. */
static double @B@_momentum_blocks(sph_body *b, int s)
{
    typedef @B@_v8 dv8;
    typedef @B@_v8m lv8;
    enum { D = 3, R = SPH_ROW(D) };
    const size_t S = (size_t)b->mb_stride;
    double *const M = b->mb_soa + b->mb_pad; /* row k from M + k S */
    const double *restrict Q = M + SPH_MB_Q * S, *restrict C = M + SPH_MB_CV * S;
    const double *restrict Cs = M + SPH_MB_CS * S, *restrict v = M + SPH_MB_V * S;
    double *a = M + SPH_MB_A * S; /* (j's share and i's may meet: not restrict) */
    const sph_ob_task *restrict mb = b->mb;
    const sph_real *restrict wtab = b->wtab, *restrict gtab = b->gtab;
    const double inv_rho = 1.0 / b->rho0;
    const lv8 lane = {1, 2, 4, 8, 16, 32, 64, 128};
    dv8 pv = {0};
    for (int B = b->mb_stripe[s]; B < b->mb_stripe[s + 1]; B++) {
        const int i = b->mb_i0[B];
        const int m = b->stripe[s + 1] - i < SPH_OB_LANES ? b->stripe[s + 1] - i : SPH_OB_LANES;
        dv8 qi[D * D], ci[D * D], vi[D], fi[D] = {0};
        for (int k = 0; k < D * D; k++)
            qi[k] = *(const dv8 *)(Q + k * S + i), ci[k] = *(const dv8 *)(C + k * S + i);
        for (int r = 0; r < D; r++)
            vi[r] = *(const dv8 *)(v + r * S + i);
        const dv8 csi = *(const dv8 *)(Cs + i);
        for (int t = b->mb_start[B]; t < b->mb_start[B + 1]; t++) {
            const int j = i + mb[t].off, k = (int)(mb[t].key >> 8);
            const lv8 in = (lane & (long long)(mb[t].key & 255)) != 0;
            const double w[D] = {wtab[(size_t)k * R], wtab[(size_t)k * R + 1],
                                 wtab[(size_t)k * R + 2]};
            dv8 qj[D * D], cj[D * D], dv[D], f[D];
            for (int e = 0; e < D * D; e++)
                qj[e] = *(const dv8 *)(Q + e * S + j), cj[e] = *(const dv8 *)(C + e * S + j);
            for (int r = 0; r < D; r++)
                dv[r] = vi[r] - *(const dv8 *)(v + r * S + j);
            @B@_momentum_term_v8(qi, qj, w, inv_rho, f);
            /* Cs_i + Cs_j zero in the lanes without the pair: no viscous pressure there */
            const dv8 cs = (dv8)((lv8)(csi + *(const dv8 *)(Cs + j)) & in);
            pv += @B@_viscosity_term_v8(ci, cj, cs, dv, w, gtab[k], f);
            for (int r = 0; r < D; r++) {
                const dv8 fr = (dv8)((lv8)f[r] & in);
                fi[r] += fr;
                double *aj = a + r * S + j;
                if (m == SPH_OB_LANES)
                    *(dv8 *)aj -= fr;
                else /* (the stripe's last block: its lanes past the stripe are another's) */
                    for (int l = 0; l < m; l++)
                        aj[l] -= fr[l];
            }
        }
        for (int r = 0; r < D; r++) {
            double *ai = a + r * S + i;
            if (m == SPH_OB_LANES)
                *(dv8 *)ai += fi[r];
            else
                for (int l = 0; l < m; l++)
                    ai[l] += fi[r][l];
        }
    }
    double power = 0;
    for (int l = 0; l < SPH_OB_LANES; l++)
        power += pv[l];
    return power;
}

/* Before the blocks: Q, cof F, Cs and v by component into b->mb_soa, the sums zeroed. */
static void @B@_momentum_copy(sph_body *b)
{
    enum { D = 3 };
    const size_t S = (size_t)b->mb_stride;
    double *restrict M = b->mb_soa + b->mb_pad;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        for (int r = 0; r < D; r++)
            for (int c = 0; c < D; c++) {
                M[(SPH_MB_Q + D * r + c) * S + i] = b->Q[SPH_TENSOR(i, r, c, D, b->n)];
                M[(SPH_MB_CV + D * r + c) * S + i] = b->Cv[SPH_TENSOR(i, r, c, D, b->n)];
            }
        M[SPH_MB_CS * S + i] = b->Cs[i];
        for (int r = 0; r < D; r++) {
            M[(SPH_MB_V + r) * S + i] = b->v[(size_t)i * D + r];
            M[(SPH_MB_A + r) * S + i] = 0;
        }
    }
}

/* After them: the blocks' sums added to the accelerations. */
static void @B@_momentum_sums(sph_body *b)
{
    enum { D = 3 };
    const size_t S = (size_t)b->mb_stride;
    const double *restrict a = b->mb_soa + b->mb_pad + SPH_MB_A * S;
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++)
        for (int r = 0; r < D; r++)
            b->a[(size_t)i * D + r] += a[r * S + i];
}

//@endif
static void @B@_momentum_pass(sph_body *b)
{
    enum { D = @DIM@ };
    double *restrict acc = b->a;
//@if MPI
    /* The halo's values of what the pairs read of a neighbour besides u and v: Q, and cof F
     * and Cs for the viscosity, F for the pair terms (which may read X, u, v and F of both
     * particles); on their way during the pairs of own particles (docs/mpi.md). */
    const sph_field halo_in[] = {
        {b->Q, SPH_TENSOR_SIZE(D) * sizeof *b->Q},
//@if VISCOSITY
        {b->Cv, SPH_TENSOR_SIZE(D) * sizeof *b->Cv},
//@if DIM3
        /* (Cs in cof F's padding, @B@_spare_Cs) */
//@else
        SPH_FIELD(b->Cs, 1),
//@endif
//@endif
//@if PAIR_TERMS
        SPH_FIELD(b->F, 9),
//@endif
//@if QUADRATIC
        SPH_FIELD(b->Qq, @B@_QN * SPH_ROW(D)), /* the quadratic gradient's pair term */
//@endif
    };
    const int nhalo_in = sizeof halo_in / sizeof *halo_in;
    b->par->post(b, halo_in, nhalo_in);
//@endif
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        for (int r = 0; r < D; r++)
//@if GRAVITY
            acc[i * D + r] = @B@_gravity[r];
//@else
            acc[i * D + r] = 0;
//@endif
//@if VHEAT
        b->vq[i] = 0;
//@endif
    }
//@if MOMENTUM_BLOCKS
    if (b->mb)
        @B@_momentum_copy(b);
//@endif
    for (int colour = 0; colour < b->ncolours; colour++) {
#pragma omp parallel for schedule(static)
        for (int s = colour; s < b->nstripes; s += b->ncolours)
//@if MOMENTUM_BLOCKS
            b->stripe_sum[s] = b->mb ? @B@_momentum_blocks(b, s) : @B@_momentum_stripe(b, s);
//@else
            b->stripe_sum[s] = @B@_momentum_stripe(b, s);
//@endif
    }
//@if MOMENTUM_BLOCKS
    if (b->mb)
        @B@_momentum_sums(b);
//@endif
//@if MPI
    b->par->wait(b, halo_in, nhalo_in);
    @B@_momentum_halo_pairs(b);
//@endif
//@if VISCOSITY
    double visc_power = 0; /* the viscous work rate, in stripe order (any number of threads) */
    for (int s = 0; s < b->nstripes; s++)
        visc_power += b->stripe_sum[s];
    b->visc_rate = -b->mass * visc_power; /* energy per second the viscosity dissipates */
//@endif
//@if CLAMP
//@if GRAVITY
    sph_clamp_reactions(b, @B@_gravity);
//@else
    sph_clamp_reactions(b, NULL);
//@endif
//@endif
}

static void @B@_forces(sph_body *b)
{
    SPH_BODY_PASS(b, "stress_pass", @B@_stress_pass(b)); /* (timed with --profile) */
    SPH_BODY_PASS(b, "momentum_pass", @B@_momentum_pass(b));
}
