#!/usr/bin/env bash
# Runs reports/data/explore.ipynb headless with Debian's jupyter nbconvert on fresh study data, and
# checks that every cell ran and that it redrew figure 3.
# Usage: notebook_test.sh STEPLAB_EXE SOURCE_DIR
set -euo pipefail
exe=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$exe" study convergence --scene spring --dt-min 1e-3 --points 8 --json "$tmp/convergence_spring.json" >/dev/null
"$exe" study stability --map-dt-points 4 --map-damping-points 3 --threshold-dampings 0.1 --json "$tmp/stability.json" >/dev/null
"$exe" study collision --dts 0.002 --t-end 2 --json "$tmp/collision.json" >/dev/null
"$exe" study scaling --sizes 8,16 --stiffness 5,5000 --methods rk4,implicit_euler --no-timing --json "$tmp/scaling_map.json" >/dev/null
STEPLAB_DATA=$tmp STEPLAB_FIGURES=$tmp jupyter nbconvert --to notebook --execute --ExecutePreprocessor.timeout=120 \
  --output-dir "$tmp" --output executed "$src/reports/data/explore.ipynb" 2>"$tmp/log" || { cat "$tmp/log"; exit 1; }
test -s "$tmp/convergence_from_notebook.png" || { echo "the notebook did not redraw figure 3"; exit 1; }
grep -q '"output_type": "error"' "$tmp/executed.ipynb" && { echo "a cell failed"; exit 1; }
echo "notebook ran: $(grep -c '"execution_count": [0-9]' "$tmp/executed.ipynb") cells"
