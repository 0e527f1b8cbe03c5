#!/usr/bin/env bash
# No heap allocation in a step of `steplab run`, counted from outside the program: every method
# on the rope of 256 masses and on the spring, writing CSV and writing JSON (which reads the
# rope's error against its exact motion, here at every step: --error-every 1), each run twice,
# the runs differing only in their number of steps, under tools/malloc_count.c (an LD_PRELOAD
# library counting malloc, calloc, realloc, aligned_alloc, posix_memalign, memalign and valloc
# of the whole process, shared libraries such as FFTW and KLU included; operator new is malloc).
# Allocations per step = (allocations of the long run - of the short) / (steps long - short).
# Prints the table; exits 1 naming each method and mode whose long run allocated more than the
# short one by more than SLACK (the output's strings grow with the digits printed, not with the
# steps: at most a reallocation or two either way; an allocation every step, or every 100th,
# is far above it over the 400 steps between the runs).
# A method that does not apply to a scene (exit status 2) is skipped. Exits 77 (skipped) under
# AddressSanitizer, whose allocator does not let another library interpose malloc.
# Usage: run_allocations_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1
source=$2
exe=$build/steplab
[[ -x $exe ]] || { echo "no $exe"; exit 1; }
if ldd "$exe" 2>/dev/null | grep -q 'libasan'; then
  echo "steplab is built with AddressSanitizer: malloc cannot be interposed; skipped"
  exit 77
fi

# The counting library, built into the build directory (renamed into place: a partial file is
# never preloaded).
libdir=$build/tests/run_allocations
mkdir -p "$libdir"
lib=$libdir/libmalloc_count.so
"${CC:-cc}" -O2 -shared -fPIC -o "$lib.tmp.$$" "$source/tools/malloc_count.c" -ldl
mv -f "$lib.tmp.$$" "$lib"

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

DT=1e-4 SHORT=0.01 LONG=0.05  # 100 and 500 steps
SLACK=2
scenes=(rope spring)
declare -A scene_args=([rope]="--scene rope --masses 256" [spring]="--scene spring")

# The methods, as `run` names them when refused one (dopri5, adaptive, is run apart and not here).
set +e
"$exe" run --method nope 2>"$tmp/methods" >/dev/null
set -e
methods=$(sed -n 's/.*accepted: //p' "$tmp/methods" | sed 's/ (.*//' | tr -d ',')
[[ -n $methods ]] || { echo "no method list in:"; cat "$tmp/methods"; exit 1; }

# count_run SCENE METHOD MODE T_END: sets $count (the process's allocations) and $steps (the
# steps the run took); returns 2 where the method does not apply.
count_run() {
  local scene=$1 method=$2 mode=$3 t_end=$4 status
  local -a args
  read -r -a args <<<"${scene_args[$scene]}"
  args+=(--method "$method" --dt "$DT" --t-end "$t_end" --samples 2)
  [[ $mode == json ]] && args+=(--json "$tmp/run.json" --error-every 1)
  rm -f "$tmp/count" "$tmp/run.json"  # the same files (none) before every run: run checks an existing one
  set +e
  MALLOC_COUNT_OUT=$tmp/count LD_PRELOAD=$lib "$exe" run "${args[@]}" >"$tmp/out.csv" 2>"$tmp/err"
  status=$?
  set -e
  if [[ $status -eq 2 ]]; then return 2; fi
  if [[ $status -ne 0 ]]; then
    echo "steplab run ${args[*]}: exit $status"
    cat "$tmp/err"
    exit 1
  fi
  [[ $(wc -l <"$tmp/count") -eq 1 ]] || { echo "steplab run ${args[*]}: not one count line:"; cat "$tmp/count"; exit 1; }
  count=$(sed -n 's/^count //p' "$tmp/count")
  if [[ $mode == json ]]; then
    steps=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["steps"])' "$tmp/run.json")
  else  # the last row's time over the step
    steps=$(tail -1 "$tmp/out.csv" | awk -F, -v dt="$DT" '{ printf "%d\n", $1 / dt + 0.5 }')
  fi
  [[ $count =~ ^[0-9]+$ && $steps =~ ^[0-9]+$ ]] || { echo "steplab run ${args[*]}: count '$count', steps '$steps'"; exit 1; }
}

declare -A cell
failures=()
for scene in "${scenes[@]}"; do
  for method in $methods; do
    for mode in csv json; do
      if ! count_run "$scene" "$method" "$mode" "$SHORT"; then
        cell[$method,$scene,$mode]=n/a
        continue
      fi
      c1=$count n1=$steps
      count_run "$scene" "$method" "$mode" "$LONG"
      c2=$count n2=$steps
      if [[ $n2 -le $n1 ]]; then
        echo "$scene $method $mode: $n1 and $n2 steps (diverged early?)"
        exit 1
      fi
      diff=$((c2 - c1))
      cell[$method,$scene,$mode]=$(awk -v d="$diff" -v n="$((n2 - n1))" 'BEGIN { printf "%.2f", d / n }')
      if [[ $diff -gt $SLACK ]]; then
        failures+=("$method on the $scene, $mode: ${cell[$method,$scene,$mode]} a step ($c1 allocations in $n1 steps, $c2 in $n2)")
      fi
    done
  done
done

echo "Heap allocations per step of steplab run (rope: 256 masses; json: --error-every 1), dt $DT, $SHORT vs $LONG"
printf '%-18s %10s %10s %12s %12s\n' method "rope csv" "rope json" "spring csv" "spring json"
for method in $methods; do
  printf '%-18s %10s %10s %12s %12s\n' "$method" "${cell[$method,rope,csv]}" "${cell[$method,rope,json]}" \
    "${cell[$method,spring,csv]}" "${cell[$method,spring,json]}"
done
if [[ ${#failures[@]} -gt 0 ]]; then
  echo
  echo "Allocating in the stepping loop:"
  printf '  %s\n' "${failures[@]}"
  echo "(where: MALLOC_COUNT_TRACE_AFTER=N prints each later allocation's backtrace, tools/malloc_count.c)"
  exit 1
fi
echo "no allocation in any step"
