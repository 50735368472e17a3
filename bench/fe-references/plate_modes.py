#!/usr/bin/python3
"""Natural frequencies of a clamped thick plate strip (3D linear elasticity).

Problem
  body      x in [0, Lx], y in [0, b], z in [0, t]; defaults 0.2 x 0.06 x 0.02 m
  clamp     u = 0 on the face x = 0, all other faces traction-free
  material  rho = 1000 kg/m^3, shear modulus mu = 0.715e6 Pa,
            bulk modulus K = 3.25e6 Pa, i.e.
            E = 9 K mu / (3 K + mu),  nu = (3 K - 2 mu) / (2 (3 K + mu))

Small-strain free vibration: find (omega^2, u) with
  int sigma(u) : eps(v) dx = omega^2 int rho u . v dx   for all admissible v.
Discretised with Q2 (27-node) hexahedra, solved with SLEPc (generalised
Hermitian problem, shift-and-invert about 0, MUMPS LU).  The clamp is imposed
by assembling K with identity rows/columns on the constrained dofs and M with
zero rows/columns there: those dofs then carry infinite eigenvalues and never
show up near the shift, so no spurious eigenvalues need filtering.

Each computed mode is characterised by
  kinetic-energy fractions  e_i = int rho u_i^2 / int rho |u|^2 (i = x, y, z)
  effective-mass fractions  m_i = (int rho u_i)^2 / (int rho |u|^2 * mass)
  torsional participation   m_rx = (int rho r x u . e_x)^2 / (int rho |u|^2 * J_x),
                            r measured from the cross-section centroid axis,
                            J_x = int rho ((y - b/2)^2 + (z - t/2)^2)
so that the first bending mode in z is the one with dominant u_z and a large
z effective mass (about 0.6 for a cantilever's first bending mode), the
lateral (y) bending mode has dominant u_y, and the torsion mode has
negligible effective mass in every direction.

Reference: Euler-Bernoulli first clamped-free mode,
  omega_1 = (1.8751 / Lx)^2 sqrt(E' I / (rho A)),  I = b t^3 / 12, A = b t,
with E' = E (plane stress / narrow beam) and E' = E / (1 - nu^2) (plane strain
/ wide plate), and T = 2 pi / omega_1.

Mesh level k has n0 2^k cells through the thickness, and proportionally
(roughly cubic cells) along y and x.  Richardson extrapolation over the last
three levels gives the converged value and an uncertainty.

Run:
  /usr/bin/python3 plate_modes.py                  # default: levels n = 1, 2, 4, 8
  /usr/bin/python3 plate_modes.py --n0 2 --levels 3 --nev 6
"""

import argparse
import gc
import math
import os
import resource
import sys
import time

import numpy as np
import ufl
from petsc4py import PETSc
from slepc4py import SLEPc
import dolfinx
import dolfinx.fem.petsc

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from fe_common import (graded_box, elasticity_forms, richardson, append_csv,  # noqa: E402
                       fixed_order_extrapolation, clamped_free_wedge_exponent)


def material(mu=0.715e6, K=3.25e6):
    E = 9.0 * K * mu / (3.0 * K + mu)
    nu = (3.0 * K - 2.0 * mu) / (2.0 * (3.0 * K + mu))
    return E, nu


def euler_bernoulli_periods(Lx, b, t, rho, E, nu):
    """First clamped-free bending period (z) for plane stress and plane strain."""
    I = b * t ** 3 / 12.0
    A = b * t
    out = {}
    for name, Ep in (("plane_stress", E), ("plane_strain", E / (1.0 - nu ** 2))):
        omega = 1.8751 ** 2 / Lx ** 2 * math.sqrt(Ep * I / (rho * A))
        out[name] = 2.0 * math.pi / omega
    return out


def classify(ex, ey, ez, mx, my, mz, mrx):
    """Short label for a mode from its energy and effective-mass fractions."""
    dom = "xyz"[int(np.argmax([ex, ey, ez]))]
    if max(mx, my, mz) < 0.02:
        if mrx > 0.2:
            return "torsion about x"
        return "higher mode (no net mass)"
    if dom == "z":
        return "bending in z (u_z dominant)"
    if dom == "y":
        return "bending in y (u_y dominant)"
    return "axial (u_x dominant)"


def solve_modes(Lx, b, t, rho, E, nu, nthick, nwidth, nlen, nev=6):
    mesh = graded_box([0.0, Lx], [nlen], b, t, nwidth, nthick)
    V = dolfinx.fem.VectorFunctionSpace(mesh, ("CG", 2))
    a, u, v, dx = elasticity_forms(V, E, nu)
    m = rho * ufl.inner(u, v) * dx

    fdim = 2
    clamp_facets = dolfinx.mesh.locate_entities_boundary(mesh, fdim, lambda x: np.isclose(x[0], 0.0))
    clamp_dofs = dolfinx.fem.locate_dofs_topological(V, fdim, clamp_facets)
    bc = dolfinx.fem.dirichletbc(np.zeros(3, dtype=PETSc.ScalarType), clamp_dofs, V)

    # Constrained dofs: identity block in K, zero block in M -> infinite eigenvalues.
    K = dolfinx.fem.petsc.assemble_matrix(dolfinx.fem.form(a), bcs=[bc], diagonal=1.0)
    K.assemble()
    M = dolfinx.fem.petsc.assemble_matrix(dolfinx.fem.form(m), bcs=[bc], diagonal=0.0)
    M.assemble()

    eps = SLEPc.EPS().create(mesh.comm)
    eps.setOperators(K, M)
    eps.setProblemType(SLEPc.EPS.ProblemType.GHEP)
    eps.setDimensions(nev=nev)
    eps.setTolerances(tol=1e-12, max_it=200)
    eps.setWhichEigenpairs(SLEPc.EPS.Which.TARGET_MAGNITUDE)
    eps.setTarget(0.0)
    st = eps.getST()
    st.setType(SLEPc.ST.Type.SINVERT)
    st.setShift(0.0)
    ksp = st.getKSP()
    ksp.setType("preonly")
    pc = ksp.getPC()
    pc.setType("lu")
    pc.setFactorSolverType("mumps")
    eps.solve()
    nconv = eps.getConverged()

    # Forms for the mode characterisation.
    uh = dolfinx.fem.Function(V)
    mass = rho * Lx * b * t
    comps = [uh.sub(i) for i in range(3)]
    f_e = [dolfinx.fem.form(rho * c * c * dx) for c in comps]
    f_m = [dolfinx.fem.form(rho * c * dx) for c in comps]
    xc = ufl.SpatialCoordinate(mesh)
    f_rx = dolfinx.fem.form(rho * ((xc[1] - 0.5 * b) * comps[2] - (xc[2] - 0.5 * t) * comps[1]) * dx)
    Jx = rho * Lx * b * t * (b ** 2 + t ** 2) / 12.0

    modes = []
    for i in range(nconv):
        lam = eps.getEigenpair(i, uh.vector)
        uh.x.scatter_forward()
        lam = lam.real
        if lam <= 0.0:
            continue
        e = [dolfinx.fem.assemble_scalar(f) for f in f_e]
        etot = sum(e)
        mi = [dolfinx.fem.assemble_scalar(f) ** 2 / (etot * mass) for f in f_m]
        ef = [x / etot for x in e]
        mrx = dolfinx.fem.assemble_scalar(f_rx) ** 2 / (etot * Jx)
        omega = math.sqrt(lam)
        modes.append({"omega2": lam, "f": omega / (2.0 * math.pi), "T": 2.0 * math.pi / omega,
                      "ex": ef[0], "ey": ef[1], "ez": ef[2], "mx": mi[0], "my": mi[1], "mz": mi[2],
                      "mrx": mrx, "kind": classify(*ef, *mi, mrx)})
    modes.sort(key=lambda d: d["omega2"])
    # Release PETSc/SLEPc objects (and the MUMPS factors) explicitly.
    pc.destroy()
    ksp.destroy()
    st.destroy()
    eps.destroy()
    K.destroy()
    M.destroy()
    gc.collect()
    ndofs = V.dofmap.index_map.size_global * V.dofmap.index_map_bs
    return modes, ndofs


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--Lx", type=float, default=0.2)
    ap.add_argument("--b", type=float, default=0.06)
    ap.add_argument("--t", type=float, default=0.02)
    ap.add_argument("--rho", type=float, default=1000.0)
    ap.add_argument("--mu", type=float, default=0.715e6)
    ap.add_argument("--K", type=float, default=3.25e6)
    ap.add_argument("--n0", type=int, default=1, help="cells through the thickness on the coarsest level")
    ap.add_argument("--levels", type=int, default=4)
    ap.add_argument("--nev", type=int, default=6, help="eigenpairs requested (first 4 are reported)")
    ap.add_argument("--csv", default=None, help="append rows to this CSV")
    args = ap.parse_args(argv)

    E, nu = material(args.mu, args.K)
    print(f"E = {E:.6e} Pa, nu = {nu:.6f}, rho = {args.rho:g}")
    eb = euler_bernoulli_periods(args.Lx, args.b, args.t, args.rho, E, nu)
    print(f"Euler-Bernoulli first z-bending period: plane stress T = {eb['plane_stress']:.6f} s,"
          f" plane strain T = {eb['plane_strain']:.6f} s")

    levels = []
    for k in range(args.levels):
        n = args.n0 * 2 ** k
        nw = max(1, int(round(n * args.b / args.t)))
        nl = max(1, int(round(n * args.Lx / args.t)))
        t0 = time.time()
        modes, ndofs = solve_modes(args.Lx, args.b, args.t, args.rho, E, nu, n, nw, nl, nev=args.nev)
        dt = time.time() - t0
        rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0 ** 2
        levels.append({"n": n, "dofs": ndofs, "modes": modes, "time": dt})
        print(f"level {k}: cells {nl} x {nw} x {n}, dofs {ndofs}, {dt:.1f} s, peak RSS {rss:.1f} GB")
        for j, md in enumerate(modes[:4]):
            print(f"   mode {j + 1}: f = {md['f']:.6f} Hz  T = {md['T']:.6f} s  "
                  f"KE frac (x,y,z) = ({md['ex']:.3f}, {md['ey']:.3f}, {md['ez']:.3f})  "
                  f"eff. mass (x,y,z,rot x) = ({md['mx']:.3f}, {md['my']:.3f}, {md['mz']:.3f}, {md['mrx']:.3f})  {md['kind']}")
        sys.stdout.flush()

    # Converged values of the first four modes (modes matched by order; the
    # ordering is checked to be the same character on every level).
    # Asymptotic convergence order of the eigenvalues, set by the clamp-edge
    # singularity: omega^2 (and f) errors ~ h^(2 lambda).
    p_th = 2.0 * clamped_free_wedge_exponent(nu)
    print()
    print("Converged natural frequencies (Richardson over the last three levels;"
          f" 'order {p_th:.3f}' = two finest levels with the clamp-singularity order 2 lambda)")
    rows = []
    nrep = min(4, min(len(lv["modes"]) for lv in levels))
    for j in range(nrep):
        kinds = {lv["modes"][j]["kind"] for lv in levels}
        fvals = [lv["modes"][j]["f"] for lv in levels]
        fe, p, unc = richardson(fvals)
        Te = 1.0 / fe
        Tunc = unc / fe ** 2
        kind = levels[-1]["modes"][j]["kind"]
        f_th = fixed_order_extrapolation(fvals, p_th)
        note = "" if len(kinds) == 1 else f" [character changes across levels: {sorted(kinds)}]"
        if len(fvals) >= 4:
            # Consistency check: the extrapolation from the previous three levels.
            fe2, p2, unc2 = richardson(fvals[:-1])
            note += f"  [levels 0..{len(fvals) - 2}: f = {fe2:.6f}, order {p2:.2f}]"
        print(f"  mode {j + 1}: f = {fe:.6f} +- {unc:.2g} Hz (order {p:.2f}),  T = {Te:.6f} +- {Tunc:.2g} s,"
              f"  {kind}{note}  [order {p_th:.3f}: f = {f_th:.6f}, T = {1.0 / f_th:.6f}]")
        rows.append((j + 1, kind, fvals, fe, p, unc, Te, Tunc, f_th))

    zb = [r for r in rows if r[1].startswith("bending in z")]
    if zb:
        j, kind, fvals, fe, p, unc, Te, Tunc, f_th = zb[0]
        print()
        print(f"First z-bending mode (mode {j}): T = {Te:.6f} s +- {Tunc:.2g} s  (f = {fe:.6f} Hz);"
              f"  with order {p_th:.3f}: T = {1.0 / f_th:.6f} s")
        print(f"  Euler-Bernoulli plane stress T = {eb['plane_stress']:.6f} s, plane strain T = {eb['plane_strain']:.6f} s")

    if args.csv:
        out = []
        for j, kind, fvals, fe, p, unc, Te, Tunc, f_th in rows:
            for k, (lv, fv) in enumerate(zip(levels, fvals)):
                out.append(["plate_modes", f"{args.Lx:g}", "", f"f_mode{j}", k, lv["n"], lv["dofs"],
                            f"{fv:.10e}", "Hz", "", "", kind])
            out.append(["plate_modes", f"{args.Lx:g}", "", f"f_mode{j}", "extrapolated", "", "",
                        f"{fe:.10e}", "Hz", f"{p:.3f}", f"{unc:.3e}", kind])
            out.append(["plate_modes", f"{args.Lx:g}", "", f"T_mode{j}", "extrapolated", "", "",
                        f"{Te:.10e}", "s", f"{p:.3f}", f"{Tunc:.3e}", kind])
            out.append(["plate_modes", f"{args.Lx:g}", "", f"f_mode{j}", "extrapolated_2lambda", "", "",
                        f"{f_th:.10e}", "Hz", f"{p_th:.3f}", f"{abs(f_th - fvals[-1]):.3e}",
                        kind + "; two finest levels, order 2 lambda"])
            out.append(["plate_modes", f"{args.Lx:g}", "", f"T_mode{j}", "extrapolated_2lambda", "", "",
                        f"{1.0 / f_th:.10e}", "s", f"{p_th:.3f}", f"{abs(1.0 / f_th - 1.0 / fvals[-1]):.3e}",
                        kind + "; two finest levels, order 2 lambda"])
        for name, T in eb.items():
            out.append(["plate_modes", f"{args.Lx:g}", "", f"T_euler_bernoulli_{name}", "", "", "",
                        f"{T:.10e}", "s", "", "", "first z-bending mode, beta L = 1.8751"])
        append_csv(args.csv, out)

if __name__ == "__main__":
    main()
