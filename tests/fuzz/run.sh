#!/usr/bin/env bash
# Builds the libFuzzer harnesses in build-fuzz/ (clang-14, ASan + UBSan) and fuzzes each in turn.
#   tests/fuzz/run.sh [--seconds N | --total N] [--build DIR] [HARNESS...] [-- libFuzzer options]
# --seconds N: N seconds per harness (default 60); --total N: N seconds shared by the harnesses.
# HARNESS: scenario, profile, csv, tables, study, metric, result (default: all). Exit status non-zero when
# a harness finds a crash, leak, timeout or out-of-memory; its input is left in
# BUILD/tests/fuzz/work/HARNESS/.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$root/build-fuzz"
seconds=60 total=0
harnesses=() extra=()
while [[ $# -gt 0 ]]; do
  case $1 in
    --seconds) seconds=$2; shift 2 ;;
    --total) total=$2; shift 2 ;;
    --build) build=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    -h|--help) sed -n '2,7p' "$0"; exit 0 ;;
    *) harnesses+=("$1"); shift ;;
  esac
done
[[ ${#harnesses[@]} -gt 0 ]] || harnesses=(scenario profile csv tables study metric result)
if [[ $total -gt 0 ]]; then seconds=$(( total / ${#harnesses[@]} )); fi

cc=${CC:-clang-14} cxx=${CXX:-clang++-14}
command -v "$cxx" >/dev/null || { echo "run.sh: $cxx not found (apt-get install clang-14 libclang-rt-14-dev)" >&2; exit 1; }
if [[ ! -f "$build/CMakeCache.txt" ]]; then
  CC=$cc CXX=$cxx cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DRB_WERROR=OFF -DRB_FUZZ=ON -DBUILD_TESTING=OFF >/dev/null
fi
targets=()
for h in "${harnesses[@]}"; do targets+=("fuzz_$h"); done
cmake --build "$build" --target "${targets[@]}"

rc=0
for h in "${harnesses[@]}"; do
  echo "== fuzz_$h: ${seconds} s"
  if ! "$root/tests/fuzz/smoke.sh" "$build/tests/fuzz/fuzz_$h" "$h" "$seconds" \
       "$build/tests/fuzz/work" ${extra[@]+"${extra[@]}"} 2> "$build/tests/fuzz/fuzz_$h.log"; then
    echo "fuzz_$h FAILED; the log: $build/tests/fuzz/fuzz_$h.log" >&2
    tail -n 40 "$build/tests/fuzz/fuzz_$h.log" >&2
    rc=1
  else
    grep -E '^stat::number_of_executed_units|^#[0-9]+.*DONE' "$build/tests/fuzz/fuzz_$h.log" || true
  fi
done
exit $rc
