#!/usr/bin/python3
"""Static tip deflection of a clamped plane-strain cantilever loaded on an end slab (2D).

The x-z section of cantilever_static.py's problem in plane strain, per unit thickness:
x in [0, L], z in [0, t], u = 0 on x = 0, E = 1, nu = 0.3, t = 1, a total force P = -1 (per
unit thickness) in z as a uniform body force over the end slab x in [L - s, L].  Output: the
mean u_z over the slab, on nested Q2 quadrilateral meshes (n = n0 2^k cells through the
thickness, square cells, so x = L - s is a line of cell edges), with Richardson's
extrapolation (fe_common.richardson).  The continuum counterpart of a 2D sphc cantilever
with n particles through the thickness whose last layer carries the load
(tests/physics/bending2d.sph).

    /usr/bin/python3 cantilever_2d.py [--L 5] [--s 0.2] [--levels 4] [--n0 5]
"""
import argparse

import numpy as np
import ufl
from mpi4py import MPI
from petsc4py import PETSc
import dolfinx
import dolfinx.fem.petsc
from dolfinx.mesh import CellType, create_rectangle

from fe_common import lame, richardson


def slab_mean(L, s, n, t=1.0, E=1.0, nu=0.3, P=-1.0):
    """The mean u_z over the end slab on a mesh of n square Q2 cells through t."""
    h = t / n
    nx = int(round(L / h))
    mesh = create_rectangle(MPI.COMM_WORLD, [np.array([0.0, 0.0]), np.array([L, t])],
                            [nx, n], CellType.quadrilateral)
    V = dolfinx.fem.VectorFunctionSpace(mesh, ("Lagrange", 2))
    mu, lmbda = lame(E, nu)
    u, v = ufl.TrialFunction(V), ufl.TestFunction(V)

    def eps(w):
        return ufl.sym(ufl.grad(w))

    def sigma(w):  # plane strain: the 3D lambda
        return 2.0 * mu * eps(w) + lmbda * ufl.tr(eps(w)) * ufl.Identity(2)

    dx = ufl.Measure("dx", domain=mesh, metadata={"quadrature_degree": 4})
    x = ufl.SpatialCoordinate(mesh)
    slab = ufl.conditional(ufl.ge(x[0], L - s - 1e-12 * L), 1.0, 0.0)
    f = ufl.as_vector([0.0, P / (s * t)]) * slab
    a = ufl.inner(sigma(u), eps(v)) * dx
    rhs = ufl.inner(f, v) * dx
    dofs = dolfinx.fem.locate_dofs_geometrical(V, lambda X: np.isclose(X[0], 0.0))
    bc = dolfinx.fem.dirichletbc(np.zeros(2, dtype=PETSc.ScalarType), dofs, V)
    problem = dolfinx.fem.petsc.LinearProblem(a, rhs, bcs=[bc], petsc_options={
        "ksp_type": "preonly", "pc_type": "lu", "pc_factor_mat_solver_type": "mumps"})
    uh = problem.solve()
    mean = dolfinx.fem.assemble_scalar(dolfinx.fem.form(uh[1] * slab * dx)) / (s * t)
    return mean, V.dofmap.index_map.size_global * 2


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--L", type=float, default=5.0)
    ap.add_argument("--s", type=float, default=0.2)
    ap.add_argument("--levels", type=int, default=4)
    ap.add_argument("--n0", type=int, default=5)
    o = ap.parse_args()
    values = []
    for k in range(o.levels):
        n = o.n0 * 2**k
        m, dofs = slab_mean(o.L, o.s, n)
        values.append(m)
        print(f"  L/t = {o.L:g}, s = {o.s:g}, n = {n:3d}: dofs {dofs:8d}  slab mean u_z {m:.8g}",
              flush=True)
    ext, p, unc = richardson(values)
    print(f"  extrapolated {ext:.8g} +- {unc:.2g} (observed order {p:.3g})")


if __name__ == "__main__":
    main()
