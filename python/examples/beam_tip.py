#!/usr/bin/env python3
"""The cantilever beam's tip against its reference (docs/verification.md, "Cantilever beam").

Builds tests/physics/beam2d_coarse.sph, the oscillating beam of cases/beam2d.sph at
dx = 1 mm, runs it for a whole period (about a minute on two cores; ``--end 0.07``, a quarter
of one, for a quick look), and prints the deflection of the tip plane against the
plane-strain FE reference, 23.2 mm x sin(2 pi t / 0.2553 s), then the model's expectations
(its period and amplitude against that reference) as summary.json reports them (a run
shorter than a period has no period to compare: that one fails).  With matplotlib it also
plots both curves (``--plot FILE``), the figure of the beam in docs/verification.md.

    PYTHONPATH=python python3 python/examples/beam_tip.py --sphc build/sphc
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import sphc

ROOT = Path(__file__).resolve().parents[2]
PERIOD, AMPLITUDE = 0.2553, 23.2e-3  # the FE reference: s, m


def reference(t: float) -> float:
    """The tip's deflection of the FE reference at time t (the model's ``reference``)."""
    return AMPLITUDE * math.sin(2 * math.pi / PERIOD * t)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--end", type=float, default=0.3, help="end time [s] (default 0.3)")
    parser.add_argument("--out", default="beam_tip_out", help="output folder")
    parser.add_argument("--sphc", help="the sphc compiler (default: $SPHC, else PATH)")
    parser.add_argument("--plot", default="beam_tip.png", help="the plot's file (matplotlib)")
    parser.add_argument("--quiet", action="store_true", help="not the program's lines")
    args = parser.parse_args()

    program = sphc.build(ROOT / "tests" / "physics" / "beam2d_coarse.sph", sphc=args.sphc)
    run = sphc.run(program, out=args.out, end=args.end, overwrite=True, check=False,
                   echo=not args.quiet)
    if run.returncode not in (0, 1):  # (1: an expectation failed; reported below)
        run.check()
    results = run.load()
    tip = results.measurements["tip"]["uz"]

    print(f"\n{'t [ms]':>8} {'tip uz [mm]':>12} {'reference [mm]':>15} {'difference [mm]':>16}")
    for t in tip.index[:: max(1, len(tip) // 12)]:
        print(f"{1e3 * t:8.1f} {1e3 * tip[t]:12.3f} {1e3 * reference(t):15.3f}"
              f" {1e3 * (tip[t] - reference(t)):16.3f}")
    peak = tip.idxmax()
    print(f"\nlargest deflection {1e3 * tip[peak]:.2f} mm at {1e3 * peak:.1f} ms; "
          f"reference {1e3 * AMPLITUDE:.2f} mm at {1e3 * PERIOD / 4:.1f} ms")
    print(f"{results.summary['particles']} particles, {results.summary['steps']} steps "
          f"in {results.summary['wall_time']:.1f} s")
    if args.end < PERIOD:
        print("the model's expectations (a run shorter than a period cannot measure the "
              "period and amplitude: the default --end 0.3 runs a whole one):")
    for x in results.summary.get("expectations", []):
        error = x.get("relative_error")
        shown = "none" if error is None else f"{100 * error:.2f} %"
        print(f"  {x['model']}: relative error {shown} ({'ok' if x['pass'] else 'FAILED'})")

    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.plot(1e3 * tip.index, 1e3 * tip, label="sphc, tip plane uz")
    ax.plot(1e3 * tip.index, [1e3 * reference(t) for t in tip.index], "--",
            label="FE reference")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel("deflection [mm]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(args.plot, dpi=120)
    print(f"plot: {args.plot}")


if __name__ == "__main__":
    main()
