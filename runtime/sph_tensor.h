/* sph_tensor.h — positive and negative parts of symmetric tensors, and their derivatives
 * (header only).
 *
 * Used by the generated code for phase-field fracture: the tension/compression split of
 * the Green–Lagrange strain (paper eq. 13–16), E = Q Λ Qᵀ, E⁺ = Q Λ⁺ Qᵀ with Λ⁺ the
 * positive parts of the eigenvalues, and E⁻ = E − E⁺.
 *
 * Conventions: a 3×3 tensor is a row-major array of 9 doubles (A[3*i+j] = A_ij); the input
 * is assumed symmetric and is symmetrised as (A_ij + A_ji)/2, so every output is exactly
 * symmetric. Eigenvectors are the COLUMNS of Q (Q[3*i+k] is component i of eigenvector k),
 * A = Q diag(lam) Qᵀ, and the eigenvalues are sorted in DESCENDING order, lam[0] >= lam[1]
 * >= lam[2]. The 2×2 variant works on the x–z plane (plane strain): {axx, axz, azz}.
 *
 * Method (3×3): cyclic Jacobi. The matrix is first divided by its largest |a_ij| (no
 * overflow or underflow in squares, and the zero matrix returns at once: lam = 0, Q = I);
 * after that the Frobenius norm lies in [1, 3] and is kept by the rotations, so the test
 * "every |a_pq| <= SPH_EIG_TOL" is a test relative to the Frobenius norm. Each rotation
 * takes the smaller angle (|φ| <= π/4) and is computed without dividing by the
 * off-diagonal entry; a rotation is made only for an entry above the tolerance, so nothing
 * divides by zero. Convergence is quadratic: 3–4 sweeps (7–12 rotations) for random
 * matrices, at most SPH_EIG_MAX_SWEEPS. Eigenvalues come out accurate to a few ulps of the
 * norm, Q orthonormal to a few ulps, and repeated eigenvalues (double, triple, c·I) need no
 * special case. The positive part is the projection onto the cone of positive semidefinite
 * tensors, hence 1-Lipschitz: its error is the backward error of the decomposition, a few
 * ulps of the norm, even where eigenvalues (nearly) coincide or straddle zero.
 *
 * Method (2×2): closed form, eigenvalues m ± r, m = (axx+azz)/2, r = hypot((axx−azz)/2, axz),
 * without branches.
 */
#ifndef SPH_TENSOR_H
#define SPH_TENSOR_H

#include <math.h>

#include "core/defs.h" /* SPH_HD: these run on the device too (CUDA target); sph_max, sph_min */

/* Off-diagonal entries at or below this (relative to the largest entry) count as zero. */
#define SPH_EIG_TOL 1e-18
/* Upper bound on the Jacobi sweeps (never reached in practice: quadratic convergence). */
#define SPH_EIG_MAX_SWEEPS 32

SPH_HD static inline double sph_absmax(double a, double b) { return sph_max(fabs(a), fabs(b)); }

/* (a + b) / 2, exactly a when a == b (also for subnormals) and free of overflow. */
SPH_HD static inline double sph_sym_avg(double a, double b) { return a == b ? a : 0.5 * a + 0.5 * b; }

/* One Jacobi rotation in the (p, q) plane, p < q, that makes the (p, q) entry zero. The
 * matrix is held as its diagonal d and its off-diagonal entries o, o[r] being the entry
 * between the two indices other than r (o[0] = a12, o[1] = a02, o[2] = a01); the columns
 * p and q of V are rotated alike. With h = d_q − d_p the angle φ has tan 2φ = 2 a_pq / h,
 * |φ| <= π/4: t = tan φ = 2 a_pq sign(h) / w, w = |h| + g, g = sqrt(h² + 4 a_pq²), and
 * cos φ, sin φ = (w, 2 a_pq sign(h)) / sqrt(w² + 4 a_pq²). The caller scales the matrix to
 * a norm of order 1, so no square over- or underflows (|a_pq| > SPH_EIG_TOL here). */
SPH_HD static inline void sph_jacobi_rotate(double d[3], double o[3], double V[9], int p, int q)
{
    int r = 3 - p - q;
    double a = o[r];
    if (fabs(a) <= SPH_EIG_TOL)
        return; /* negligible */
    double h = d[q] - d[p], a2 = a + a, sg = h < 0.0 ? -1.0 : 1.0;
    double g = sqrt(h * h + a2 * a2); /* eigenvalue gap of the 2×2 block, >= 2|a| > 0 */
    double w = fabs(h) + g, x = w * w + a2 * a2;
    /* 1/sqrt(x) as sqrt(x) * (1/x): the square root and the division run in parallel. */
    double rn = sqrt(x) * (1.0 / x), c = w * rn, s = sg * a2 * rn;
    double ta = sg * 0.5 * (g - fabs(h)); /* t a_pq = 2 a² sign(h) / w, as g² − h² = 4a² */
    d[p] -= ta;
    d[q] += ta;
    o[r] = 0.0;
    double arp = o[q], arq = o[p]; /* the entries (r, p) and (r, q) */
    o[q] = c * arp - s * arq;
    o[p] = s * arp + c * arq;
    for (int k = 0; k < 3; k++) {
        double vp = V[3 * k + p], vq = V[3 * k + q];
        V[3 * k + p] = c * vp - s * vq;
        V[3 * k + q] = s * vp + c * vq;
    }
}

/* Cyclic Jacobi: eigenvalues lam (unsorted) and eigenvectors in the columns of Q. */
SPH_HD static inline void sph_sym_eig3_unsorted(const double A[9], double lam[3], double Q[9])
{
    for (int k = 0; k < 9; k++)
        Q[k] = (k % 4 == 0); /* identity */
    double a01 = sph_sym_avg(A[1], A[3]), a02 = sph_sym_avg(A[2], A[6]);
    double a12 = sph_sym_avg(A[5], A[7]);
    double scale = sph_absmax(sph_absmax(A[0], A[4]), sph_absmax(A[8], a01));
    scale = sph_absmax(scale, sph_absmax(a02, a12));
    if (scale == 0.0) { /* the zero matrix */
        lam[0] = lam[1] = lam[2] = 0.0;
        return;
    }
    /* Divide (multiplying by 1/scale would overflow for a subnormal scale); the largest
     * entry becomes ±1 and the Frobenius norm lies in [1, 3] (rotations keep it). */
    double d[3] = {A[0] / scale, A[4] / scale, A[8] / scale};
    double o[3] = {a12 / scale, a02 / scale, a01 / scale};
    for (int sweep = 0; sweep < SPH_EIG_MAX_SWEEPS; sweep++) {
        if (fabs(o[0]) <= SPH_EIG_TOL && fabs(o[1]) <= SPH_EIG_TOL && fabs(o[2]) <= SPH_EIG_TOL)
            break; /* converged: off-diagonal negligible relative to the norm */
        sph_jacobi_rotate(d, o, Q, 0, 1);
        sph_jacobi_rotate(d, o, Q, 0, 2);
        sph_jacobi_rotate(d, o, Q, 1, 2);
    }
    for (int k = 0; k < 3; k++)
        lam[k] = d[k] * scale;
}

/* Swaps eigenpairs i and j (eigenvalue and column of Q). */
SPH_HD static inline void sph_eig_swap(double lam[3], double Q[9], int i, int j)
{
    double t = lam[i];
    lam[i] = lam[j];
    lam[j] = t;
    for (int k = 0; k < 3; k++) {
        t = Q[3 * k + i];
        Q[3 * k + i] = Q[3 * k + j];
        Q[3 * k + j] = t;
    }
}

/* Eigen-decomposition of a symmetric 3×3 tensor: A = Q diag(lam) Qᵀ, lam DESCENDING,
 * eigenvectors in the columns of Q, Q orthonormal (a rotation or a reflection). Finite
 * input gives finite output (as long as the eigenvalues themselves are representable);
 * the zero matrix and c·I give lam = c exactly and Q = I. */
SPH_HD static inline void sph_sym_eig3(const double A[9], double lam[3], double Q[9])
{
    sph_sym_eig3_unsorted(A, lam, Q);
    if (lam[0] < lam[1])
        sph_eig_swap(lam, Q, 0, 1);
    if (lam[1] < lam[2])
        sph_eig_swap(lam, Q, 1, 2);
    if (lam[0] < lam[1])
        sph_eig_swap(lam, Q, 0, 1);
}

/* Positive part Ap = Σ max(lam_k, 0) q_k q_kᵀ of a symmetric 3×3 tensor (the negative part
 * is A − Ap). Exactly the (symmetrised) A when no eigenvalue is negative, exactly 0 when
 * none is positive. */
SPH_HD static inline void sph_sym_pos3(const double A[9], double Ap[9])
{
    double lam[3], Q[9];
    sph_sym_eig3_unsorted(A, lam, Q); /* the order does not matter here */
    double lo = sph_min(lam[0], sph_min(lam[1], lam[2]));
    double hi = sph_max(lam[0], sph_max(lam[1], lam[2]));
    if (lo >= 0.0) { /* positive semidefinite: Ap = A */
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++)
                Ap[3 * i + j] = sph_sym_avg(A[3 * i + j], A[3 * j + i]);
        return;
    }
    if (hi <= 0.0) { /* negative semidefinite: Ap = 0 */
        for (int k = 0; k < 9; k++)
            Ap[k] = 0.0;
        return;
    }
    /* Mixed signs: sum over the positive eigenvalues. */
    double w[3] = {sph_max(lam[0], 0.0), sph_max(lam[1], 0.0), sph_max(lam[2], 0.0)};
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++)
                v += w[k] * Q[3 * i + k] * Q[3 * j + k];
            Ap[3 * i + j] = Ap[3 * j + i] = v;
        }
}

/* Positive part of the symmetric 2×2 tensor {{axx, axz}, {axz, azz}} (x–z plane, plane
 * strain), closed form; out = {pxx, pxz, pzz}. The negative part is A − out.
 * Without branches: the three cases (A, 0, the mixed form) are selects, so that a loop
 * over particles that calls it can be vectorised (the fracture laws' stress pass).
 * With eigenvalues l1 >= l2: positive semidefinite (l2 >= 0): Ap = A; negative
 * semidefinite (l1 <= 0): Ap = 0; across zero: Ap = l1 q1 q1ᵀ = w (A − l2 I),
 * w = l1 / (l1 − l2) in (0, 1).  NaN in gives NaN out. */
SPH_HD static inline void sph_sym_pos2(double axx, double axz, double azz, double out[3])
{
    double m = 0.5 * axx + 0.5 * azz, dh = 0.5 * axx - 0.5 * azz, r2 = dh * dh + axz * axz;
    /* r = hypot(dh, axz): where r2 could have over- or underflowed (and for r2 = 0) from dh
     * and axz scaled by a power of two (exact), and scaled back */
    const int big = r2 > 0x1p1000, small = r2 < 0x1p-1000;
    const double up = big ? 0x1p-600 : small ? 0x1p600 : 1.0;
    const double down = big ? 0x1p600 : small ? 0x1p-600 : 1.0;
    const double sx = dh * up, sz = axz * up;
    double r = sqrt(sx * sx + sz * sz) * down;
    double l1 = m + r, l2 = m - r;        /* eigenvalues, l1 >= l2 */
    const double w = l1 / (l1 - l2);      /* (not finite for r = 0: then not selected) */
    const double a = l2 >= 0.0 ? 1.0 : l1 <= 0.0 ? 0.0 : w; /* A, 0 or the mixed form */
    const double shift = l2 >= 0.0 ? 0.0 : l2;
    out[0] = a * (axx - shift), out[1] = a * axz, out[2] = a * (azz - shift);
}

/* ------------------------------------------------------------------ derivatives
 *
 * The adjoints (reverse-mode derivatives) of the positive parts, for laws whose stress is
 * derived from an energy that uses pos or neg (neg(A) = A − pos(A) needs no routine of its
 * own).  pos is the spectral function F(A) = Σ f(λ_k) q_k q_kᵀ with f(λ) = max(λ, 0).  Its
 * derivative (Daleckii–Krein): for a symmetric perturbation dA,
 *     dF = Q (Γ ∘ (Qᵀ dA Q)) Qᵀ,  Γ_ij = (f(λ_i) − f(λ_j)) / (λ_i − λ_j), Γ_ii = f'(λ_i),
 * so the adjoint G = ∂<B, F(A)>/∂A of an adjoint B of the output is Q (Γ ∘ (Qᵀ sym(B) Q)) Qᵀ.
 * For f = max(·, 0): Γ_ij = 1 where λ_i, λ_j > 0, 0 where neither is positive, and
 * λ_+ / (λ_+ − λ_−) across zero (a positive denominator: no cancellation, equal eigenvalues
 * need no special case).  At a zero eigenvalue f'(0) is taken as 0 (the derivative from the
 * compressive side).  Special cases: G = sym(B) exactly where every eigenvalue is positive,
 * G = 0 where none is.  Consequence: d tr(pos(A)²)/dA = 2 pos(A), d tr(neg(A)²)/dA = 2 neg(A). */

/* Γ_ij for f(λ) = max(λ, 0). */
SPH_HD static inline double sph_pos_divided_difference(double li, double lj)
{
    if (li > 0.0 && lj > 0.0)
        return 1.0;
    if (li <= 0.0 && lj <= 0.0)
        return 0.0;
    return li > 0.0 ? li / (li - lj) : lj / (lj - li);
}

/* The adjoint of sph_sym_pos3: in = {A[9], B[9]}, B the adjoint of its output Ap (row-major);
 * G[k] = ∂(Σ_m B[m] Ap[m]) / ∂A[k], symmetric (A is symmetrised as sph_sym_pos3 does). */
SPH_HD static inline void sph_sym_pos3_adjoint(const double in[18], double G[9])
{
    const double *A = in, *B = in + 9;
    double lam[3], Q[9], Bs[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            Bs[3 * i + j] = sph_sym_avg(B[3 * i + j], B[3 * j + i]);
    sph_sym_eig3_unsorted(A, lam, Q);
    double lo = sph_min(lam[0], sph_min(lam[1], lam[2]));
    double hi = sph_max(lam[0], sph_max(lam[1], lam[2]));
    if (lo > 0.0 || hi <= 0.0) { /* F(A) = A near A: G = sym(B); F(A) = 0: G = 0 */
        for (int k = 0; k < 9; k++)
            G[k] = lo > 0.0 ? Bs[k] : 0.0;
        return;
    }
    double T[9], M[9]; /* T = Bs Q, M = Γ ∘ (Qᵀ Bs Q) */
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++)
                v += Bs[3 * i + k] * Q[3 * k + j];
            T[3 * i + j] = v;
        }
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++)
                v += Q[3 * k + i] * T[3 * k + j];
            M[3 * i + j] = M[3 * j + i] = sph_pos_divided_difference(lam[i], lam[j]) * v;
        }
    for (int i = 0; i < 3; i++) /* G = Q M Qᵀ, its upper triangle mirrored */
        for (int j = i; j < 3; j++) {
            double v = 0.0;
            for (int k = 0; k < 3; k++)
                for (int l = 0; l < 3; l++)
                    v += Q[3 * i + k] * M[3 * k + l] * Q[3 * j + l];
            G[3 * i + j] = G[3 * j + i] = v;
        }
}

/* The adjoint of sph_sym_pos2: in = {axx, axz, azz, bxx, bxz, bzz}, b the adjoints of its
 * outputs {pxx, pxz, pzz}; out = the adjoints of its inputs {axx, axz, azz} (axz stands for
 * both off-diagonal entries: out[1] = 2 G_xz).  Across zero (l1 > 0 >= l2), with the
 * projectors P1 = (A − l2 I)/(l1 − l2), P2 = (l1 I − A)/(l1 − l2) and w = l1/(l1 − l2):
 * G = P1 Bs P1 + w (P1 Bs P2 + P2 Bs P1), Bs = {{bxx, bxz/2}, {bxz/2, bzz}}. */
SPH_HD static inline void sph_sym_pos2_adjoint(const double in[6], double out[3])
{
    double axx = in[0], axz = in[1], azz = in[2];
    double m = 0.5 * axx + 0.5 * azz, dh = 0.5 * axx - 0.5 * azz, r2 = dh * dh + axz * axz;
    double r = r2 < 0x1p1000 && r2 > 0x1p-1000 ? sqrt(r2) : hypot(dh, axz);
    double l1 = m + r, l2 = m - r;
    if (l2 > 0.0 || l1 <= 0.0) {
        double keep = l2 > 0.0 ? 1.0 : 0.0;
        out[0] = keep * in[3], out[1] = keep * in[4], out[2] = keep * in[5];
        return;
    }
    double den = l1 - l2, w = l1 / den;
    double P1[4] = {(axx - l2) / den, axz / den, axz / den, (azz - l2) / den};
    double P2[4] = {(l1 - axx) / den, -axz / den, -axz / den, (l1 - azz) / den};
    double Bs[4] = {in[3], 0.5 * in[4], 0.5 * in[4], in[5]};
    double X[4], Y[4], G[4]; /* X = Bs P1, Y = Bs P2 */
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            X[2 * i + j] = Bs[2 * i] * P1[j] + Bs[2 * i + 1] * P1[2 + j];
            Y[2 * i + j] = Bs[2 * i] * P2[j] + Bs[2 * i + 1] * P2[2 + j];
        }
    for (int i = 0; i < 2; i++)
        for (int j = 0; j < 2; j++) {
            double p1x = P1[2 * i] * X[j] + P1[2 * i + 1] * X[2 + j];
            double p1y = P1[2 * i] * Y[j] + P1[2 * i + 1] * Y[2 + j];
            double p2x = P2[2 * i] * X[j] + P2[2 * i + 1] * X[2 + j];
            G[2 * i + j] = p1x + w * (p1y + p2x);
        }
    out[0] = G[0], out[1] = G[1] + G[2], out[2] = G[3];
}

#endif /* SPH_TENSOR_H */
