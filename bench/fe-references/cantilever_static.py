#!/usr/bin/python3
"""Static tip deflection of a clamped 3D cantilever loaded on an end slab.

Problem (small-strain isotropic linear elasticity, E = 1, nu = 0.3,
b = t = 1 by default):

  body     x in [0, L], y in [0, b], z in [0, t]
  clamp    u = 0 (all three components) on the face x = 0
  load     total force P (in z; P = -1 by default) applied as a uniform
           body force f = (0, 0, P / (s b t)) over the end slab x in [L - s, L];
           the rest of the body is unloaded, all other faces traction-free.

This is the continuum counterpart of an SPH cantilever with n particles
through the thickness whose last layer of particles (thickness s = t/n)
carries the tip load.

Outputs per case
  (a) slab_mean  mean u_z over the volume of the loaded slab
  (b) point      u_z at (L - s/2, b/2, t/2)
  (c) face_mean  mean u_z over the end face x = L
and the Timoshenko beam value  P Lr^3/(3 E I) + P Lr/(k G A),  Lr = L - s/2,
k = 5/6, which treats the slab load as a point load at the slab centroid.

Discretisation: Q2 (27-node) hexahedra.  The x-direction is split into the
unloaded part [0, L - s] and the slab [L - s, L], each meshed uniformly, so the
slab boundary is a plane of cell faces and the body-force integral is exact.
Level k has n0 * 2^k cells through the thickness (and width) and all cell
counts of level 0 multiplied by 2^k, so the meshes are nested.  The three (or
more) levels give a Richardson extrapolation; its difference to the finest
level is quoted as the discretisation uncertainty.

Run (serial, Debian's python3-dolfinx 0.5.2):
  /usr/bin/python3 cantilever_static.py                 # full default table
  /usr/bin/python3 cantilever_static.py --L 5 --s 0.2   # one case
  /usr/bin/python3 cantilever_static.py --L 10 20 --s 0.25 0.125 --levels 3
"""

import argparse
import gc
import os
import resource
import sys
import time

import numpy as np
import ufl
from petsc4py import PETSc
import dolfinx
import dolfinx.fem.petsc

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fe_common import (graded_box, elasticity_forms, richardson, point_value, append_csv,  # noqa: E402
                       rigid_body_modes, fixed_order_extrapolation, clamped_free_wedge_exponent)  # noqa: E402


def level0_cells(L, s, t, n0, aspect):
    """Cell counts of the coarsest mesh: (main-part x cells, slab x cells, n0).

    Target cell length along x is aspect * t / n0 (bending is smooth along x,
    the cross-section resolution controls the error)."""
    hx = aspect * t / n0
    n_main = max(1, int(round((L - s) / hx)))
    n_slab = max(1, int(round(s / hx)))
    return n_main, n_slab


# Above this many unknowns the direct solver needs more memory than a 24 GB
# machine has (the MUMPS factors grow like the cube of the cross-section
# resolution); there the solver switches to CG + smoothed-aggregation AMG.
DIRECT_MAX_DOFS = 400_000


def solve_linear(V, a, Lform, bc, solver="auto"):
    """Solve K u = f with the clamp imposed by lifting; returns the Function.

    solver: "lu" (MUMPS), "gamg" (CG preconditioned by PETSc GAMG with the
    rigid-body near-nullspace, relative residual 1e-11) or "auto"."""
    a_form, L_form = dolfinx.fem.form(a), dolfinx.fem.form(Lform)
    A = dolfinx.fem.petsc.assemble_matrix(a_form, bcs=[bc])
    A.assemble()
    rhs = dolfinx.fem.petsc.assemble_vector(L_form)
    dolfinx.fem.petsc.apply_lifting(rhs, [a_form], [[bc]])
    rhs.ghostUpdate(addv=PETSc.InsertMode.ADD, mode=PETSc.ScatterMode.REVERSE)
    dolfinx.fem.petsc.set_bc(rhs, [bc])

    ndofs = V.dofmap.index_map.size_global * V.dofmap.index_map_bs
    if solver == "auto":
        solver = "lu" if ndofs <= DIRECT_MAX_DOFS else "gamg"
    ksp = PETSc.KSP().create(V.mesh.comm)
    ksp.setOperators(A)
    pc = ksp.getPC()
    if solver == "lu":
        ksp.setType("preonly")
        pc.setType("lu")
        pc.setFactorSolverType("mumps")
    elif solver == "gamg":
        A.setNearNullSpace(rigid_body_modes(V))
        ksp.setType("cg")
        ksp.setTolerances(rtol=1e-11, atol=0.0, max_it=2000)
        pc.setType("gamg")
        opts = PETSc.Options()
        opts["pc_gamg_threshold"] = 0.02
        opts["mg_levels_ksp_type"] = "chebyshev"
        opts["mg_levels_pc_type"] = "jacobi"
        ksp.setFromOptions()
    else:
        raise ValueError(solver)
    uh = dolfinx.fem.Function(V)
    ksp.solve(rhs, uh.vector)
    if ksp.getConvergedReason() <= 0:
        raise RuntimeError(f"linear solver failed: reason {ksp.getConvergedReason()}")
    uh.x.scatter_forward()
    # petsc4py objects are not reliably freed by reference counting; release
    # the matrix and the factorisation / AMG hierarchy explicitly.
    pc.destroy()
    ksp.destroy()
    A.destroy()
    rhs.destroy()
    return uh


def solve_case(L, s, b=1.0, t=1.0, E=1.0, nu=0.3, P=-1.0, nthick=2, n_main=10,
               n_slab=1, nwidth=None, solver="auto"):
    """Solve one mesh level; return dict with the three deflections and dofs."""
    if nwidth is None:
        nwidth = max(1, int(round(nthick * b / t)))
    mesh = graded_box([0.0, L - s, L], [n_main, n_slab], b, t, nwidth, nthick)
    V = dolfinx.fem.VectorFunctionSpace(mesh, ("CG", 2))
    a, u, v, dx = elasticity_forms(V, E, nu)

    # Slab cells: all vertices in x >= L - s (exact: L - s is a mesh plane).
    tol = 1e-9 * L
    slab_cells = dolfinx.mesh.locate_entities(mesh, 3, lambda x: x[0] >= L - s - tol)
    ct = dolfinx.mesh.meshtags(mesh, 3, slab_cells, np.full(len(slab_cells), 1, dtype=np.int32))
    dxs = ufl.Measure("dx", domain=mesh, subdomain_data=ct, metadata={"quadrature_degree": 4})

    # End face x = L.
    fdim = 2
    end_facets = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[0], L))
    ft = dolfinx.mesh.meshtags(mesh, fdim, end_facets, np.full(len(end_facets), 2, dtype=np.int32))
    dse = ufl.Measure("ds", domain=mesh, subdomain_data=ft)

    # Load: uniform body force over the slab, total P in z.
    fz = P / (s * b * t)
    f = dolfinx.fem.Constant(mesh, PETSc.ScalarType((0.0, 0.0, fz)))
    Lform = ufl.inner(f, v) * dxs(1)

    # Clamp: u = 0 on x = 0.
    clamp_facets = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[0], 0.0))
    clamp_dofs = dolfinx.fem.locate_dofs_topological(V, fdim, clamp_facets)
    zero = np.zeros(3, dtype=PETSc.ScalarType)
    bc = dolfinx.fem.dirichletbc(zero, clamp_dofs, V)

    uh = solve_linear(V, a, Lform, bc, solver)
    uz = uh.sub(2)
    slab_int = dolfinx.fem.assemble_scalar(dolfinx.fem.form(uz * dxs(1)))
    slab_vol = dolfinx.fem.assemble_scalar(dolfinx.fem.form(
        dolfinx.fem.Constant(mesh, PETSc.ScalarType(1.0)) * dxs(1)))
    face_int = dolfinx.fem.assemble_scalar(dolfinx.fem.form(uz * dse(2)))
    face_area = dolfinx.fem.assemble_scalar(dolfinx.fem.form(
        dolfinx.fem.Constant(mesh, PETSc.ScalarType(1.0)) * dse(2)))
    assert abs(slab_vol - s * b * t) < 1e-9 * s * b * t, (slab_vol, s * b * t)
    assert abs(face_area - b * t) < 1e-9 * b * t
    res = {
        "slab_mean": slab_int / slab_vol,
        "point": point_value(uh, (L - 0.5 * s, 0.5 * b, 0.5 * t), 2),
        "face_mean": face_int / face_area,
        "dofs": V.dofmap.index_map.size_global * V.dofmap.index_map_bs,
    }
    del uh
    gc.collect()
    return res


def timoshenko(L, s, b=1.0, t=1.0, E=1.0, nu=0.3, P=-1.0, k=5.0 / 6.0):
    """Timoshenko cantilever deflection under a point load at Lr = L - s/2."""
    Lr = L - 0.5 * s
    I = b * t ** 3 / 12.0
    A = b * t
    G = E / (2.0 * (1.0 + nu))
    return P * Lr ** 3 / (3.0 * E * I) + P * Lr / (k * G * A)


QUANTITIES = ("slab_mean", "point", "face_mean")


def converge_case(L, s, b=1.0, t=1.0, E=1.0, nu=0.3, P=-1.0, n0=2, levels=3,
                  aspect=1.0, label=None, log=print, solver="auto"):
    """Run the nested refinement sequence for one case.

    Returns the list of per-level dicts and a dict of extrapolations:
      ext[q]         = (value, observed order, |value - finest|)  Richardson over
                       the last three levels with the observed order
      ext["theory"][q] = (value, 2 lambda, |value - finest|)  two finest levels
                       with the asymptotic order 2 lambda of the clamp-edge
                       singularity (see fe_common.clamped_free_wedge_exponent)
      ext["prev"][q] = observed-order Richardson over the previous three
                       levels (only with four or more levels), as a check."""
    n_main0, n_slab0 = level0_cells(L, s, t, n0, aspect)
    rows = []
    for k in range(levels):
        m = 2 ** k
        t0 = time.time()
        r = solve_case(L, s, b=b, t=t, E=E, nu=nu, P=P, nthick=n0 * m,
                       n_main=n_main0 * m, n_slab=n_slab0 * m,
                       nwidth=max(1, int(round(n0 * m * b / t))), solver=solver)
        r["time"] = time.time() - t0
        r["maxrss_gb"] = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0 ** 2
        r["level"] = k
        r["nthick"] = n0 * m
        r["nx"] = (n_main0 + n_slab0) * m
        r["nslab"] = n_slab0 * m
        rows.append(r)
        log(f"  {label or ''} level {k}: cells x/slab/thick = {r['nx']}/{r['nslab']}/{r['nthick']}"
            f"  dofs {r['dofs']:8d}  slab {r['slab_mean']:.8g}  point {r['point']:.8g}"
            f"  face {r['face_mean']:.8g}  ({r['time']:.1f} s, peak RSS {r['maxrss_gb']:.1f} GB)")
        sys.stdout.flush()
    ext = {q: richardson([r[q] for r in rows]) for q in QUANTITIES}
    p_th = 2.0 * clamped_free_wedge_exponent(nu)
    ext["theory"] = {}
    for q in QUANTITIES:
        vals = [r[q] for r in rows]
        fx = fixed_order_extrapolation(vals, p_th)
        ext["theory"][q] = (fx, p_th, abs(fx - vals[-1]))
    if levels >= 4:
        ext["prev"] = {q: richardson([r[q] for r in rows][:-1]) for q in QUANTITIES}
    return rows, ext


def print_extrapolations(ext, fmt=".7g"):
    for q in QUANTITIES:
        e, p, unc = ext[q]
        ft, pt, ut = ext["theory"][q]
        line = (f"    {q:9s}: extrapolated {e:{fmt}} +- {unc:.2g} (observed order {p:.2f});"
                f"  with order {pt:.3f}: {ft:{fmt}}")
        if "prev" in ext:
            e2, p2, u2 = ext["prev"][q]
            line += f";  previous three levels: {e2:{fmt}} (order {p2:.2f})"
        print(line)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--L", type=float, nargs="+", default=[5.0, 10.0, 20.0],
                    help="beam lengths (t = b = 1, so L = L/t)")
    ap.add_argument("--s", type=float, nargs="+", default=[0.25, 0.2, 0.125, 0.1],
                    help="loaded slab thicknesses")
    ap.add_argument("--levels", type=int, default=3, help="number of mesh levels (>= 3 for extrapolation)")
    ap.add_argument("--n0", type=int, default=2, help="cells through the thickness on the coarsest level")
    ap.add_argument("--aspect", type=float, default=1.0, help="x cell length / cross-section cell size on the main part")
    ap.add_argument("--solver", choices=("auto", "lu", "gamg"), default="auto",
                    help="linear solver: MUMPS LU, CG+GAMG, or auto (LU up to %d unknowns)" % DIRECT_MAX_DOFS)
    ap.add_argument("--csv", default=None, help="append per-level and extrapolated rows to this CSV")
    args = ap.parse_args(argv)

    summary = []
    for L in args.L:
        for s in args.s:
            print(f"case L/t = {L:g}, s = {s:g}")
            rows, ext = converge_case(L, s, n0=args.n0, levels=args.levels, aspect=args.aspect,
                                      label=f"L={L:g} s={s:g}", solver=args.solver)
            tim = timoshenko(L, s)
            summary.append((L, s, rows, ext, tim))
            print_extrapolations(ext)
            print(f"    Timoshenko (Lr = L - s/2): {tim:.7g}")
            if args.csv:
                write_csv(args.csv, "cantilever_static", L, s, rows, ext, tim,
                          unit="u_z * E * t / |P|")

    print()
    print("Summary: u_z (E = 1, nu = 0.3, b = t = 1, P = -1); extrapolated +- uncertainty")
    print(f"{'L/t':>5} {'s':>6} {'slab mean':>22} {'point (L-s/2,b/2,t/2)':>24} {'end face mean':>22} {'Timoshenko':>12}")
    for L, s, rows, ext, tim in summary:
        cols = [f"{ext[q][0]:.2f} +- {ext[q][2]:.1e}" for q in QUANTITIES]
        print(f"{L:5g} {s:6g} {cols[0]:>22} {cols[1]:>24} {cols[2]:>22} {tim:12.6f}")


def write_csv(path, problem, L, s, rows, ext, tim, unit="", note=""):
    """Append per-level values, the extrapolations and the Timoshenko value."""
    seq = "levels n = " + ",".join(str(r["nthick"]) for r in rows)
    note = (note + "; " if note else "") + seq
    out = []
    for q in QUANTITIES:
        for r in rows:
            out.append([problem, f"{L:g}", f"{s:g}", q, r["level"], r["nthick"], r["dofs"],
                        f"{r[q]:.10e}", unit, "", "", note])
        e, p, unc = ext[q]
        out.append([problem, f"{L:g}", f"{s:g}", q, "extrapolated", "", "",
                    f"{e:.10e}", unit, f"{p:.3f}", f"{unc:.3e}", note])
        e, p, unc = ext["theory"][q]
        out.append([problem, f"{L:g}", f"{s:g}", q, "extrapolated_2lambda", "", "",
                    f"{e:.10e}", unit, f"{p:.3f}", f"{unc:.3e}", note + "; two finest levels, order 2 lambda"])
        if "prev" in ext:
            e, p, unc = ext["prev"][q]
            out.append([problem, f"{L:g}", f"{s:g}", q, "extrapolated_previous_levels", "", "",
                        f"{e:.10e}", unit, f"{p:.3f}", f"{unc:.3e}", note + "; levels 0..N-2 (check)"])
    out.append([problem, f"{L:g}", f"{s:g}", "timoshenko", "", "", "",
                f"{tim:.10e}", unit, "", "", "Lr = L - s/2, k = 5/6"])
    append_csv(path, out)


if __name__ == "__main__":
    main()
