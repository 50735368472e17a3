#!/usr/bin/python3
"""Print the results of results.csv as Markdown tables (used for README.md).

Run after run_all.sh:  /usr/bin/python3 make_tables.py [results.csv]
"""

import csv
import sys
from collections import OrderedDict

QUANT = ("slab_mean", "point", "face_mean")


def load(path):
    with open(path, newline="") as fh:
        return list(csv.DictReader(fh))


def seq_of(note):
    return note.split("levels n = ")[-1].split(";")[0] if "levels n = " in note else ""


def fmt(v, digits=6):
    return f"{float(v):.{digits}g}"


def static_tables(rows, problem, scale=1.0, digits=7, spec=".2f"):
    # group per (L, s, sequence)
    groups = OrderedDict()
    for r in rows:
        if r["problem"] != problem:
            continue
        if r["quantity"] == "timoshenko":
            groups.setdefault(("tim", r["L"], r["s"]), r)
            continue
        key = (r["L"], r["s"], seq_of(r["note"]))
        groups.setdefault(key, {}).setdefault(r["quantity"], []).append(r)

    print(f"#### {problem}: extrapolated values (uncertainty = |extrapolated - finest|)\n")
    print("Each cell: observed-order Richardson ± |extrapolated − finest| / two-finest-level extrapolation"
          " with the singularity order 2λ.\n")
    print("| L | s | mesh n | slab mean | point (L-s/2, b/2, t/2) | end-face mean | Timoshenko |")
    print("|---|---|---|---|---|---|---|")
    for key, g in groups.items():
        if key[0] == "tim":
            continue
        L, s, seq = key
        tim = groups[("tim", L, s)]["value"]
        cells = []
        for q in QUANT:
            ext = [r for r in g[q] if r["level"] == "extrapolated"][0]
            th = [r for r in g[q] if r["level"] == "extrapolated_2lambda"][0]
            cells.append(f"{float(ext['value']) * scale:{spec}} ± {float(ext['uncertainty']) * scale:.2g}"
                         f" / {float(th['value']) * scale:{spec}}")
        print(f"| {L} | {s} | {seq} | " + " | ".join(cells) + f" | {float(tim) * scale:{spec}} |")
    print()
    print(f"#### {problem}: per-level values and observed orders\n")
    print("| L | s | quantity | " + "level values (coarse → fine) | observed order p |")
    print("|---|---|---|---|---|")
    for key, g in groups.items():
        if key[0] == "tim":
            continue
        L, s, seq = key
        for q in QUANT:
            lv = [r for r in g[q] if not r["level"].startswith("extrapolated")]
            ext = [r for r in g[q] if r["level"] == "extrapolated"][0]
            vals = ", ".join(f"{float(r['value']) * scale:.{digits + 1}g} (n={r['nthick']})" for r in lv)
            prev = [r for r in g[q] if r["level"] == "extrapolated_previous_levels"]
            pv = f" (levels 0-2: {prev[0]['observed_order']})" if prev else ""
            print(f"| {L} | {s} | {q} | {vals} | {ext['observed_order']}{pv} |")
    print()


def recommended(rows, problem, spec=".2f", unit=""):
    """One line per case from the refinement sequence with the finest mesh."""
    best = OrderedDict()
    for r in rows:
        if r["problem"] != problem or r["quantity"] not in QUANT or r["level"].startswith("extrapolated"):
            continue
        key = (r["L"], r["s"])
        n = int(r["nthick"])
        if key not in best or n > best[key][0]:
            best[key] = (n, seq_of(r["note"]))
    tim = {(r["L"], r["s"]): r["value"] for r in rows
           if r["problem"] == problem and r["quantity"] == "timoshenko"}
    print(f"#### {problem}: recommended values {unit}\n")
    print("Observed-order Richardson over the finest three levels ± |extrapolated − finest|;"
          " in brackets the two-finest-level extrapolation with the singularity order 2λ.\n")
    print("| L | s | meshes n | slab mean | point (L-s/2, b/2, t/2) | end-face mean | Timoshenko |")
    print("|---|---|---|---|---|---|---|")
    for (L, s), (n, seq) in sorted(best.items(), key=lambda kv: (float(kv[0][0]), -float(kv[0][1]))):
        cells = []
        for q in QUANT:
            sel = [r for r in rows if r["problem"] == problem and r["L"] == L and r["s"] == s
                   and r["quantity"] == q and seq_of(r["note"]) == seq]
            e = [r for r in sel if r["level"] == "extrapolated"][0]
            t = [r for r in sel if r["level"] == "extrapolated_2lambda"][0]
            cells.append(f"{float(e['value']):{spec}} ± {float(e['uncertainty']):.2g} ({float(t['value']):{spec}})")
        print(f"| {L} | {s} | {seq} | " + " | ".join(cells) + f" | {float(tim[(L, s)]):{spec}} |")
    print()


def plate_tables(rows):
    pr = [r for r in rows if r["problem"] == "plate_modes"]
    if not pr:
        return
    print("#### plate_modes: first four natural frequencies\n")
    print("| mode | character | f per level (n = 1, 2, 4, 8) [Hz] | f extrapolated [Hz] | order p | T [s] "
          "| f, T with order 2λ |")
    print("|---|---|---|---|---|---|---|")
    modes = OrderedDict()
    for r in pr:
        if r["quantity"].startswith("f_mode") or r["quantity"].startswith("T_mode"):
            modes.setdefault(r["quantity"][-1], []).append(r)
    for m, rs in modes.items():
        fl = [r for r in rs if r["quantity"].startswith("f_") and not r["level"].startswith("extrapolated")]
        fe = [r for r in rs if r["quantity"].startswith("f_") and r["level"] == "extrapolated"][0]
        te = [r for r in rs if r["quantity"].startswith("T_") and r["level"] == "extrapolated"][0]
        f2 = [r for r in rs if r["quantity"].startswith("f_") and r["level"] == "extrapolated_2lambda"][0]
        t2 = [r for r in rs if r["quantity"].startswith("T_") and r["level"] == "extrapolated_2lambda"][0]
        vals = ", ".join(f"{float(r['value']):.6f}" for r in fl)
        print(f"| {m} | {fe['note']} | {vals} | {float(fe['value']):.5f} ± {float(fe['uncertainty']):.2g} "
              f"| {fe['observed_order']} | {float(te['value']):.5f} ± {float(te['uncertainty']):.2g} "
              f"| {float(f2['value']):.5f} Hz, {float(t2['value']):.5f} s (p = {f2['observed_order']}) |")
    for r in pr:
        if r["quantity"].startswith("T_euler"):
            print(f"\n{r['quantity']}: T = {float(r['value']):.6f} s", end="")
    print("\n")


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "results.csv"
    rows = load(path)
    recommended(rows, "cantilever_static", unit="(u_z E t / |P|, P = -1)")
    recommended(rows, "bigbeam_static", spec=".5e", unit="(m/N)")
    static_tables(rows, "cantilever_static")
    static_tables(rows, "bigbeam_static", digits=6, spec=".5e")
    plate_tables(rows)


if __name__ == "__main__":
    main()
