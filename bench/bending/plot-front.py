#!/usr/bin/env python3
"""The plate's error-against-wall-time fronts, before and after, on one plot.

Reads build/bending/plate_front.csv (bench/bending/plate-front) and writes
build/bending/plate_front.png: |period error| against the run's wall time, log-log, one line
per scheme (eq. 63 with the clamp held; the quadratic gradient with the clamp by images), each
point labelled with its spacing and the particles through the thickness.  Needs matplotlib.

    python3 bench/bending/plot-front.py [CSV [PNG]]
"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

THICKNESS = 20e-3  # the plate's, m
LABELS = {"linear": "eq. 63, clamp held", "quadratic": "gradient quadratic, clamp by images"}


def main():
    src = sys.argv[1] if len(sys.argv) > 1 else "build/bending/plate_front.csv"
    dst = sys.argv[2] if len(sys.argv) > 2 else "build/bending/plate_front.png"
    runs = {}
    with open(src) as f:
        for row in csv.DictReader(f):
            runs.setdefault(row["scheme"], []).append(row)
    fig, ax = plt.subplots(figsize=(6, 4))
    for scheme, rows in runs.items():
        rows.sort(key=lambda r: float(r["wall_s"]))
        wall = [float(r["wall_s"]) for r in rows]
        err = [100 * abs(float(r["period_err"])) for r in rows]
        ax.loglog(wall, err, "o-", label=LABELS.get(scheme, scheme))
        for r, x, y in zip(rows, wall, err):
            dp = float(r["dp"])
            ax.annotate(f"dp {1e3 * dp:g} mm, n = {round(THICKNESS / dp)}", (x, y),
                        textcoords="offset points", xytext=(5, 4), fontsize=7)
    ax.set_xlabel("wall time of the run [s] (one thread)")
    ax.set_ylabel("|first period - FE| / FE [%]")
    ax.set_title("3D plate: error against run time")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    fig.savefig(dst, dpi=120)
    print(f"wrote {dst}")


if __name__ == "__main__":
    main()
