"""tlsph_linear.py — sphc's total-Lagrangian SPH linearised: its stiffness matrix, for static
and modal answers without time stepping.

The discrete energy of a body is E = sum_i V_i psi(F_i) with F_i from the corrected gradient;
for small strains psi = eps : C : eps / 2 and the momentum pass's forces are exactly -dE/du
(templates/body_forces.c), so K = sum_i V_i B_i^T C B_i is the matrix of the same scheme, and
K u = f gives the static answer a damped run reaches, K phi = w^2 M phi the periods a free run
shows (the 3D plate at dp 5 mm and 4 mm: 0.3943 s and 0.3475 s here, 0.39417 s and 0.34699 s
in the time-stepping runs of docs/verification.md).  What can be switched, one at a time:

  gradient   'linear'     eq. 63: L_i grad W_ij, exact for linear fields
             'quadratic'  the least-squares fit of the gradient and second derivatives
                          (runtime/pairs/quadratic.c), exact for quadratic fields
  quadrature 'node'       psi at the particle times its volume (one point a cell)
             'cell'       plus the strain-gradient term of a linear F over the cell
                          (templates/body_quadratic.c; needs the quadratic gradient)
  clamp      'held'       the particles behind the clamp's plane held at zero displacement
             'images'     those particles the mirror images of the ones in front, u = -u(mirror),
                          without energy (runtime/run/clamp.c)
  hourglass  alpha of the body setting `hourglass` (0: none), linearised
  clamp layers, the kernel (Wendland C2 or cubic spline) and coefh (h = coefh sqrt(3) dx).

Needs numpy and scipy (Debian: python3-numpy, python3-scipy); run with /usr/bin/python3.
"""
import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as spl
from scipy.spatial import cKDTree


def kernel(kind, r, h):
    """W(r) and dW/dr in 3D (runtime/core/kernel.c)."""
    q = r / h
    if kind == 'wendland':
        a = 21.0 / (16 * np.pi * h**3)
        t = np.clip(1 - q / 2, 0, None)
        return a * t**4 * (2 * q + 1), a * (-5 * q) * t**3 / h
    a = 1.0 / (np.pi * h**3)
    w = np.where(q < 1, 1 - 1.5 * q**2 + 0.75 * q**3, np.where(q < 2, 0.25 * (2 - q)**3, 0))
    dw = np.where(q < 1, -3 * q + 2.25 * q**2, np.where(q < 2, -0.75 * (2 - q)**2, 0))
    return a * w, a * dw / h


def box_lattice(lo, hi, dx):
    """Cell centres of a box whose extent is a whole number of cells (runtime/geom/fill.c)."""
    axes = [lo[c] + (np.arange(int(round((hi[c] - lo[c]) / dx))) + 0.5) * dx for c in range(3)]
    return np.array(np.meshgrid(*axes, indexing='ij')).reshape(3, -1).T


def quad_monomials(d):
    return np.column_stack([d[:, 0]**2, d[:, 1]**2, d[:, 2]**2,
                            d[:, 0] * d[:, 1], d[:, 1] * d[:, 2], d[:, 0] * d[:, 2]])


# d^2/dX_a dX_b -> (monomial column, factor): x^2's coefficient is half of d^2/dx^2
SECOND = {(a, b): ((3 + a if a == b else {1: 6, 3: 7, 2: 8}[a + b]), 2.0 if a == b else 1.0)
          for a in range(3) for b in range(3)}


def operators(X, V, h, kind, gradient):
    """Pairs (I, J) and per pair G (grad u_i = sum_j (u_j - u_i) (x) G_ij) and, with the
    quadratic gradient, Hs[:, a, b] (d/dX_a of grad_b u_i likewise)."""
    tree = cKDTree(X)
    P = tree.query_pairs(2 * h, output_type='ndarray')
    I = np.concatenate([P[:, 0], P[:, 1]])
    J = np.concatenate([P[:, 1], P[:, 0]])
    N = len(X)
    d = X[J] - X[I]
    r = np.linalg.norm(d, axis=1)
    _, dW = kernel(kind, r, h)
    omega = V[J] * (-dW / r)            # V_j (-dW/dr) / r: the first-order correction's weight
    if gradient == 'linear':
        w = -omega[:, None] * d          # V_j grad_i W_ij
        M = np.zeros((N, 3, 3))
        np.add.at(M, I, d[:, :, None] * w[:, None, :])
        return I, J, np.einsum('kcr,kc->kr', np.linalg.inv(M)[I], w), None
    p = np.column_stack([d, quad_monomials(d)])
    A = np.zeros((N, 9, 9))
    np.add.at(A, I, omega[:, None, None] * p[:, :, None] * p[:, None, :])
    R = np.einsum('kab,kb->ka', np.linalg.inv(A)[I], p) * omega[:, None]
    Hs = np.zeros((len(I), 3, 3))
    for (a, b), (m, f) in SECOND.items():
        Hs[:, a, b] = f * R[:, m]
    return I, J, R[:, :3], Hs


def bmatrix(N, I, J, G):
    rows, cols, vals = [], [], []
    for r in range(3):
        for c in range(3):
            row = I * 9 + r * 3 + c
            rows += [row, row]
            cols += [J * 3 + r, I * 3 + r]
            vals += [G[:, c], -G[:, c]]
    return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                         shape=(9 * N, 3 * N))


def elasticity(lam, mu):
    C = np.zeros((9, 9))
    for r in range(3):
        for c in range(3):
            for k in range(3):
                for l in range(3):
                    C[r * 3 + c, k * 3 + l] = (lam * (r == c) * (k == l) +
                                               mu * ((r == k) * (c == l) + (r == l) * (c == k)))
    return sp.csr_matrix(C)


def stiffness(X, V, Ve, dx, scheme, lam, mu):
    """K of the particles X (neighbour volumes V, energy weights Ve: 0 for images)."""
    h = scheme.get('coefh', 1.0) * np.sqrt(3) * dx
    I, J, G, Hs = operators(X, V, h, scheme.get('kernel', 'wendland'), scheme['gradient'])
    N = len(X)
    C = elasticity(lam, mu)
    B = bmatrix(N, I, J, G)
    if scheme.get('quadrature', 'node') == 'node':
        return (B.T @ sp.kron(sp.diags(Ve), C) @ B).tocsr()
    # a linear F over the cell: the six face points F +- (dx/2) dF/dX_a, weight 1/6 each, give
    # V (psi(F) + dx^2/24 sum_a dF_a : C : dF_a), the strain-gradient term of body_quadratic.c
    K = None
    for a in range(3):
        Ba = bmatrix(N, I, J, Hs[:, a, :])
        for s in (1, -1):
            Bf = B + s * dx / 2 * Ba
            k = Bf.T @ sp.kron(sp.diags(Ve / 6), C) @ Bf
            K = k if K is None else K + k
    return K.tocsr()


def hourglass(X, V, dx, scheme, lam, mu):
    """The linearised hourglass penalty of `hourglass alpha` (templates/body_particle.c,
    Ganzenmueller 2015) as a matrix Kh, f = -Kh u: for every pair (i, j), X = X_j - X_i,
    s = X . ((grad u_i + grad u_j) X - 2 (u_j - u_i)) and the force on i
    -(alpha E / 2) V^2 W(r) s X / r^4 (on j the opposite).  Not symmetric in general."""
    alpha = scheme.get('hourglass', 0.0)
    h = scheme.get('coefh', 1.0) * np.sqrt(3) * dx
    kind = scheme.get('kernel', 'wendland')
    I, J, G, _ = operators(X, V, h, kind, scheme['gradient'])
    N, P = len(X), len(I)
    B = bmatrix(N, I, J, G)
    d = X[J] - X[I]
    r = np.linalg.norm(d, axis=1)
    W, _ = kernel(kind, r, h)
    E = mu * (3 * lam + 2 * mu) / (lam + mu)
    c = 0.5 * alpha * E * V[I] * V[J] * W / r**4
    rows = np.repeat(np.arange(P), 9)
    xx = (d[:, :, None] * d[:, None, :]).reshape(-1)
    cols_i = (I[:, None] * 9 + np.arange(9)).reshape(-1)
    cols_j = (J[:, None] * 9 + np.arange(9)).reshape(-1)
    A = sp.csr_matrix((np.concatenate([xx, xx]), (np.concatenate([rows, rows]),
                       np.concatenate([cols_i, cols_j]))), shape=(P, 9 * N))
    rows3 = np.repeat(np.arange(P), 3)
    Dm = sp.csr_matrix((np.concatenate([-2 * d.reshape(-1), 2 * d.reshape(-1)]),
                        (np.concatenate([rows3, rows3]),
                         np.concatenate([(J[:, None] * 3 + np.arange(3)).reshape(-1),
                                         (I[:, None] * 3 + np.arange(3)).reshape(-1)]))),
                       shape=(P, 3 * N))
    S = A @ B + Dm
    Pm = sp.csr_matrix((d.reshape(-1), ((I[:, None] * 3 + np.arange(3)).reshape(-1), rows3)),
                       shape=(3 * N, P))
    return (Pm @ sp.diags(c) @ S).tocsr()


def clamped_system(X, dx, scheme, lam, mu, clamp_x=0.0):
    """K reduced to the particles in front of the plane x = clamp_x: held (behind it zero) or
    with images (behind it minus the mirror particle's displacement, no energy).  Returns the
    reduced K, the map T from reduced to all displacements, and the free particles' mask."""
    N = len(X)
    V = np.full(N, dx**3)
    free = X[:, 0] > clamp_x
    images = scheme.get('clamp', 'held') == 'images'
    Ve = np.where(free, V, 0.0) if images else V
    K = stiffness(X, V, Ve, dx, scheme, lam, mu)
    if scheme.get('hourglass', 0.0) > 0:
        K = K + hourglass(X, V, dx, scheme, lam, mu)
    idx = np.where(free)[0]
    key = {tuple(np.round(X[i] / dx * 2).astype(int)): k for k, i in enumerate(idx)}
    rows, cols, vals = [], [], []
    for k, i in enumerate(idx):
        for c in range(3):
            rows.append(3 * i + c), cols.append(3 * k + c), vals.append(1.0)
    if images:
        for i in np.where(~free)[0]:
            y = X[i].copy()
            y[0] = 2 * clamp_x - y[0]
            k = key[tuple(np.round(y / dx * 2).astype(int))]
            for c in range(3):
                rows.append(3 * i + c), cols.append(3 * k + c), vals.append(-1.0)
    T = sp.csr_matrix((vals, (rows, cols)), shape=(3 * N, 3 * len(idx)))
    return (T.T @ K @ T).tocsc(), T, free


def lame(E, nu):
    return E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))


def cantilever(L, t, n, scheme, E=1.0, nu=0.3, layers=4):
    """The square cantilever of tests/physics/bending5.sph: L long, t x t, n particles through
    t, `layers` of particles behind the clamp, a total force -1 in z over the last layer;
    returns that layer's mean u_z (bench/fe-references/cantilever_static.py's slab_mean)."""
    dx = t / n
    X = box_lattice([-layers * dx, 0, 0], [L, t, t], dx)
    K, T, free = clamped_system(X, dx, scheme, *lame(E, nu))
    last = X[:, 0] > L - dx
    f = np.zeros((len(X), 3))
    f[last, 2] = -1.0 / last.sum()
    u = (T @ spl.spsolve(K, T.T @ f.reshape(-1))).reshape(-1, 3)
    return u[last, 2].mean()


def plate_period(dx, scheme, layers=1, mu=0.715e6, K=3.25e6, rho=1000.0):
    """The first bending period of cases/plate3d.sph's plate (0.2 x 0.06 x 0.02 m) clamped on
    x = 0 with `layers` of particles behind it: the lowest mode of K phi = w^2 M phi."""
    lam = K - 2 * mu / 3
    X = box_lattice([-layers * dx, 0, 0], [0.2, 0.06, 0.02], dx)
    Kr, T, free = clamped_system(X, dx, scheme, lam, mu)
    M = sp.diags(np.full(Kr.shape[0], rho * dx**3))
    w2, phi = spl.eigsh(Kr, k=3, M=M, sigma=0, which='LM')
    for k in np.argsort(w2):  # the first mode whose motion is mostly along z
        if np.argmax(np.abs(phi[:, k]).reshape(-1, 3).sum(axis=0)) == 2:
            return 2 * np.pi / np.sqrt(w2[k])
    return float('nan')
