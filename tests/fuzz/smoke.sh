#!/usr/bin/env bash
# One fuzz run of a harness: smoke.sh FUZZER HARNESS SECONDS WORKDIR [libFuzzer options...]
# The kept inputs tests/fuzz/HARNESS/* (not its crashes/ folder) seed a working corpus in
# WORKDIR/HARNESS/corpus, so the run never writes into the source tree; a crash, leak, timeout or
# out-of-memory is written to WORKDIR/HARNESS/ and fails the run.
set -euo pipefail
fuzzer=$1 harness=$2 seconds=$3 work=$4
shift 4
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
corpus="$work/$harness/corpus"
mkdir -p "$corpus"
find "$here/$harness" -maxdepth 1 -type f ! -name 'README*' -exec cp -f {} "$corpus/" \;
dict=()
if [[ -f "$here/$harness.dict" ]]; then dict=(-dict="$here/$harness.dict"); fi
# -timeout: a single input running longer is a hang; -rss_limit_mb: the Lua host may use up to
# 1 GiB by design, ASan adds its shadow on top.
exec "$fuzzer" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=3072 -max_len=65536 \
  -print_final_stats=1 -artifact_prefix="$work/$harness/" ${dict[@]+"${dict[@]}"} "$@" "$corpus"
