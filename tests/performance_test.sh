#!/usr/bin/env bash
# tools/performance-md writes docs/performance.md from the JSON of `make bench` and of the studies:
# here from a few benchmarks and a small scaling study, into a temporary file. Each table it
# writes holds the figure of its JSON (the median of the repetitions), and a study whose JSON is
# missing gets a line saying so.
# Usage: performance_test.sh STEPLAB_BENCH STEPLAB SOURCE_DIR
set -euo pipefail
bench=$1 steplab=$2 src=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$bench" --benchmark_filter='^((step|odeint|hand)/spring/rk4|rope_size/rk4/64|throughput_w1/spring/explicit_euler)$' \
  --benchmark_min_time=0.001 --benchmark_repetitions=3 --benchmark_out="$tmp/bench.json" --benchmark_out_format=json >/dev/null
mkdir "$tmp/studies"
"$steplab" study scaling --sizes 8,16 --methods rk4,cvode_adams_band --error 1e-4 --no-timing --json "$tmp/studies/scaling-rope.json" >/dev/null
"$steplab" study scaling --sizes 8,16 --stiffness 5,5000 --methods rk4,implicit_euler,cvode_bdf_max2_band --no-timing \
  --json "$tmp/studies/scaling-map-rope.json" >/dev/null
"$src/tools/performance-md" --bench "$tmp/bench.json" --studies "$tmp/studies" --out "$tmp/performance.md" >/dev/null
python3 - "$tmp/bench.json" "$tmp/studies/scaling-rope.json" "$tmp/performance.md" "$tmp/studies/scaling-map-rope.json" <<'PY'
import json, sys
bench, scal, md, smap = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), open(sys.argv[3]).read(), json.load(open(sys.argv[4]))
# the median CPU time: the figure tools/performance-md writes (wall time differs under load)
med = {b["run_name"]: b["cpu_time"] for b in bench["benchmarks"] if b.get("aggregate_name") == "median"}
step, odeint = med["step/spring/rk4"], med["odeint/spring/rk4"]
row = next(l for l in md.splitlines() if l.startswith("| `spring/rk4`"))
cells = [c.strip() for c in row.strip("|").split("|")]
assert abs(float(cells[1]) - step) <= 0.0015 * step + 0.05, (cells, step)  # three significant digits
assert abs(float(cells[4]) - step / odeint) <= 0.006, (cells, step / odeint)  # two decimals
assert "| `rk4` |" in md and "N = 64" in md, "the rope_size table"
assert "`throughput_w1/spring/explicit_euler`" in md, "the packs table"
assert bench["context"]["compiler"].startswith("GCC") and bench["context"]["compiler"] in md, "the machine line"
for r in scal["rows"]:
    assert any(l.startswith(f"| `{r['solver']}` | {r['masses']} |") and f"| {r['counts']['steps']} |" in l for l in md.splitlines()), r
assert "scaling-softbody.json` is missing" in md and "work-precision.json` is missing" in md
# the map: each stiffness's row names its cells' cheapest solvers, in the order of the sizes
assert "## When does implicit pay?" in md and "scaling-map-softbody.json` is missing" in md
maps = md[md.index("## When does implicit pay?"):]
for b in smap["blocks"]:
    at = maps.split("\nError ")[1 + b["target"]]  # the target's table
    row = next(l for l in at.splitlines() if l.startswith(f"| {b['stiffness']:g} |"))
    cells = [c.strip() for c in row.strip("|").split("|")][1:]
    assert [c.split("`")[1] for c in cells] == [m["cheapest"] for m in b["map"]], (row, b["map"])
print("performance.md ok")
PY
