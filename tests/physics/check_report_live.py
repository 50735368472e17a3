"""The report page written during a run (Python's standard library only).

    check_report_live.py PROGRAM OUT [ARGS...]

starts PROGRAM --quiet --overwrite --summary 0 --out OUT ARGS (summary.json and summary.html
written again at every output), reads OUT/summary.html as the run goes until a page says
"Running" and plots at least MIN_ROWS rows of energies, then stops the run with SIGTERM (it
must exit 7: stopped, without a checkpoint).  The page read during the run must match the
first rows of the CSV files, as many as it says it drew, and summary.json must have said
"running"; the page of the stopped run must match the whole files (check_report.check_page).
"""
import json
import os
import signal
import subprocess
import sys
import time

import check_report

MIN_ROWS = 5
WAIT_SECONDS = 60


def running_page(out):
    """The text of OUT/summary.html when it is a running page with MIN_ROWS rows of
    energies, else None (each write renames a whole file over it: never a part)."""
    try:
        with open(os.path.join(out, "summary.html"), encoding="utf-8") as f:
            text = f.read()
    except FileNotFoundError:
        return None
    if 'class="verdict running"' not in text:
        return None
    root = check_report.ET.fromstring(text)
    for svg in root.iter(check_report.SVG + "svg"):
        if svg.get("data-csv") == "energies.csv" and int(svg.get("data-rows")) >= MIN_ROWS:
            return text
    return None


def main():
    program, out, args = sys.argv[1], sys.argv[2], sys.argv[3:]
    proc = subprocess.Popen([program, "--quiet", "--overwrite", "--summary", "0", "--out",
                             out] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True)
    text, start = None, time.monotonic()
    while text is None and proc.poll() is None and time.monotonic() - start < WAIT_SECONDS:
        text = running_page(out)
        time.sleep(0.002)
    proc.send_signal(signal.SIGTERM)
    output = proc.communicate()[0]
    if text is None:
        sys.exit(f"no running page with {MIN_ROWS} rows of energies was seen (the program "
                 f"exited {proc.returncode}):\n{output}")
    if proc.returncode != 7:
        sys.exit(f"{program} exited {proc.returncode}, not 7 (stopped):\n{output}")
    errors = check_report.check_page(text, out, {"status": "running"}, prefix=True)[0]
    errors = [f"during the run: {e}" for e in errors]
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "summary.html"), encoding="utf-8") as f:
        final = f.read()
    if summary["status"] != "stopped":
        errors.append(f"summary.json says {summary['status']} after SIGTERM")
    errors += [f"after the run: {e}" for e in check_report.check_page(final, out, summary)[0]]
    if errors:
        sys.exit("summary.html:\n  " + "\n  ".join(errors))
    rows = len(check_report.energy_times(out))
    print(f"summary.html: a running page matched the first rows of the files; the stopped "
          f"run's page matches all {rows} rows")


if __name__ == "__main__":
    main()
