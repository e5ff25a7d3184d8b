#!/usr/bin/env bash
# Scale-out of studies through the real command line (docs/studies.md, "Running on a cluster").
# usage: scale_test.sh WORKBENCH MODE MPI_BUILT MPIEXEC   (run from the repository root)
#   same        a 2x3 study run locally (--jobs 2) and as 3 shards + --summarize gives the same
#               summaries (cost columns aside); bad --shard values are errors; --summarize of
#               an empty folder says "missing".
#   same_mpi    the same study under `mpirun -np 3 ... --mpi` gives the local summaries.
#   kill_shard  a shard killed (SIGKILL) after its first result and relaunched completes, with
#               the results finished before the kill untouched and nothing missing.
#   kill_mpi    the same for the MPI farm (SIGKILL, then SIGTERM, to mpirun), and no run
#               outlives the farm.
# The MPI modes exit 77 (skipped) when the workbench was built without MPI.
set -u
WB="$1"; MODE="$2"; MPI_BUILT="$3"; MPIEXEC="${4:-mpirun}"
ROOT="$PWD"
PY=/usr/bin/python3
HERE="$(cd "$(dirname "$0")" && pwd)"
TMP="$(mktemp -d)"
export RAILBENCH_STUDY_PLOTS=0
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok: $1"; }
bad() { fail=$((fail + 1)); echo "FAILED: $1"; }
wb()  { "$WB" --root "$ROOT" "$@" </dev/null; }
mpi=("$MPIEXEC" --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpi+=(--allow-run-as-root)
# Under ./wb test --sanitize: OpenMPI's components are dlopen'ed and closed again at
# MPI_Finalize, so what they keep allocated until exit is reported from "<unknown module>"
# frames that no suppression (lsan_mpi.supp) can name. The ranks (which are workbench processes
# started by mpirun) run without the leak check; the same code is leak-checked in every non-MPI
# test, including the local and shard runs of this script.
mpi+=(-x "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0")
pids=()
cleanup() {
  local p
  for p in ${pids[@]+"${pids[@]}"}; do kill -KILL "$p" 2>/dev/null; done
  rm -rf "$TMP"
}
trap cleanup EXIT

case "$MODE" in
  same_mpi|kill_mpi)
    if [ "$MPI_BUILT" != 1 ]; then
      echo "SKIPPED: this workbench was built without MPI (cmake -DRB_MPI=ON, libopenmpi-dev)"
      exit 77
    fi ;;
esac

# The paper's case 3 over a few metres: a 2x3 matrix of short runs (well under a second each),
# and 6 runs of about a second each for the kill tests.
cat >"$TMP/six.lua" <<LUA
study { base = "$ROOT/scenarios/studies/case3_base.lua",
        matrix = { ["run.distance"] = { 3, 4, 5 }, ["solver.step"] = { 2.5e-4, 2e-4 } },
        metrics = {
          { name = "y_max", signal = "/bodies/ws1/y", stat = "max_abs" },
          { name = "q_rms", signal = "/contact/ws1/left/Q", stat = "rms", along = "time",
            from = 0.02, to = 0.1 },
          { name = "yaw_p2p", signal = "/bodies/ws2/yaw", stat = "half_peak_to_peak" },
          { name = "y_sum", signals = { a = "/bodies/ws1/y", b = "/bodies/ws4/y" },
            fn = function(s) local t = 0 for i = 1, #s.a do t = t + s.a[i] - s.b[i] end return t end },
        } }
LUA
cat >"$TMP/full.lua" <<LUA
study { base = "$ROOT/scenarios/studies/case3_base.lua", output = "full",
        matrix = { ["run.distance"] = { 3, 4 } } }
LUA
cat >"$TMP/err.lua" <<LUA
study { base = "$ROOT/scenarios/studies/case3_base.lua",
        matrix = { ["run.distance"] = { 3 }, ["solver.step"] = { 2.5e-4, 0.01 } } }
LUA
cat >"$TMP/slow.lua" <<LUA
study { base = "$ROOT/scenarios/studies/case3_base.lua",
        matrix = { ["run.distance"] = { 40, 80, 120, 160, 200, 240 } } }
LUA
# A train of two wagons (tests/run/data/train_two_wagons.lua) with a parameter of one vehicle
# named by its name and a metric on the rear wagon's outputs: 4 runs of 0.05 s.
cat >"$TMP/train.lua" <<LUA
study { base = "$ROOT/tests/run/data/train_two_wagons.lua",
        matrix = { ["run.duration"] = { 0.05 }, ["contact.mu"] = { 0.2, 0.3 },
                   ["train.vehicles.rear.vehicle.bodies.car.mass"] = { 32000, 36000 } },
        metrics = {
          { name = "rear_q_rms", signal = "/vehicles/rear/contact/ws1/left/Q", stat = "rms" },
          { name = "front_y_max", signal = "/vehicles/front/bodies/ws1/y", stat = "max_abs" },
        } }
LUA
results() { find "$1" -maxdepth 1 -regex '.*_r[0-9]+\.h5' 2>/dev/null | sort; }
nresults() { results "$1" | wc -l; }
# name inode mtime(ns) of every result file
snapshot() { results "$1" | "$PY" -c '
import os, sys
for f in sys.stdin.read().split():
    s = os.stat(f)
    print(os.path.basename(f), s.st_ino, s.st_mtime_ns)'; }
unchanged() {  # every file of snapshot $1 is still there with the same inode and mtime
  local name ino mt
  while read -r name ino mt; do
    grep -q "^$name $ino $mt\$" "$2" || return 1
  done <"$1"
  return 0
}
waitfirst() {  # until a result file appears in $1 (or 120 s)
  local i
  for i in $(seq 1 1200); do
    [ "$(nresults "$1")" -gt 0 ] && return 0
    sleep 0.1
  done
  return 1
}
runsof() { pgrep -f -- "run .* --out $1/" | wc -l; }  # `workbench run` processes writing into $1
noorphans() {  # no run of folder $1 is alive (after at most 5 s)
  local i
  for i in $(seq 1 50); do
    [ "$(runsof "$1")" -eq 0 ] && return 0
    sleep 0.1
  done
  return 1
}
summary_ok() {  # $1: folder, $2: runs expected, all ok
  "$PY" - "$1" "$2" <<'PYEOF'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1] + "/summary.csv")))
bad = [(r["case"], r["repeat"], r["status"]) for r in rows if r["status"] != "ok"]
sys.exit(0 if len(rows) == int(sys.argv[2]) and not bad else f"{len(rows)} rows, not ok: {bad}")
PYEOF
}

case "$MODE" in
train)
  # A study of a train: local, as 2 shards + --summarize and, when built with MPI, as the farm,
  # the same summaries; the metrics read each vehicle's outputs.
  wb study "$TMP/train.lua" --out "$TMP/tlocal" --jobs 2 >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && summary_ok "$TMP/tlocal" 4 && ok "local run of a train study" \
    || bad "train local ($rc): $(cat "$TMP/e")"
  "$PY" - "$TMP/tlocal" <<'PY' && ok "the rear wagon's mass changes its wheel load" || bad "train metrics"
import csv, os, sys
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "summary.csv"))))
q = {}
for r in rows:
    mass = next(t for t in r["overrides"].split() if "car.mass=" in t).split("=")[1]
    q.setdefault(float(mass), []).append(float(r["metric_rear_q_rms"]))
    assert float(r["metric_front_y_max"]) >= 0.0, r
light, heavy = min(q[32000.0]), min(q[36000.0])
# A quarter of 4 t more on each of 8 wheels: about 4.9 kN more wheel load.
assert 3.5e3 < heavy - light < 6.5e3, (light, heavy)
PY
  for k in 1 2; do
    wb study "$TMP/train.lua" --out "$TMP/tshards" --shard "$k/2" --jobs 1 >/dev/null 2>"$TMP/e$k" \
      || bad "train shard $k/2: $(cat "$TMP/e$k")"
  done
  wb study "$TMP/train.lua" --out "$TMP/tshards" --summarize >/dev/null 2>"$TMP/e"
  "$PY" "$HERE/compare_summaries.py" "$TMP/tshards" "$TMP/tlocal" 4 \
    && ok "train: shards + --summarize, the local summaries" || bad "train shards differ from local"
  if [ "$MPI_BUILT" = 1 ]; then
    "${mpi[@]}" -np 3 "$WB" --root "$ROOT" study "$TMP/train.lua" --out "$TMP/tmpi" --mpi \
      </dev/null >/dev/null 2>"$TMP/e"; rc=$?
    [ $rc -eq 0 ] && "$PY" "$HERE/compare_summaries.py" "$TMP/tmpi" "$TMP/tlocal" 4 \
      && ok "train: the MPI farm, the local summaries" || bad "train MPI ($rc): $(cat "$TMP/e")"
  fi
  ;;
same)
  wb study "$TMP/six.lua" --out "$TMP/local" --jobs 2 >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && summary_ok "$TMP/local" 6 && ok "local run of 6 runs" || bad "local ($rc): $(cat "$TMP/e")"
  # The comparisons below cover the metrics: every run has its 4 values, stored in its file by
  # the runner that ran it; the compact cases share one stored track.
  "$PY" - "$TMP/local" <<'PY' && ok "4 metrics per run, stored in every case file" || bad "metrics missing"
import csv, glob, os, sys
import h5py
d = sys.argv[1]
rows = list(csv.DictReader(open(os.path.join(d, "summary.csv"))))
names = ["metric_y_max", "metric_q_rms", "metric_yaw_p2p", "metric_y_sum"]
assert all(r[n] not in ("", "nan") for r in rows for n in names), rows[0]
files = glob.glob(os.path.join(d, "case_*_r0.h5"))
assert len(files) == 6
for f in files:
    with h5py.File(f, "r") as h:
        assert "metrics" in h and "definitions_hash" in h["metrics"].attrs, f
        assert "stored_in" in h["track"].attrs and "compact" in h.attrs, f
PY
  [ "$(ls "$TMP/local/tracks" | wc -l)" -eq 1 ] && ok "one stored track for the 6 cases" \
    || bad "stored tracks: $(ls "$TMP/local/tracks")"
  for k in 1 2 3; do
    wb study "$TMP/six.lua" --out "$TMP/shards" --shard "$k/3" --jobs 1 >"$TMP/o$k" 2>"$TMP/e$k"
    rc=$?
    [ $rc -eq 0 ] && grep -q "shard $k/3: 2 of 6 runs, 0 already done, running 2" "$TMP/e$k" \
      && grep -q -- "--summarize" "$TMP/o$k" && ok "shard $k/3 ran its 2 runs" \
      || bad "shard $k/3 ($rc): $(cat "$TMP/o$k" "$TMP/e$k")"
    [ ! -e "$TMP/shards/summary.csv" ] && ok "shard $k/3 wrote no summary" || bad "shard $k/3 wrote a summary"
  done
  [ "$(nresults "$TMP/shards")" -eq 6 ] && ok "the 3 shards cover the 6 runs" \
    || bad "shards left $(nresults "$TMP/shards") results"
  wb study "$TMP/six.lua" --out "$TMP/shards" --shard 2/3 >/dev/null 2>"$TMP/e"
  grep -q "2 already done, running 0" "$TMP/e" && ok "a shard run again runs nothing" \
    || bad "shard rerun: $(cat "$TMP/e")"
  before="$(snapshot "$TMP/shards")"
  wb study "$TMP/six.lua" --out "$TMP/shards" --summarize >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && [ "$before" = "$(snapshot "$TMP/shards")" ] && ok "--summarize runs nothing" \
    || bad "--summarize ($rc): $(cat "$TMP/e")"
  "$PY" "$HERE/compare_summaries.py" "$TMP/shards" "$TMP/local" 6 \
    && ok "shards + --summarize: the local summaries" || bad "shards + --summarize differ from local"
  # The comparison can fail: a changed metric-free field (a run's status) is found.
  cp -r "$TMP/shards" "$TMP/changed"
  sed -i '2s/,ok,/,failed,/' "$TMP/changed/summary.csv"
  "$PY" "$HERE/compare_summaries.py" "$TMP/changed" "$TMP/local" >/dev/null \
    && bad "the comparison missed a changed status" || ok "the comparison finds a changed status"
  # --summarize of a folder with nothing: every run missing, exit 2.
  wb study "$TMP/six.lua" --out "$TMP/empty" --summarize >/dev/null 2>"$TMP/e"; rc=$?
  n="$(grep -c ',missing,' "$TMP/empty/summary.csv" 2>/dev/null)"
  [ $rc -eq 2 ] && [ "$n" = 6 ] && grep -q "6 missing" "$TMP/e" && ok "--summarize of nothing: 6 missing" \
    || bad "--summarize of an empty folder ($rc, $n missing): $(cat "$TMP/e")"
  # One result removed: that run, and only that one, is missing.
  rm "$(results "$TMP/shards" | head -1)"
  wb study "$TMP/six.lua" --out "$TMP/shards" --summarize >/dev/null 2>&1
  [ "$(grep -c ',missing,' "$TMP/shards/summary.csv")" = 1 ] && ok "a removed result is missing" \
    || bad "removed result: $(cat "$TMP/shards/summary.csv")"
  # A run that leaves no result (its step beyond the stability limit, refused when the model is
  # built: exit 1) is an error with its log's reason in both.
  wb study "$TMP/err.lua" --out "$TMP/errlocal" --jobs 2 >/dev/null 2>&1
  for k in 1 2; do wb study "$TMP/err.lua" --out "$TMP/errshards" --shard "$k/2" >/dev/null 2>&1; done
  wb study "$TMP/err.lua" --out "$TMP/errshards" --summarize >/dev/null 2>&1
  grep -q ',error,.*step' "$TMP/errshards/summary.csv" \
    && "$PY" "$HERE/compare_summaries.py" "$TMP/errshards" "$TMP/errlocal" \
    && ok "a run with no result: the same error row from shards + --summarize" \
    || bad "no-result run: $(cat "$TMP/errshards/summary.csv" "$TMP/errlocal/summary.csv")"
  for s in 0/3 4/3 3 a/b 1/0 -1/2 "2/3x" "1/3/4"; do
    wb study "$TMP/six.lua" --out "$TMP/bad" --shard "$s" >/dev/null 2>"$TMP/e"; rc=$?
    [ $rc -eq 1 ] && grep -q "expected K/N" "$TMP/e" && ok "--shard $s is an error" \
      || bad "--shard $s ($rc): $(cat "$TMP/e")"
  done
  [ "$(nresults "$TMP/bad" 2>/dev/null || echo 0)" -eq 0 ] && ok "a bad shard ran nothing" || bad "a bad shard ran runs"
  wb study "$TMP/six.lua" --shard 1/2 --summarize >/dev/null 2>&1
  [ $? -eq 1 ] && ok "--shard with --summarize is an error" || bad "--shard with --summarize accepted"
  if [ "$MPI_BUILT" != 1 ]; then
    wb study "$TMP/six.lua" --out "$TMP/nompi" --mpi >/dev/null 2>"$TMP/e"; rc=$?
    [ $rc -eq 1 ] && grep -q "without MPI" "$TMP/e" && ok "--mpi without MPI is an error" \
      || bad "--mpi without MPI ($rc): $(cat "$TMP/e")"
  fi
  ;;
output)
  # output = "full": plain case files (the track in each), no store; compact is the default.
  wb study "$TMP/full.lua" --out "$TMP/full" >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && [ ! -e "$TMP/full/tracks" ] && "$PY" - "$TMP/full" <<'PY' \
    && ok "output = full: plain case files" || bad "output = full ($rc): $(cat "$TMP/e")"
import glob, sys
import h5py
files = glob.glob(sys.argv[1] + "/case_*_r0.h5")
assert len(files) == 2
for f in files:
    with h5py.File(f, "r") as h:
        assert "centreline" in h["track"] and "compact" not in h.attrs, f
PY
  # A compact result whose stored track is gone is not done: the study runs it again.
  wb study "$TMP/six.lua" --out "$TMP/compact" --jobs 2 >/dev/null 2>&1
  wb study "$TMP/six.lua" --out "$TMP/compact" >/dev/null 2>"$TMP/e"
  grep -q "6 already done, running 0" "$TMP/e" && ok "compact results resume" \
    || bad "compact rerun: $(cat "$TMP/e")"
  rm -rf "$TMP/compact/tracks"
  wb study "$TMP/six.lua" --out "$TMP/compact" --jobs 2 >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && grep -q "0 already done, running 6" "$TMP/e" && [ -d "$TMP/compact/tracks" ] \
    && ok "a deleted track store runs the cases again" || bad "track store deleted ($rc): $(cat "$TMP/e")"
  # Switching the output mode is a change of inputs: the cases run again.
  sed -i 's/matrix = { \["run.distance"\] = { 3, 4 } }/matrix = { ["run.distance"] = { 3, 4 } }, output = "compact"/; s/output = "full", //' "$TMP/full.lua"
  wb study "$TMP/full.lua" --out "$TMP/full" >/dev/null 2>"$TMP/e"
  grep -q "0 already done, running 2" "$TMP/e" && ok "output mode in the case hash" \
    || bad "output mode switch: $(cat "$TMP/e")"
  ;;
same_mpi)
  wb study "$TMP/six.lua" --out "$TMP/local" --jobs 2 >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && ok "local run" || bad "local ($rc): $(cat "$TMP/e")"
  "${mpi[@]}" -np 3 "$WB" --root "$ROOT" study "$TMP/six.lua" --out "$TMP/mpi" --mpi \
    </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && grep -q "running 6 on 3 MPI ranks" "$TMP/e" && ok "mpirun -np 3 ran 6 runs" \
    || bad "mpirun ($rc): $(cat "$TMP/o" "$TMP/e")"
  grep -qi "fork" "$TMP/e" && bad "OpenMPI warned about fork: $(cat "$TMP/e")" || ok "no fork warning"
  for r in 0 1 2; do  # every rank took part (runs are handed out to whoever asks)
    grep -q "^rank $r:" "$TMP/e" && ok "rank $r ran runs" || bad "rank $r ran nothing: $(cat "$TMP/e")"
  done
  "$PY" "$HERE/compare_summaries.py" "$TMP/mpi" "$TMP/local" 6 \
    && ok "MPI farm: the local summaries" || bad "MPI farm summaries differ from local"
  [ -e "$TMP/mpi/summary.h5" ] && ok "summary.h5 written" || bad "no summary.h5"
  # A rank that cannot go on ends the farm (MPI_Abort) instead of leaving the others waiting.
  timeout 120 "${mpi[@]}" -np 2 "$WB" --root "$ROOT" study "$TMP/six.lua" --out /proc/no/such \
    --mpi </dev/null >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -ne 0 ] && [ $rc -ne 124 ] && grep -q "MPI rank [0-9]*: .*cannot create the study's output folder" "$TMP/e" \
    && ok "an unusable output folder ends the farm with the reason" \
    || bad "unusable folder ($rc): $(cat "$TMP/e")"
  "${mpi[@]}" -np 1 "$WB" --root "$ROOT" study "$TMP/six.lua" --out "$TMP/mpi" --mpi \
    </dev/null >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && grep -q "6 already done, running 0" "$TMP/e" && ok "a farm run again runs nothing" \
    || bad "farm rerun ($rc): $(cat "$TMP/e")"
  ;;
kill_shard)
  O="$TMP/kill"
  "$WB" --root "$ROOT" study "$TMP/slow.lua" --out "$O" --shard 1/2 --jobs 1 </dev/null \
    >/dev/null 2>"$TMP/e1" &
  pids+=($!)
  waitfirst "$O" || bad "no result within 120 s"
  kill -KILL "${pids[0]}"; wait "${pids[0]}" 2>/dev/null
  noorphans "$O" && ok "no run outlives the killed shard" || bad "orphan runs: $(pgrep -af -- "$O")"
  snapshot "$O" >"$TMP/before"
  nb=$(wc -l <"$TMP/before")
  [ "$nb" -ge 1 ] && [ "$nb" -lt 3 ] && ok "killed mid-shard ($nb of 3 done)" \
    || bad "kill did not land mid-shard ($nb of 3 done)"
  wb study "$TMP/slow.lua" --out "$O" --shard 1/2 --jobs 1 >/dev/null 2>"$TMP/e2"; rc=$?
  [ $rc -eq 0 ] && grep -q "$nb already done, running $((3 - nb))" "$TMP/e2" \
    && ok "the relaunched shard runs only the $((3 - nb)) unfinished runs" || bad "relaunch ($rc): $(cat "$TMP/e2")"
  snapshot "$O" >"$TMP/after"
  unchanged "$TMP/before" "$TMP/after" && ok "results finished before the kill are untouched" \
    || bad "results rewritten: $(cat "$TMP/before") / $(cat "$TMP/after")"
  [ "$(ls "$O" | grep -c '\.run-')" -eq 0 ] && ok "no stray .run-* file" || bad "stray: $(ls "$O")"
  wb study "$TMP/slow.lua" --out "$O" --shard 2/2 --jobs 2 >/dev/null 2>&1
  wb study "$TMP/slow.lua" --out "$O" --summarize >/dev/null 2>"$TMP/e3"; rc=$?
  [ $rc -eq 0 ] && summary_ok "$O" 6 && ok "both shards + --summarize: all 6 runs ok" \
    || bad "summary after the shards ($rc): $(cat "$TMP/e3")"
  ;;
kill_mpi)
  O="$TMP/kill"
  for sig in KILL TERM; do
    rm -rf "$O"
    "${mpi[@]}" -np 3 "$WB" --root "$ROOT" study "$TMP/slow.lua" --out "$O" --mpi \
      </dev/null >/dev/null 2>"$TMP/e1" &
    pid=$!; pids+=($pid)
    waitfirst "$O" || bad "no result within 120 s"
    kill -"$sig" "$pid"; wait "$pid" 2>/dev/null
    noorphans "$O" && ok "SIG$sig to mpirun: no run outlives the farm" \
      || bad "SIG$sig: orphan runs: $(pgrep -af -- "$O")"
    snapshot "$O" >"$TMP/before"
    nb=$(wc -l <"$TMP/before")
    [ "$nb" -ge 1 ] && [ "$nb" -lt 6 ] && ok "SIG$sig landed mid-study ($nb of 6 done)" \
      || bad "SIG$sig did not land mid-study ($nb of 6 done)"
    "${mpi[@]}" -np 3 "$WB" --root "$ROOT" study "$TMP/slow.lua" --out "$O" --mpi \
      </dev/null >/dev/null 2>"$TMP/e2"; rc=$?
    [ $rc -eq 0 ] && grep -q "$nb already done, running $((6 - nb)) on 3" "$TMP/e2" \
      && ok "relaunched farm runs only the $((6 - nb)) unfinished runs" || bad "relaunch ($rc): $(cat "$TMP/e2")"
    snapshot "$O" >"$TMP/after"
    unchanged "$TMP/before" "$TMP/after" && ok "results finished before SIG$sig are untouched" \
      || bad "results rewritten: $(cat "$TMP/before") / $(cat "$TMP/after")"
    summary_ok "$O" 6 && ok "all 6 runs ok after the relaunch" || bad "summary: $(cat "$O/summary.csv")"
    [ "$(ls "$O" | grep -c '\.run-')" -eq 0 ] && ok "no stray .run-* file" || bad "stray: $(ls "$O")"
  done
  ;;
*) echo "unknown mode $MODE" >&2; exit 2 ;;
esac

echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
