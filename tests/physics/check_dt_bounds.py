"""What bounded the time step, on tests/physics/dt_bounds.sph (standard library only).

    check_dt_bounds.py PROGRAM OUT A

runs PROGRAM --quiet --overwrite --out OUT (a block under an acceleration of A m/s^2 moving
rigidly, and a block at rest): the time step is sqrt(h / A) (eq. 66, "acceleration") until
t* = (sqrt(h A) - c0) / A, h / (c0 + A t) (eq. 65, "speed") after it, the first step's
"speed" (no acceleration known yet); the block at rest sets none.  Checks summary.json's
time_step_bounds and the page's plot of each interval's shares against that, away from
t* by an output interval; and the page against the files (check_report.check_page).
"""
import json
import os
import subprocess
import sys

import check_report


def main():
    program, out, accel = sys.argv[1], sys.argv[2], float(sys.argv[3])
    run = subprocess.run([program, "--quiet", "--overwrite", "--out", out],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if run.returncode != 0:
        sys.exit(f"{program} exited {run.returncode}:\n{run.stdout}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "summary.html"), encoding="utf-8") as f:
        text = f.read()
    errors = check_report.check_page(text, out, summary)[0]
    block = next(b for b in summary["bodies"] if b["name"] == "block")
    h, c0 = block["h"], block["c0"]
    t_star = ((h * accel) ** 0.5 - c0) / accel
    bounds = summary["time_step_bounds"]
    if bounds["counted"] != summary["steps"] or bounds["bodies"] != {
            "block": summary["steps"], "still": 0}:
        errors.append(f"time_step_bounds {bounds}: not every one of {summary['steps']} steps "
                      f"set by the block")
    root = check_report.ET.fromstring(text)
    shares = next(s for s in root.iter(check_report.SVG + "svg")
                  if s.get("id") == "time-step-shares")
    lines = {l.get("data-column"): check_report.line_values(l)
             for l in shares.iter(check_report.SVG + "polyline")}
    if set(lines) != {"speed", "acceleration"}:
        errors.append(f"the bounds plotted are {sorted(lines)}, not acceleration and speed")
    else:
        times = check_report.energy_times(out)
        margin = times[1] - times[0]
        checked = 0
        for k, (t0, t1) in enumerate(zip(times, times[1:])):
            want = "speed" if k == 0 or t0 > t_star + margin else (
                "acceleration" if t1 < t_star - margin else None)
            if want is None:
                continue
            checked += 1
            if lines[want][1][k] != 1:
                errors.append(f"the interval ({t0:g}, {t1:g}] s: {want} set "
                              f"{100 * lines[want][1][k]:g} % of its steps, not all "
                              f"(t* = {t_star:g} s)")
        if checked < len(times) - 4:
            errors.append(f"only {checked} intervals checked of {len(times) - 1}")
    if errors:
        sys.exit("time step bounds:\n  " + "\n  ".join(errors))
    print(f"time step bounds: acceleration before t* = {t_star:.4g} s, speed after it: "
          f"{bounds['bounds']}")


if __name__ == "__main__":
    main()
