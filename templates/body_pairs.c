/* ---- body @B@: a pair's terms in short vectors --------------------------------------------
 * The pair loops hold a table entry, a column of Q or Cv, and A's rows in short vectors
 * (SPH_VECTOR, rows and columns padded with zeros to SPH_ROW(D) entries): a pair's outer
 * product is one or two vector multiplies (@B@_pair_tensor).  Written entry by entry, the
 * compiler keeps every entry scalar, and the 3D plate's step took 1.7 times as long. */
SPH_VECTOR(@B@_vec, SPH_ROW(@DIM@));
/* A pair's term of the gradient pass, (u_j - u_i) (x) w_ij, all D x R entries of it at once
 * (@B@_tensor): entry (r, c) is the product of row r's difference, repeated R times, and
 * the table entry w, repeated D times.  In 2D one vector of 4 (the two rows side by side), in
 * 3D rows 0 and 1 in a vector of 8 and row 2 in one of 4, where a row at a time took D
 * multiplies and D additions to each of A_i and A_j (the flyer plates' whole step: 4 % more
 * time).  An A_i in memory is its D x R entries from A + i D R. */
//@if DIM3
SPH_VECTOR(@B@_vec8, 8);
typedef struct {
    @B@_vec8 r01; /* rows 0 and 1 */
    @B@_vec r2;
} @B@_tensor;
static inline void @B@_pair_tensor(const double *restrict uj, const double ui[3], @B@_vec w,
                                   @B@_tensor *t)
{
    /* x and y of u_j - u_i with one vector load (sph_double2): component by component, the
     * Taylor bar's gradient pass took an eighth longer */
    const sph_double2 d01 = *(const sph_double2 *)uj - *(const sph_double2 *)ui;
    const sph_real d0 = (sph_real)d01[0], d1 = (sph_real)d01[1], d2 = (sph_real)(uj[2] - ui[2]);
    t->r01 = (@B@_vec8){d0, d0, d0, d0, d1, d1, d1, d1} *
             (@B@_vec8){w[0], w[1], w[2], w[3], w[0], w[1], w[2], w[3]};
    t->r2 = d2 * w;
}
static inline void @B@_tensor_add(@B@_tensor *to, const @B@_tensor *t)
{
    to->r01 += t->r01;
    to->r2 += t->r2;
}
static inline void @B@_tensor_add_to(sph_real *to, const @B@_tensor *t)
{
    *(@B@_vec8 *)to += t->r01;
    *(@B@_vec *)(to + 8) += t->r2;
}
//@else
SPH_VECTOR(@B@_vec4, 4);
typedef struct {
    @B@_vec4 r01; /* rows 0 and 1 */
} @B@_tensor;
static inline void @B@_pair_tensor(const double *restrict uj, const double ui[2], @B@_vec w,
                                   @B@_tensor *t)
{
    const sph_double2 d01 = *(const sph_double2 *)uj - *(const sph_double2 *)ui;
    const sph_real d0 = (sph_real)d01[0], d1 = (sph_real)d01[1];
    t->r01 = (@B@_vec4){d0, d0, d1, d1} * (@B@_vec4){w[0], w[1], w[0], w[1]};
}
static inline void @B@_tensor_add(@B@_tensor *to, const @B@_tensor *t)
{
    to->r01 += t->r01;
}
static inline void @B@_tensor_add_to(sph_real *to, const @B@_tensor *t)
{
    *(@B@_vec4 *)to += t->r01;
}
//@endif
