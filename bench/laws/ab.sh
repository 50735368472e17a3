#!/bin/sh
# ab.sh SPHC BEFORE_DIR WORK MODEL END PAIRS [AFTER_DIR]: builds MODEL twice with sphc, once
# with the laws of BEFORE_DIR (a folder of .sph laws, put beside a copy of the model: `import`
# looks there before the standard library) and once with the standard library (or the laws
# of AFTER_DIR), then runs the two programs in turn (A B A B ..., PAIRS pairs, one thread,
# --end END) and prints each run's wall time and the median of the ratios after/before with
# their range.
set -e
sphc=$1 before=$2 work=$3 model=$4 end=$5 pairs=${6:-5} after=$7
name=$(basename "$model" .sph)
mkdir -p "$work/a" "$work/b"
cp "$before"/*.sph "$work/a/"
cp "$model" "$work/a/$name.sph"
cp "$model" "$work/b/$name.sph"
[ -n "$after" ] && cp "$after"/*.sph "$work/b/"
(cd "$work/a" && "$sphc" -o prog "$name.sph" >/dev/null)
(cd "$work/b" && "$sphc" -o prog "$name.sph" >/dev/null)
unset OMP_WAIT_POLICY
run() { # the program's wall time in seconds
    s=$(date +%s.%N)
    "$work/$1/prog" --threads 1 --end "$end" --quiet --overwrite --out "$work/$1/out" >/dev/null
    e=$(date +%s.%N)
    echo "$e - $s" | bc -l
}
ratios=""
i=0
while [ $i -lt "$pairs" ]; do
    ta=$(run a)
    tb=$(run b)
    r=$(echo "$tb / $ta" | bc -l)
    printf '%s before %.3f s  after %.3f s  ratio %.4f\n' "$name" "$ta" "$tb" "$r"
    ratios="$ratios $r"
    i=$((i + 1))
done
echo "$ratios" | tr ' ' '\n' | grep . | sort -g | awk -v n="$name" '
  { r[NR] = $1 }
  END { m = NR % 2 ? r[(NR + 1) / 2] : (r[NR / 2] + r[NR / 2 + 1]) / 2;
        printf "%s median ratio after/before %.4f  (range %.4f .. %.4f, %d pairs)\n", n, m, r[1], r[NR], NR }'
