#!/bin/bash
# callgrind.sh SPHC BEFORE_DIR WORK MODEL END [AFTER_DIR]: the instructions a short run of
# MODEL executes (valgrind --tool=callgrind, one thread; compiled for AVX2 by cc-v3, as
# valgrind does not know AVX-512), built with the laws of BEFORE_DIR (as ab.sh) and with the
# standard library (or the laws of AFTER_DIR): the whole run's and the stress pass's
# (inclusive; the material law is inlined there), and their ratio after/before.
set -e
sphc=$1 before=$2 work=$3 model=$4 end=$5 after=$6
name=$(basename "$model" .sph)
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$work/a" "$work/b"
cp "$before"/*.sph "$work/a/"
cp "$model" "$work/a/$name.sph"
cp "$model" "$work/b/$name.sph"
[ -n "$after" ] && cp "$after"/*.sph "$work/b/"
for v in a b; do
    (cd "$work/$v" && CC="$here/cc-v3" "$sphc" -o prog "$name.sph" >/dev/null)
    valgrind --tool=callgrind --callgrind-out-file="$work/$v/cg.out" "$work/$v/prog" --threads 1 \
        --end "$end" --quiet --overwrite --out "$work/$v/out" >/dev/null 2>&1
    callgrind_annotate --inclusive=yes --threshold=100 "$work/$v/cg.out" 2>/dev/null |
        awk -v v="$v" '/PROGRAM TOTALS/ { gsub(",", "", $1); print v, "total", $1 }
                       /_stress_pass\._omp_fn/ { gsub(",", "", $1); f = $(NF - 1); sub(/^\?\?\?:/, "", f); print v, f, $1 }' \
        > "$work/$v/ir.txt"
done
join -j 2 -o 0,1.3,2.3 <(sort -k2 "$work/a/ir.txt") <(sort -k2 "$work/b/ir.txt") |
    awk -v n="$name" '{ printf "%s %s: before %.0f after %.0f instructions, ratio %.4f\n", n, $1, $2, $3, $3 / $2 }'
