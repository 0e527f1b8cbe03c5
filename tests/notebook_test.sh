#!/usr/bin/env bash
# reports/data/explore.ipynb run as the README shows it, from a folder laid out as steplab's (the
# notebook in reports/data/, a report in report/): a small report's data, every JSON document of
# it loaded into a table, the convergence figure drawn. nbconvert exits non-zero if a cell fails.
# Usage: notebook_test.sh STEPLAB_EXE SOURCE_DIR
set -euo pipefail
exe=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/reports/data"
cp "$src/reports/data/explore.ipynb" "$tmp/reports/data/"
cd "$tmp"
cat > small.json <<'JSON'
{"convergence": {"points": 4, "dt_min": 0.01}, "work_precision": {"points": 3, "stiffnesses": [5], "timing": false},
 "stability": {"map_dt_points": 4, "map_damping_points": 4}, "collision": {"t_end": 1, "dts": [0.004]},
 "figures": {"energy_t_end": 2, "cannonball_t_end": 2},
 "scaling": {"rope": [4, 8], "softbody": [2], "t_end": 0.5, "map_sizes": [4, 8], "stiffening": [1, 100]},
 "long_time": {"periods": 100}}
JSON
"$exe" report --config small.json --out report >/dev/null
command=$(grep -o 'jupyter nbconvert --to html --execute reports/data/explore.ipynb --output-dir build' "$src/README.md")
[[ -n $command ]] || { echo "the README shows no notebook command this test knows"; exit 1; }
$command 2>log || { cat log; exit 1; }
html=build/explore.html
grep -q 'data:image/png' "$html" || { echo "the notebook drew no figure"; exit 1; }
documents=$(find report/data -name '*.json' ! -name config.json | wc -l)
grep -q "$documents documents in" "$html" || { echo "the notebook did not load the report's $documents JSON documents"; exit 1; }
echo "notebook ran as the README shows: $documents JSON documents"
