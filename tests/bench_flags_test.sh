#!/usr/bin/env bash
# Google Benchmark's own flags work on steplab_bench as Google Benchmark documents them:
# --benchmark_format=json and csv print that format on stdout (no ratio table mixed in),
# --benchmark_out writes the file, --ratios=FILE writes the ratio table, and an unknown format
# is refused with exit status 2.
# Usage: bench_flags_test.sh STEPLAB_BENCH_EXE
set -euo pipefail
bench=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
one=(--benchmark_filter='^(step|odeint)/spring/explicit_euler$' --benchmark_min_time=0.001)

"$bench" "${one[@]}" --benchmark_format=json --ratios="$tmp/ratios.md" >"$tmp/out.json"
python3 - "$tmp/out.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
names = sorted(b["name"] for b in d["benchmarks"])
assert names == ["odeint/spring/explicit_euler", "step/spring/explicit_euler"], names
assert all(b["real_time"] > 0 for b in d["benchmarks"])
PY
grep -q '^| spring/explicit_euler |' "$tmp/ratios.md" || { echo "no ratio row in --ratios file"; exit 1; }

"$bench" "${one[@]}" --benchmark_format=csv >"$tmp/out.csv"
head -1 "$tmp/out.csv" | grep -q '^name,iterations,real_time' || { echo "not CSV:"; head -3 "$tmp/out.csv"; exit 1; }
! grep -q 'CPU time per step' "$tmp/out.csv" || { echo "ratio table mixed into CSV"; exit 1; }

"$bench" "${one[@]}" --benchmark_out="$tmp/file.json" --benchmark_out_format=json >"$tmp/console.txt"
python3 -c 'import json, sys; assert json.load(open(sys.argv[1]))["benchmarks"]' "$tmp/file.json"
grep -q 'CPU time per step' "$tmp/console.txt" || { echo "console output lost its ratio table"; exit 1; }

set +e
"$bench" "${one[@]}" --benchmark_format=xml >/dev/null 2>"$tmp/err"
status=$?
set -e
[[ $status -eq 2 ]] || { echo "--benchmark_format=xml: exit $status, expected 2"; exit 1; }
grep -q 'benchmark_format' "$tmp/err" || { echo "no message naming the flag"; exit 1; }
echo "bench flags ok"
