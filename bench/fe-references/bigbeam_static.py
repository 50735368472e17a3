#!/usr/bin/python3
"""Static deflection of the steel "big beam" cantilever, per newton of tip load.

Problem (small-strain isotropic linear elasticity, SI units)
  body     x in [0, 0.1] m, y in [0, 0.01] m, z in [0, 0.01] m
  clamp    u = 0 on x = 0
  material E = 210 GPa, nu = 0.3
  load     total force P = -1 N in z as a uniform body force over the end slab
           x in [0.1 - s, 0.1], for s = 1 mm and s = 2 mm (the last one or two
           particle layers of a 10-particle-thick SPH model)

Outputs (m per N): mean u_z over the slab, u_z at (L - s/2, b/2, t/2), mean
u_z over the end face x = L, the Richardson-extrapolated values with their
uncertainty, and the Timoshenko value P Lr^3/(3EI) + P Lr/(kGA), Lr = L - s/2.

The computation is the one of cantilever_static.py in physical units; by
linearity and similarity it equals the dimensionless L/t = 10 result with
s/t = 0.1 and 0.2 scaled by 1 / (E t), which the script checks.

Run:  /usr/bin/python3 bigbeam_static.py [--levels 3] [--csv results.csv]
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from cantilever_static import converge_case, timoshenko, write_csv, print_extrapolations, QUANTITIES  # noqa: E402

L, B, T = 0.1, 0.01, 0.01
E, NU, P = 210e9, 0.3, -1.0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--s", type=float, nargs="+", default=[0.001, 0.002], help="slab thicknesses [m]")
    ap.add_argument("--levels", type=int, default=3)
    ap.add_argument("--n0", type=int, default=2)
    ap.add_argument("--csv", default=None)
    args = ap.parse_args(argv)

    summary = []
    for s in args.s:
        print(f"case s = {s * 1e3:g} mm")
        rows, ext = converge_case(L, s, b=B, t=T, E=E, nu=NU, P=P, n0=args.n0,
                                  levels=args.levels, label=f"s={s * 1e3:g}mm")
        tim = timoshenko(L, s, b=B, t=T, E=E, nu=NU, P=P)
        summary.append((s, rows, ext, tim))
        print_extrapolations(ext, fmt=".7e")
        print(f"    Timoshenko: {tim:.7e} m/N")
        # Similarity check against the dimensionless problem (E = t = 1, P = -1).
        print(f"    dimensionless equivalent (x E t): slab mean {ext['slab_mean'][0] * E * T:.6f}")
        if args.csv:
            write_csv(args.csv, "bigbeam_static", L, s, rows, ext, tim, unit="m/N")

    print()
    print("Summary: u_z per newton [m/N] (E = 210 GPa, nu = 0.3, 0.1 x 0.01 x 0.01 m)")
    print(f"{'s [mm]':>7} {'slab mean':>26} {'point (L-s/2,b/2,t/2)':>26} {'end face mean':>26} {'Timoshenko':>14}")
    for s, rows, ext, tim in summary:
        cols = [f"{ext[q][0]:.6e} +- {ext[q][2]:.1e}" for q in QUANTITIES]
        print(f"{s * 1e3:7g} {cols[0]:>26} {cols[1]:>26} {cols[2]:>26} {tim:14.6e}")


if __name__ == "__main__":
    main()
