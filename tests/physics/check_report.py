"""The report page, summary.html, against the files it reports (Python's standard library only).

    check_report.py [--exit N] [--launcher WORDS] PROGRAM OUT [ARGS...]

runs PROGRAM --quiet --overwrite --out OUT ARGS (it must exit 0, or N; WORDS, separated by
commas, start it: mpirun and its flags), then checks OUT/summary.html:
it is well-formed XML (XHTML); its verdict says how summary.json says the run ended; its
table has each expectation of summary.json with its result and relative error; every plotted
line's values (data-x, data-y: the rows data-stride picks) are those of its CSV file, row by
row, and it draws one point for each finite pair; energies.csv has a plot with every column,
each measure_*.csv one.  Then it checks that the comparison itself fails on a page with one
number changed.
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

XHTML = "{http://www.w3.org/1999/xhtml}"
SVG = "{http://www.w3.org/2000/svg}"


def same(a, b):
    return a == b or (math.isnan(a) and math.isnan(b))


def drawn_rows(n, stride):
    rows = list(range(0, n, stride))
    if n and rows[-1] != n - 1:
        rows.append(n - 1)
    return rows


def check_plots(root, out, prefix=False):
    """The errors of the page's plots against the CSV files of folder out (prefix: a page
    written during the run, against the files' first rows, as many as it says)."""
    errors, plotted = [], {}
    for svg in root.iter(SVG + "svg"):
        name = svg.get("data-csv")
        if name is None:  # (the time step and its bounds: checked in check_page)
            continue
        with open(os.path.join(out, name), newline="") as f:
            table = list(csv.reader(f))
        header, rows = table[0], [[float(v) for v in r] for r in table[1:]]
        if prefix and int(svg.get("data-rows")) <= len(rows):
            rows = rows[:int(svg.get("data-rows"))]
        if int(svg.get("data-rows")) != len(rows):
            errors.append(f"{name}: the page says {svg.get('data-rows')} rows, the file has "
                          f"{len(rows)}")
        picked = drawn_rows(len(rows), int(svg.get("data-stride")))
        for line in svg.iter(SVG + "polyline"):
            if line.get("data-expect") is not None:  # (check_curves)
                continue
            column = line.get("data-column")
            if column not in header:
                errors.append(f"{name}: no column {column}")
                continue
            k = header.index(column)
            plotted.setdefault(name, set()).add(column)
            xs = [float(v) for v in line.get("data-x").split()]
            ys = [float(v) for v in line.get("data-y").split()]
            if len(xs) != len(picked) or len(ys) != len(picked):
                errors.append(f"{name} {column}: {len(xs)} x and {len(ys)} y values for "
                              f"{len(picked)} rows drawn")
                continue
            for x, y, r in zip(xs, ys, picked):
                if not same(x, rows[r][0]) or not same(y, rows[r][k]):
                    errors.append(f"{name} {column}: row {r + 1} plotted as ({x}, {y}), the "
                                  f"file has ({rows[r][0]}, {rows[r][k]})")
                    break
            finite = sum(math.isfinite(x) and math.isfinite(y) for x, y in zip(xs, ys))
            if len(line.get("points").split()) != finite:
                errors.append(f"{name} {column}: {len(line.get('points').split())} points "
                              f"drawn for {finite} finite pairs")
    return errors, plotted


def line_values(line):
    return ([float(v) for v in line.get("data-x").split()],
            [float(v) for v in line.get("data-y").split()])


def check_bounds(root, summary):
    """The errors of what bounded the time step: the table's steps are summary.json's
    time_step_bounds (where given), each interval's shares, plotted at the time step's
    output times, add up to 1."""
    errors = []
    bounds = summary.get("time_step_bounds")
    table = [e for e in root.iter(XHTML + "table") if e.get("id") == "time-step-bounds"]
    if bounds and bounds["counted"] > 0:
        want = {("data-bound", k): v for k, v in bounds["bounds"].items() if v}
        want.update({("data-body", k): v for k, v in bounds["bodies"].items() if v})
        got = {}
        for row in (table[0].iter(XHTML + "tr") if table else []):
            for key in ("data-bound", "data-body"):
                if row.get(key) is not None:
                    got[(key, row.get(key))] = int("".join(list(row)[1].itertext()))
        if got != want:
            errors.append(f"the time step's bounds on the page {got}, in summary.json {want}")
    shares = [s for s in root.iter(SVG + "svg") if s.get("id") == "time-step-shares"]
    steps = [s for s in root.iter(SVG + "svg") if s.get("id") == "time-step"]
    if bool(shares) != bool(steps):
        errors.append(f"{len(shares)} plots of the bounds' shares, {len(steps)} of the time "
                      f"step")
    if not shares or not steps:
        return errors
    step_x = line_values(next(steps[0].iter(SVG + "polyline")))[0]
    lines = [line_values(line) for line in shares[0].iter(SVG + "polyline")]
    if not lines or any(xs != step_x for xs, _ in lines):
        errors.append("the shares of the bounds are not plotted at the time step's times")
    elif any(abs(sum(col) - 1) > 1e-12 for col in zip(*(ys for _, ys in lines))):
        errors.append("the shares of the bounds of an interval do not add up to 1")
    return errors


def close(a, b, scale):
    return abs(a - b) <= 1e-9 * scale


def check_curve(line, rows, k, expect, whole):
    """The errors of an expectation's curve over column k of a plane's rows (those drawn),
    against summary.json's expect: a reference's largest difference from the column is its
    max_abs_error (at most, where not every row is drawn: whole false); where every row is
    drawn, a period's sinusoid has the expected period, the column's mid-line and
    half range, and its formula's values, the column crossing its mid-line at t0; an
    amplitude's line is the mid-line plus or minus it."""
    xs, ys = line_values(line)
    column = [r[k] for r in rows]
    lo, hi = min(column), max(column)
    scale = max(abs(lo), abs(hi), 1e-300)
    name = expect["model"]
    if expect["kind"] == "reference":
        worst = max(abs(y - c) for y, c in zip(ys, column) if math.isfinite(y))
        if not close(worst, expect["max_abs_error"], scale) and (
                whole or worst > expect["max_abs_error"]):
            return [f"{name}: the curve is at most {worst} from the column, summary.json says "
                    f"{expect['max_abs_error']}"]
        return []
    mid = (lo + hi) / 2
    if not whole:
        return []
    if expect["kind"] == "amplitude":
        if not all(close(abs(y - mid), expect["expected"], scale) for y in ys):
            return [f"{name}: its lines are not the mid-line {mid} plus or minus "
                    f"{expect['expected']}"]
        return []
    period, t0 = float(line.get("data-period")), float(line.get("data-t0"))
    amp = float(line.get("data-amplitude"))
    errors = []
    if period != expect["expected"] or not close(float(line.get("data-mid")), mid, scale) or \
            not close(abs(amp), (hi - lo) / 2, scale):
        errors.append(f"{name}: period {period}, mid {line.get('data-mid')}, amplitude {amp}; "
                      f"expected {expect['expected']}, the column's {mid} and {(hi - lo) / 2}")
    want = [float(line.get("data-mid")) + amp * math.sin(2 * math.pi * (x - t0) / period)
            for x in xs]
    if not all(close(y, w, scale) for y, w in zip(ys, want)):
        errors.append(f"{name}: the sinusoid's values are not its formula's")
    before = [c for x, c in zip(xs, column) if x <= t0]
    after = [c for x, c in zip(xs, column) if x >= t0]
    if not before or not after or (before[-1] - mid) * (after[0] - mid) > 0 or \
            (after[0] - before[-1]) * amp < 0:
        errors.append(f"{name}: the column does not cross its mid-line at t0 = {t0} the way "
                      f"the sinusoid does")
    return errors


def check_curves(root, out, summary):
    """The errors of the expectations drawn over the planes' plots (a finished run's: its
    expectations in summary.json), and each drawn at the rows its plot draws."""
    if summary["status"] != "finished":
        return []
    expects = {e["model"]: e for e in summary.get("expectations", [])}
    errors, drawn = [], set()
    for svg in root.iter(SVG + "svg"):
        name = svg.get("data-csv")
        if name is None or not name.startswith("measure_"):
            continue
        with open(os.path.join(out, name), newline="") as f:
            table = list(csv.reader(f))
        header, rows = table[0], [[float(v) for v in r] for r in table[1:]]
        rows = [rows[r] for r in drawn_rows(len(rows), int(svg.get("data-stride")))]
        for line in svg.iter(SVG + "polyline"):
            if line.get("data-expect") is None:
                continue
            drawn.add(line.get("data-model"))
            if line_values(line)[0] != [r[0] for r in rows]:
                errors.append(f"{line.get('data-model')}: not drawn at the plot's rows")
                continue
            errors += check_curve(line, rows, header.index(line.get("data-column")),
                                  expects[line.get("data-model")],
                                  svg.get("data-stride") == "1")
    missing = {m for m, e in expects.items() if e["kind"] != "energy"} - drawn
    if missing:
        errors.append(f"expectations not drawn over their planes: {sorted(missing)}")
    return errors


def check_processes(root, summary):
    """The errors of the page's table of processes against summary.json's processes (a run on
    many; none on one)."""
    procs = summary.get("processes")
    rows = [r for r in root.iter(XHTML + "tr") if r.get("data-process") is not None]
    if not procs:
        return ["a table of processes for a run on one"] if rows else []
    keys = ("particles", "halo", "bytes_per_step", "wait_time")
    got = [[float(r.get(f"data-{k}")) for k in keys] for r in rows]
    want = [[float(procs[k][p]) for k in keys] for p in range(procs["count"])]
    if got != want or [r.get("data-process") for r in rows] != [
            str(p) for p in range(procs["count"])]:
        return [f"the processes on the page {got}, in summary.json {want}"]
    return []


def check_margins(root, summary):
    """The errors of the stability margins: the page's are summary.json's, number for number;
    a finished run's largest speed over c0 is at least its bodies' at the end (its last
    output was checked)."""
    margins = summary.get("stability", {}).get("margins")
    if not margins:
        return []
    errors = []
    rows = {r.get("data-check"): float(r.get("data-seen")) for r in root.iter(XHTML + "tr")
            if r.get("data-check") is not None}
    want = {"J": margins["smallest_J"], "speed": margins["largest_speed_over_c0"],
            "energy_growth": margins["largest_energy_growth"]}
    want = {k: math.nan if v is None else v for k, v in want.items()}
    if set(rows) != set(want) or any(not same(rows[k], want[k]) for k in want):
        errors.append(f"the stability margins on the page {rows}, in summary.json {want}")
    if summary["status"] == "finished":
        end = max(b["max_velocity"] / b["c0"] for b in summary["bodies"])
        if not want["speed"] >= end * (1 - 1e-12):
            errors.append(f"the largest speed over c0 the checks saw, {want['speed']}, is "
                          f"below the bodies' at the end, {end}")
    return errors


def energy_times(out, rows=None):
    """The times of energies.csv's rows (its first rows only, when given)."""
    with open(os.path.join(out, "energies.csv")) as f:
        times = [float(r.split(",")[0]) for r in f.read().split()[1:]]
    return times if rows is None else times[:rows]


def check_page(text, out, summary, prefix=False):
    """The errors of page text against summary.json's summary and the files of out (prefix:
    a page written during the run, against the first rows of the files); and what it
    plotted."""
    root = ET.fromstring(text)
    errors = []

    verdict = next(e for e in root.iter(XHTML + "p") if e.get("id") == "verdict")
    words = {"finished": "Finished", "unstable": "Unstable", "stopped": "Stopped",
             "running": "Running", "failed": "Failed"}
    if not "".join(verdict.itertext()).startswith(words[summary["status"]]):
        errors.append(f"the verdict '{''.join(verdict.itertext())}' is not "
                      f"'{summary['status']}'")

    expects = summary.get("expectations", [])
    table = [e for e in root.iter(XHTML + "table") if e.get("id") == "expectations"]
    rows = list(table[0].iter(XHTML + "tr"))[1:] if table else []
    if len(rows) != len(expects):
        errors.append(f"{len(rows)} expectations on the page, {len(expects)} in summary.json")
    for row, x in zip(rows, expects):
        cells = ["".join(c.itertext()) for c in row.iter(XHTML + "td")]
        if cells[0] != x["model"] or cells[-1] != ("pass" if x["pass"] else "FAIL"):
            errors.append(f"expectation row {cells} is not {x['model']} ({x['pass']})")
        error = x["relative_error"]
        if error is not None and float(cells[4]) != float(f"{100 * error:.4g}"):
            errors.append(f"{x['model']}: relative error {cells[4]} % on the page, "
                          f"{100 * error} % in summary.json")

    plot_errors, plotted = check_plots(root, out, prefix)
    errors += plot_errors
    with open(os.path.join(out, "energies.csv")) as f:
        columns = set(f.readline().strip().split(",")[1:])
    if plotted.get("energies.csv") != columns:
        errors.append(f"energies.csv's columns {sorted(columns)}, plotted "
                      f"{sorted(plotted.get('energies.csv', []))}")
    for name in os.listdir(out):
        if name.startswith("measure_") and name.endswith(".csv") and name not in plotted:
            errors.append(f"no plot of {name}")

    # The mean time step of each output interval: at the output times after the first, each
    # no longer than its interval.
    steps = [s for s in root.iter(SVG + "svg") if s.get("id") == "time-step"]
    energies = [s for s in root.iter(SVG + "svg") if s.get("data-csv") == "energies.csv"]
    times = energy_times(out, int(energies[0].get("data-rows")) if prefix and energies
                         else None)
    if len(steps) != (len(times) > 1):
        errors.append(f"{len(steps)} time step plots (expected {int(len(times) > 1)})")
    elif steps:
        line = next(steps[0].iter(SVG + "polyline"))
        xs = [float(v) for v in line.get("data-x").split()]
        ys = [float(v) for v in line.get("data-y").split()]
        want = times[1:][::int(steps[0].get("data-stride"))]
        if len(times) > 1 and want[-1] != times[-1]:
            want.append(times[-1])
        if len(xs) != len(want) or any(abs(x - t) > 1e-9 * max(abs(t), 1e-30)
                                       for x, t in zip(xs, want)):
            errors.append(f"the time step is plotted at {xs[:5]}..., the outputs are at "
                          f"{want[:5]}...")
        elif steps[0].get("data-stride") == "1" and not all(
                0 < y <= (b - a) * (1 + 1e-9) for y, a, b in zip(ys, times, times[1:])):
            errors.append(f"a mean time step is not within its output interval: {ys[:5]}...")

    errors += check_bounds(root, summary)
    errors += check_margins(root, summary)
    errors += check_curves(root, out, summary)
    errors += check_processes(root, summary)

    # The comparison can fail: one plotted number changed is found.
    line = next(root.iter(SVG + "polyline"))
    ys = line.get("data-y").split()
    ys[-1] = repr(float(ys[-1]) * 1.001 + 1e-300)
    line.set("data-y", " ".join(ys))
    if not check_plots(root, out, prefix)[0]:
        errors.append("a page with a plotted number changed passes the check")
    return errors, plotted


def check_unstable(summary):
    """The errors of an unstable run's numbers against its message: a particle inverted has
    the smallest det F the margins give; a time step that collapsed under compression was
    last set by the compression bound."""
    errors, message = [], summary["stability"].get("message", "")
    margins, bounds = summary["stability"]["margins"], summary["time_step_bounds"]
    inverted = re.search(r"det F <= 0 \(particle inverted\) \(value (\S+)\)", message)
    if inverted and f"{margins['smallest_J']:g}" != inverted.group(1):
        errors.append(f"smallest_J {margins['smallest_J']} is not the message's det F "
                      f"{inverted.group(1)}")
    if "collapsed" in message and "compressed to a principal stretch" in message and (
            bounds["last"] != "compression"):
        errors.append(f"the time step collapsed under compression, its last bound is "
                      f"{bounds['last']}")
    return errors


def main():
    code, launcher = 0, []
    while sys.argv[1] in ("--exit", "--launcher"):
        if sys.argv[1] == "--exit":
            code = int(sys.argv[2])
        else:
            launcher = [w for w in sys.argv[2].split(",") if w]
        del sys.argv[1:3]
    program, out, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    run = subprocess.run(launcher + [program, "--quiet", "--overwrite", "--out", out] + args,
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if run.returncode != code:
        sys.exit(f"{program} exited {run.returncode}:\n{run.stdout}")
    with open(os.path.join(out, "summary.html"), encoding="utf-8") as f:
        text = f.read()
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    errors, plotted = check_page(text, out, summary)
    if summary["status"] == "unstable":
        errors += check_unstable(summary)
    expects = summary.get("expectations", [])
    if errors:
        sys.exit("summary.html:\n  " + "\n  ".join(errors))
    print(f"summary.html: {summary['status']}, {len(expects)} expectations, "
          f"{sum(len(v) for v in plotted.values())} lines in {len(plotted)} files match")


if __name__ == "__main__":
    main()
