#!/bin/sh
# Regenerate results.csv and the run logs (serial; about 15 minutes on 2 cores,
# peak memory about 10 GB, in plate_modes.py).  Requires Debian's
# python3-dolfinx 0.5.2 and python3-slepc4py-real (see README.md).
set -e
cd "$(dirname "$0")"
PY=/usr/bin/python3
rm -f results.csv
# 1. Dimensionless cantilever table: meshes n = 2, 4, 8 cells through the thickness.
$PY cantilever_static.py --csv results.csv | tee log_cantilever.txt
# 1b. Fourth level n = 16 (CG + GAMG) for L/t = 5 and for L/t = 10, s = 0.1
#     (the big-beam s = 1 mm case), to check the extrapolation.
$PY cantilever_static.py --L 5 --levels 4 --csv results.csv | tee log_cantilever_4levels.txt
$PY cantilever_static.py --L 10 --s 0.1 --levels 4 --csv results.csv | tee -a log_cantilever_4levels.txt
# 1c. Independent (non-nested with 1) sequence n = 3, 6, 12 for L/t = 5.
$PY cantilever_static.py --n0 3 --L 5 --csv results.csv | tee log_cantilever_n0_3.txt
# 2. Steel beam 0.1 x 0.01 x 0.01 m, per newton.
$PY bigbeam_static.py --csv results.csv | tee log_bigbeam.txt
# 3. Clamped plate strip natural frequencies: meshes n = 1, 2, 4, 8.
$PY plate_modes.py --csv results.csv | tee log_plate_modes.txt
