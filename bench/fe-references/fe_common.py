"""Shared helpers for the finite-element reference computations.

Everything here targets DOLFINx 0.5.2 (Debian bookworm's python3-dolfinx);
later DOLFINx releases renamed several of the calls used below.

Contents
  graded_box       hexahedral box mesh whose x-planes sit at prescribed
                   breakpoints (so that e.g. the loaded end slab x >= L - s is
                   exactly a union of cells)
  elasticity_forms small-strain isotropic linear elasticity bilinear form
  richardson       Richardson extrapolation of a sequence computed on meshes
                   refined by a factor 2 each time
"""

import csv
import logging
import math
import os

import numpy as np
import ufl
from mpi4py import MPI
import dolfinx
from dolfinx.mesh import CellType, create_box

# FFCx/cffi report every JIT compilation at INFO level; keep the output readable.
logging.disable(logging.INFO)


def graded_box(x_breaks, x_cells, y1, z1, ny, nz, comm=MPI.COMM_WORLD):
    """Hexahedral mesh of [x_breaks[0], x_breaks[-1]] x [0, y1] x [0, z1].

    The x-direction is split into pieces [x_breaks[i], x_breaks[i+1]] each
    divided uniformly into x_cells[i] cells.  The mesh is built on a unit-
    spaced index box and its x-coordinates are mapped piecewise linearly, so
    every breakpoint is a plane of cell faces and every cell stays a
    rectangular brick (affine geometry).
    """
    nx = int(sum(x_cells))
    mesh = create_box(comm, [np.array([0.0, 0.0, 0.0]), np.array([float(nx), y1, z1])],
                      [nx, ny, nz], CellType.hexahedron)
    idx_breaks = np.concatenate([[0.0], np.cumsum(x_cells).astype(float)])
    x = mesh.geometry.x
    x[:, 0] = np.interp(x[:, 0], idx_breaks, np.asarray(x_breaks, dtype=float))
    return mesh


def lame(E, nu):
    """Lame parameters (mu, lambda) from Young's modulus and Poisson ratio."""
    mu = E / (2.0 * (1.0 + nu))
    lmbda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return mu, lmbda


def elasticity_forms(V, E, nu, qdeg=4):
    """Stiffness bilinear form a(u, v) = int sigma(u) : eps(v) dx.

    qdeg = 4 (3x3x3 Gauss points on bricks) integrates the Q2 stiffness and
    mass matrices exactly on affine hexahedra.
    """
    mu, lmbda = lame(E, nu)
    u = ufl.TrialFunction(V)
    v = ufl.TestFunction(V)

    def eps(w):
        return ufl.sym(ufl.grad(w))

    def sigma(w):
        return 2.0 * mu * eps(w) + lmbda * ufl.tr(eps(w)) * ufl.Identity(3)

    dx = ufl.Measure("dx", domain=V.mesh, metadata={"quadrature_degree": qdeg})
    a = ufl.inner(sigma(u), eps(v)) * dx
    return a, u, v, dx


def richardson(values, ratio=2.0):
    """Richardson extrapolation from the last three values of a sequence.

    values are results on successively refined meshes (h, h/ratio, ...).
    Returns (extrapolated value, observed order p, uncertainty) where the
    uncertainty is |extrapolated - finest|.  If the last two differences do not
    have the same sign (non-monotone convergence) or the observed order is
    outside [0.5, 8], the extrapolation is not trusted: the finest value is
    returned as the estimate and the uncertainty is the last difference
    (p reported as nan).
    """
    if len(values) < 3:
        return float("nan"), float("nan"), float("nan")
    f1, f2, f3 = values[-3:]
    d1, d2 = f2 - f1, f3 - f2
    if d2 == 0.0:
        return f3, float("inf"), 0.0
    if d1 * d2 <= 0.0:
        return f3, float("nan"), abs(d2)
    p = math.log(abs(d1 / d2)) / math.log(ratio)
    if not (0.5 <= p <= 8.0):
        return f3, float("nan"), abs(d2)
    fext = f3 + d2 / (ratio ** p - 1.0)
    return fext, p, abs(fext - f3)


def fixed_order_extrapolation(values, p, ratio=2.0):
    """Richardson extrapolation of the two finest values with a prescribed order p."""
    f2, f3 = values[-2:]
    return f3 + (f3 - f2) / (ratio ** p - 1.0)


def clamped_free_wedge_exponent(nu, angle=math.pi / 2):
    """Leading singular exponent lambda of a clamped-free elastic wedge.

    Near the edge where the clamped face meets a free face the displacement
    behaves like r^lambda, the root in (1/2, 1) of the plane-strain
    characteristic equation (Williams 1952)
        (3 - 4 nu) sin^2(lambda w) = 4 (1 - nu)^2 - lambda^2 sin^2(w).
    Energy-type quantities (compliance, the load-weighted deflection,
    eigenvalues) then converge like h^(2 lambda) under uniform refinement:
    2 lambda = 1.422 for nu = 0.3 and 1.303 for nu = 0.3975.
    """
    kappa = 3.0 - 4.0 * nu

    def f(lam):
        return kappa * math.sin(lam * angle) ** 2 - (4.0 * (1.0 - nu) ** 2 - lam ** 2 * math.sin(angle) ** 2)

    lo, hi = 0.5, 0.999
    if f(lo) * f(hi) > 0.0:
        raise ValueError("no real root in (1/2, 1)")
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(lo) * f(mid) <= 0.0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


def rigid_body_modes(V):
    """Near-nullspace (six rigid-body modes) of a 3D vector space, for GAMG."""
    import dolfinx.la
    from petsc4py import PETSc
    im = V.dofmap.index_map
    n = im.size_local
    x = V.tabulate_dof_coordinates()[:n]
    vecs = [dolfinx.la.create_petsc_vector(im, 3) for _ in range(6)]
    modes = [np.zeros((n, 3)) for _ in range(6)]
    for i in range(3):
        modes[i][:, i] = 1.0                                   # translations
    modes[3][:, 0], modes[3][:, 1] = -x[:, 1], x[:, 0]         # rotation about z
    modes[4][:, 0], modes[4][:, 2] = x[:, 2], -x[:, 0]         # rotation about y
    modes[5][:, 1], modes[5][:, 2] = -x[:, 2], x[:, 1]         # rotation about x
    for vec, m in zip(vecs, modes):
        with vec.localForm() as loc:
            loc.set(0.0)
        vec.array[:3 * n] = m.ravel()
    dolfinx.la.orthonormalize(vecs)
    return PETSc.NullSpace().create(vectors=vecs)


def point_value(u, point, comp):
    """Value of component comp of the FE function u at a single point (serial)."""
    mesh = u.function_space.mesh
    tree = dolfinx.geometry.BoundingBoxTree(mesh, mesh.topology.dim)
    pts = np.array([point], dtype=np.float64)
    cand = dolfinx.geometry.compute_collisions(tree, pts)
    cells = dolfinx.geometry.compute_colliding_cells(mesh, cand, pts)
    links = cells.links(0)
    if len(links) == 0:
        raise RuntimeError(f"point {point} not found in mesh")
    val = u.eval(pts, np.array([links[0]], dtype=np.int32))
    return float(np.asarray(val).reshape(len(pts), -1)[0, comp])


# Common layout of results.csv (one row per mesh level, plus one row per
# extrapolated value and per analytical comparison value).
CSV_HEADER = ["problem", "L", "s", "quantity", "level", "nthick", "dofs", "value", "unit",
              "observed_order", "uncertainty", "note"]


def append_csv(path, rows):
    """Append rows (lists in CSV_HEADER order) to path, writing the header if new."""
    new = not os.path.exists(path)
    with open(path, "a", newline="") as fh:
        w = csv.writer(fh)
        if new:
            w.writerow(CSV_HEADER)
        for r in rows:
            w.writerow(r)
