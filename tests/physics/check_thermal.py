#!/usr/bin/env python3
"""The program of thermo2d.sph (J2 with adiabatic heating, beta = 0.9) run to its end:
energies.csv has the body's heat in sq_thermal, beta times its dissipated energy sq_plastic
(to 1e-9 of it), and the total is strain + kinetic + plastic, the heat not added again (to
1e-9 of it); the particle files carry the temperature T.
Usage: check_thermal.py PROGRAM OUT"""
import csv
import os
import re
import subprocess
import sys

program, out = sys.argv[1], sys.argv[2]
subprocess.run([program, "--quiet", "--overwrite", "--threads", "1", "--out", out], check=True)
with open(os.path.join(out, "energies.csv")) as f:
    rows = list(csv.DictReader(f))
failures = 0


def check(what, ok):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += not ok


check("energies.csv has sq_thermal", "sq_thermal" in rows[0])
last = {k: float(v) for k, v in rows[-1].items()}
check("the body flowed (sq_plastic > 0)", last["sq_plastic"] > 0)
for row in rows:
    r = {k: float(v) for k, v in row.items()}
    check("t = %g: sq_thermal = 0.9 sq_plastic" % r["time"],
          abs(r["sq_thermal"] - 0.9 * r["sq_plastic"]) <= 1e-9 * max(r["sq_plastic"], 1e-300))
    held = r["sq_strain"] + r["sq_kinetic"] + r["sq_plastic"]
    check("t = %g: total = strain + kinetic + plastic" % r["time"],
          abs(r["total"] - held) <= 1e-9 * max(abs(held), 1e-300))
frames = sorted(f for f in os.listdir(os.path.join(out, "particles")) if f.endswith(".vtu"))
with open(os.path.join(out, "particles", frames[-1]), "rb") as f:
    check("the last frame has the temperature T", b'Name="T"' in f.read())
sys.exit(1 if failures else 0)
