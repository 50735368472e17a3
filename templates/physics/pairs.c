//@if FIRST
/* ---- body @B@: the pair terms ---------------------------------------------------------------
 * The arithmetic of a pair (i, j), written once for every loop that visits pairs: the half
 * lists and the offset blocks (templates/body_forces.c), the 2D lattice stencil
 * (body_stencil.c) and the device's full lists (body_cuda.cu).  A loop gathers the pair's
 * values and calls these; how it finds j, and where the sums go, is the loop's business.
 * Each function is filled in once for every element type a loop of this body uses (sphc:
 * compiler/emit/emit_body.c): _d, _f one pair in double or float, _v8 the eight pairs of an
 * offset block side by side in the lanes of a vector (or four pairs' x and y, the stencil).
 * The lanes are independent: a term is the same formula lane by lane, so a lane's result
 * does not depend on the type it was computed in (the tests compare the loops' energies).
 * Tensors D x D row by row; w = V_j grad W_ij, the pair's entry of the offset table.  Only
 * the terms a body's loops call are filled in. */
//@endif
/* ---- body @B@: the pair terms over @T@ (_@S@) */
//@if LANES_V8
#if defined(__GNUC__) && !defined(__clang__)
/* (these functions are static and inlined: how a vector crosses a call, which GCC warns may
 * differ between machines without AVX-512, never matters) */
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
typedef double @B@_v8 __attribute__((vector_size(8 * sizeof(double)), aligned(sizeof(double)),
                                     may_alias));
typedef long long @B@_v8m __attribute__((vector_size(8 * sizeof(long long))));
//@endif
//@if TERM_PRESSURE
//@if BETA2
/* |x|, lane by lane */
//@if LANES_V8
static inline @B@_v8 @B@_abs_v8(@B@_v8 x)
{
    const @B@_v8 sign = {-0.0, -0.0, -0.0, -0.0, -0.0, -0.0, -0.0, -0.0};
    return (@B@_v8)((@B@_v8m)x & ~(@B@_v8m)sign); /* (the sign bits cleared) */
}
//@else
SPH_FN @T@ @B@_abs_@S@(@T@ x)
{
    return fabs(x);
}
//@endif
//@else
/* max(x, 0), lane by lane: a compare-and-move, not a branch */
//@if LANES_V8
static inline @B@_v8 @B@_max0_v8(@B@_v8 x)
{
    return (@B@_v8)((@B@_v8m)(x > 0) & (@B@_v8m)x);
}
//@else
SPH_FN @T@ @B@_max0_@S@(@T@ x)
{
    return x > 0 ? x : 0;
}
//@endif
//@endif
//@endif
//@if TERM_GRADIENT

/* Eq. 53 with the corrected gradient (eq. 63): the pair's share of
 *   A_i = sum_j V_j (u_j - u_i) (x) grad W_ij,   added to a,
 * from d = u_j - u_i (the loop has it in its own layout: one load and a subtraction). */
SPH_FN void @B@_gradient_term_@S@(@T@ a[@DIM@ * @DIM@], const @T@ d[@DIM@], const @W@ w[@DIM@])
{
    enum { D = @DIM@ };
    for (int r = 0; r < D; r++)
        for (int c = 0; c < D; c++)
            a[r * D + c] += d[r] * (@E@)w[c];
}
//@endif
//@if TERM_MOMENTUM

/* Sum over c of (x_i + x_j)_c w_c: a row of (X_i + X_j) w, the pair's tensors contracted with
 * its kernel gradient, from row r's entries (x = X + r D). */
SPH_FN @T@ @B@_contract_@S@(const @T@ *xi, const @T@ *xj, const @W@ w[@DIM@])
{
    @T@ s = (xi[0] + xj[0]) * (@E@)w[0];
    for (int c = 1; c < @DIM@; c++)
        s += (xi[c] + xj[c]) * (@E@)w[c];
    return s;
}

/* Eq. 55 in the symmetric corrected form: the pair's force on i per unit mass,
 *   f = V_j (P_i L_i + P_j L_j) grad W_ij / rho0,   from Q = P L of both (the stress pass's).
 * The force on j is -f: linear momentum is conserved to round-off. */
SPH_FN void @B@_momentum_term_@S@(const @T@ qi[@DIM@ * @DIM@], const @T@ qj[@DIM@ * @DIM@],
                                  const @W@ w[@DIM@], @E@ inv_rho, @T@ f[@DIM@])
{
    for (int r = 0; r < @DIM@; r++)
        f[r] = @B@_contract_@S@(qi + r * @DIM@, qj + r * @DIM@, w) * inv_rho;
}
//@endif
//@if TERM_PRESSURE
/* Eq. 58-60, Monaghan and Gingold's viscosity (the paper's [61]) on approach only: half the
 * viscous pressure, hpi = pi / 2 (times rho0), of a pair whose approach rate along its
 * viscous direction is vw = (v_i - v_j) . fv, g its factor G / ((v_i - v_j) . w) of eq. 60
 * from the offset table (h / (r^2 + 0.001 h^2) in the units of w), cs = Cs_i + Cs_j:
 *   G = g vw cs / 4,  pi = -beta1 c0 G + beta2 G^2 where G < 0, zero as the pair separates.
 * The constant factors are folded, and what does not wait for vw is multiplied first: the
 * momentum pass is as slow as its longest chain of dependent operations, and one product
 * more between vw and hpi cost the 3D cases' pass a third.  The approach-only switch is a
 * select between two values (a compare-and-move): a branch there, taken for about every
 * other pair at random, cost the 3D column's momentum pass a quarter of its time. */
SPH_FN @T@ @B@_viscous_pressure_@S@(@E@ g, @T@ cs, @T@ vw)
{
//@if BETA2
    const @T@ x = g * (@E@)0.5 * cs * vw;
    const @T@ d = x - @B@_abs_@S@(x); /* 2 G - 2 |G| = 4 min(G, 0) */
    return d * ((@E@)(-0.125 * @BETA1@ * @C0@) + d * (@E@)(0.03125 * @BETA2@));
//@else
    return @B@_max0_@S@(g * (@E@)(-0.125 * @BETA1@ * @C0@) * cs * vw);
//@endif
}
//@endif
//@if TERM_MOMENTUM
//@if VISCOSITY

/* Eq. 57-60: the pair's artificial viscosity, subtracted from its force f; returns its
 * viscous power share -hpi vw (the work rate f_visc . (v_i - v_j), each pair once).
 * The viscous pressure acts along fv = (J F^-T)_i w + (J F^-T)_j w (eq. 57 from both sides,
 * without the correction L; ci, cj the cofactors cof F = J F^-T), and G of eq. 60 is
 * measured along it from dv = v_i - v_j and scaled by the mean of the pair's
 * Cs = lambda_min / J (cs = Cs_i + Cs_j).  In the reference configuration fv/2 is w,
 * parallel to X_i - X_j, and Cs is 1, so this is eq. 60; fv turns with the pair, so a rigid
 * rotation gives G = 0 at any angle, and the viscous power is never positive (eq. 60 taken
 * along X_i - X_j feeds energy in once a pair has turned by more than 90 degrees, and L in
 * fv lets a boundary pair's G see a rigid rotation).  fv/2 is longer than w by up to 1 / Cs
 * where the body is compressed along the pair: Cs takes that out, so that G is the approach
 * rate in the pair's reference length, as in eq. 60, not in its current, shorter one
 * (docs/stability.md). */
SPH_FN @T@ @B@_viscosity_term_@S@(const @T@ ci[@DIM@ * @DIM@], const @T@ cj[@DIM@ * @DIM@],
                                  @T@ cs, const @T@ dv[@DIM@], const @W@ w[@DIM@], @E@ g,
                                  @T@ f[@DIM@])
{
    enum { D = @DIM@ };
    @T@ fv[D];
    for (int r = 0; r < D; r++)
        fv[r] = @B@_contract_@S@(ci + r * D, cj + r * D, w);
    @T@ vw = dv[0] * fv[0];
    for (int r = 1; r < D; r++)
        vw += dv[r] * fv[r];
    const @T@ hpi = @B@_viscous_pressure_@S@(g, cs, vw);
    for (int r = 0; r < D; r++)
        f[r] -= hpi * fv[r];
    return -(hpi * vw);
}
//@endif
//@endif
