#!/usr/bin/env bash
# steplab as a package: install the build into a temporary prefix, build tests/consumer/ (a
# project outside the tree) against it with find_package(steplab 0.2), run its two programs
# (steplab::core and steplab::analysis, their headers included as <steplab/...>), and run the
# installed CLI.
# Usage: consumer_test.sh BUILD_DIR SOURCE_DIR [extra cmake arguments for the consumer]
set -euo pipefail
build=$1 src=$2
shift 2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
for f in include/steplab/core/methods/rk4.hpp include/steplab/analysis/kernel/kernel.hpp include/steplab/reports/cli/cli.hpp bin/steplab \
         lib/cmake/steplab/steplabConfig.cmake lib/cmake/steplab/steplabConfigVersion.cmake lib/cmake/steplab/steplabTools.cmake; do
  [[ -e $tmp/prefix/$f ]] || { echo "not installed: $f"; exit 1; }
done
cmake -S "$src/tests/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$tmp/consumer" -j 2 >/dev/null
"$tmp/consumer/consumer_core"
"$tmp/consumer/consumer_analysis"
"$tmp/prefix/bin/steplab" --version
# Versions the package does not provide are refused (0.x: a minor version may break the API).
for want in 0.1 0.3 1.0; do
  if cmake -S "$src/tests/consumer" -B "$tmp/wrong-$want" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
       -DSTEPLAB_WANT=$want "$@" >/dev/null 2>&1; then
    echo "find_package(steplab $want) accepted an installed $("$tmp/prefix/bin/steplab" --version)"; exit 1
  fi
done
echo "consumer ok"
