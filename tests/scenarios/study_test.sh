#!/usr/bin/env bash
# Studies and the table cache through the real command line: resume keyed on content (an edited
# base scenario or module re-runs every case, no change re-runs none, a damaged or foreign result
# file is not trusted), two runners sharing one folder run each case exactly once, a runner killed
# with SIGKILL and resumed at once, a study whose every case fails exits non-zero, a huge matrix
# is refused before anything runs, an unusable table-cache folder is a warning, a forged cache file
# is rebuilt, a run beyond --run-timeout is killed and reported.
# usage: study_test.sh WORKBENCH_BINARY   (run from the repository root)
set -u
WB="$1"
ROOT="$PWD"
PY=/usr/bin/python3
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
export RAILBENCH_STUDY_PLOTS=0
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok: $1"; }
bad() { fail=$((fail + 1)); echo "FAILED: $1"; }
wb()  { "$WB" --root "$ROOT" "$@" </dev/null; }

# A short guided run over a local module, and studies over it.
mkdir -p "$TMP/s"
cat >"$TMP/s/mine.lua" <<'LUA'
return { speed = 20 }
LUA
cat >"$TMP/s/base.lua" <<'LUA'
local lib = require "tracks.lib"
local wagon = require "vehicles.manchester_wagon1"
local mine = require "mine"
track { segments = lib.manchester_r500() }
vehicle (wagon { speed = mine.speed })
contact { method = "guided" }
solver { method = "abm", step = 1e-3 }
run { duration = 0.2, output = { every = 0.01 } }
LUA
cat >"$TMP/s/two.lua" <<'LUA'
study { base = "base.lua", matrix = { ["solver.method"] = { "rk4", "abm" } }, jobs = 2 }
LUA
cat >"$TMP/s/six.lua" <<'LUA'
study { base = "base.lua",
        matrix = { ["solver.method"] = { "rk4", "abm" }, ["run.duration"] = { 0.2, 0.3, 0.4 } },
        jobs = 1 }
LUA
cat >"$TMP/s/long.lua" <<'LUA'
study { base = "base.lua", matrix = { ["run.duration"] = { 2, 2.2 } },
        cases = { { ["solver.method"] = "rk4", ["solver.step"] = 1e-5 } }, jobs = 2 }
LUA
cat >"$TMP/s/allfail.lua" <<'LUA'
study { base = "base.lua", matrix = { ["solver.step"] = { 0.03, 0.07 } },
        cases = { { ["solver.method"] = "rk4" } }, jobs = 2 }
LUA
stray() { ls "$1" | grep -c '\.run-' ; }

# 1. Resume keyed on content.
O="$TMP/o1"
wb study "$TMP/s/two.lua" --out "$O" >/dev/null 2>"$TMP/e"; rc=$?
[ $rc -eq 0 ] && grep -q "0 already done, running 2" "$TMP/e" && ok "study runs 2 cases" \
  || bad "first run ($rc): $(cat "$TMP/e")"
wb study "$TMP/s/two.lua" --out "$O" >/dev/null 2>"$TMP/e"
grep -q "2 already done, running 0" "$TMP/e" && ok "nothing changed: nothing re-run" \
  || bad "no-change resume: $(cat "$TMP/e")"
sed -i 's/duration = 0.2/duration = 0.25/' "$TMP/s/base.lua"
wb study "$TMP/s/two.lua" --out "$O" >/dev/null 2>"$TMP/e"
grep -q "0 already done, running 2" "$TMP/e" && ok "one number of the base changed: every case re-run" \
  || bad "base edit resume: $(cat "$TMP/e")"
wb study "$TMP/s/two.lua" --out "$O" >/dev/null 2>"$TMP/e"
grep -q "2 already done, running 0" "$TMP/e" && ok "then nothing re-run" || bad "after base edit: $(cat "$TMP/e")"
sed -i 's/speed = 20/speed = 21/' "$TMP/s/mine.lua"
wb study "$TMP/s/two.lua" --out "$O" >/dev/null 2>"$TMP/e"
grep -q "0 already done, running 2" "$TMP/e" && ok "a required module changed: every case re-run" \
  || bad "module edit resume: $(cat "$TMP/e")"
"$PY" - "$O" <<'PYEOF' && ok "results are of the edited inputs" || bad "results of the edited inputs"
import glob, sys, h5py
files = sorted(glob.glob(sys.argv[1] + "/case_*_r0.h5"))
assert len(files) == 2, files
for f in files:
    h = h5py.File(f)
    v = h["vehicle/speed"][0] if "vehicle/speed" in h else None
    assert v is None or abs(v - 21) < 1e-12, v
    assert abs(h["time"][-1] - 0.25) < 1e-9, h["time"][-1]
    assert len(h.attrs["input_hash"]) == 16
PYEOF
# A damaged result and a valid result of another case under a case's name are not trusted.
set -- "$O"/case_*_r0.h5
head -c 300 "$1" >"$TMP/cut" && cp "$TMP/cut" "$1"
wb study "$TMP/s/two.lua" --out "$O" >/dev/null 2>"$TMP/e"
grep -q "1 already done, running 1" "$TMP/e" && ok "a truncated result file is run again" \
  || bad "truncated result: $(cat "$TMP/e")"
cp "$1" "$2"
wb study "$TMP/s/two.lua" --out "$O" >/dev/null 2>"$TMP/e"
grep -q "1 already done, running 1" "$TMP/e" && ok "another case's result under its name is run again" \
  || bad "foreign result: $(cat "$TMP/e")"
[ "$(stray "$O")" = 0 ] && ok "no temporary files left" || bad "stray files: $(ls "$O")"

# 2. Two runners on one folder: every case exactly once, all results valid.
O="$TMP/o2"
wb study "$TMP/s/six.lua" --out "$O" >/dev/null 2>"$TMP/e1" & p1=$!
wb study "$TMP/s/six.lua" --out "$O" >/dev/null 2>"$TMP/e2" & p2=$!
wait $p1; r1=$?; wait $p2; r2=$?
n=$(cat "$TMP/e1" "$TMP/e2" | grep -c ": ok  ")
[ $r1 -eq 0 ] && [ $r2 -eq 0 ] && [ "$n" = 6 ] && ok "two runners: 6 cases run once ($(cat "$TMP/e1" "$TMP/e2" | grep -c 'another runner') skipped or found done)" \
  || bad "two runners ($r1 $r2, $n runs): $(cat "$TMP/e1" "$TMP/e2")"
wb study "$TMP/s/six.lua" --out "$O" >/dev/null 2>"$TMP/e"
grep -q "6 already done, running 0" "$TMP/e" && [ "$(grep -c ',ok,' "$O/summary.csv")" = 6 ] \
  && [ "$(stray "$O")" = 0 ] && ok "two runners: 6 valid results" || bad "after two runners: $(cat "$TMP/e")"

# 3. A runner killed with SIGKILL while its cases run, resumed at once.
O="$TMP/o3"
"$WB" --root "$ROOT" study "$TMP/s/long.lua" --out "$O" </dev/null >/dev/null 2>"$TMP/e" & p=$!
for _ in $(seq 100); do [ "$(ls "$O" 2>/dev/null | grep -c '\.run-')" -ge 2 ] && break; sleep 0.1; done
sleep 0.5
kill -9 $p; wait $p 2>/dev/null
sleep 0.3
pgrep -f -- "--out $O/case_" >/dev/null && bad "runs outlived their killed runner" \
  || ok "runs die with their runner"
n=$(ls "$O" | grep -c '_r0\.h5$')
wb study "$TMP/s/long.lua" --out "$O" >/dev/null 2>"$TMP/e"; rc=$?
[ $rc -eq 0 ] && grep -q "$n already done, running $((2 - n))" "$TMP/e" \
  && [ "$(grep -c ',ok,' "$O/summary.csv")" = 2 ] && [ "$(stray "$O")" = 0 ] \
  && ok "killed runner: resumed at once, every case complete ($n had finished)" \
  || bad "kill -9 resume ($rc, $n finished before): $(cat "$TMP/e")"

# 4. Every case fails (each scenario loads, and each run refuses its step: the output interval is
# no multiple of it): the study exits 2.
wb study "$TMP/s/allfail.lua" --out "$TMP/o4" >/dev/null 2>"$TMP/e"; rc=$?
[ $rc -eq 2 ] && grep -q "no run of the study is ok" "$TMP/e" && ok "all cases failing exits 2" \
  || bad "all-fail study exit $rc: $(cat "$TMP/e")"

# 4a. `check` on a study file: every case's scenario loaded, nothing run or written.
wb check "$TMP/s/six.lua" >"$TMP/o" 2>"$TMP/e"; rc=$?
[ $rc -eq 0 ] && grep -q "six.lua: ok (a study of 6 cases" "$TMP/o" && [ ! -e out/six ] \
  && ok "check of a study file" || bad "check study ($rc): $(cat "$TMP/o" "$TMP/e")"

# 4b. A metric on a signal no case writes is refused before any run, every such metric at once,
# each with its did-you-mean; nothing is written.
cat >"$TMP/s/badsignal.lua" <<'LUA'
study { base = "base.lua", matrix = { ["solver.method"] = { "rk4", "abm" } },
  metrics = {
    { name = "y", signal = "/bodies/ws1/y", stat = "max_abs" },
    { name = "typo", signal = "/bodies/ws9/y", stat = "max_abs" },
    { name = "wheel", signal = "/contact/ws1/left/Q", stat = "max" },
  } }
LUA
wb study "$TMP/s/badsignal.lua" --out "$TMP/o4b" >/dev/null 2>"$TMP/e"; rc=$?
[ $rc -eq 1 ] && grep -q "badsignal.lua:4: study.metrics\[2\] (typo): signal '/bodies/ws9/y': no body 'ws9' (did you mean 'ws1'?)" "$TMP/e" \
  && grep -q "study.metrics\[3\] (wheel): signal '/contact/ws1/left/Q': the scenario has no wheel/rail contact model" "$TMP/e" \
  && grep -q "^2 problems found; nothing was run" "$TMP/e" && [ ! -e "$TMP/o4b" ] \
  && ok "metric signals checked before the runs" || bad "metric signals ($rc): $(cat "$TMP/e")"

# 5. A 1e8-case matrix is refused at check time, before anything runs.
wb study tests/scenario/study/huge.lua --out "$TMP/o5" >/dev/null 2>"$TMP/e"; rc=$?
[ $rc -eq 1 ] && grep -q "^tests/scenario/study/huge.lua:6: study: 100000000 cases (100 x 100 x 100 x 100 x 1) exceed max_cases = 10000; raise study.max_cases" "$TMP/e" \
  && [ ! -e "$TMP/o5" ] && ok "huge matrix refused" || bad "huge matrix ($rc): $(cat "$TMP/e")"

# 6. An unusable table-cache folder: a warning, the tables built in memory, never a failure.
SC=scenarios/validation/case1_R500_kec.lua
touch "$TMP/afile"
for cache in /proc/self/railbench-cache "$TMP/afile" "$TMP/afile/sub"; do
  RAILBENCH_TABLE_CACHE="$cache" wb run $SC --set run.duration=0.05 --out "$TMP/c.h5" --quiet >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && [ -f "$TMP/c.h5" ] && [ "$(grep -c "table cache folder '$cache' cannot be used" "$TMP/e")" = 1 ] \
    && ok "run with unusable cache $cache" || bad "run with cache $cache ($rc): $(cat "$TMP/e")"
  RAILBENCH_TABLE_CACHE="$cache" wb check $SC >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && grep -q "cannot be used" "$TMP/e" && ok "check with unusable cache $cache" \
    || bad "check with cache $cache ($rc): $(cat "$TMP/e")"
  rm -f "$TMP/c.h5"
done
if [ "$(id -u)" != 0 ]; then
  mkdir -p "$TMP/ro" && chmod 555 "$TMP/ro"
  RAILBENCH_TABLE_CACHE="$TMP/ro" wb run $SC --set run.duration=0.05 --out "$TMP/c.h5" --quiet >/dev/null 2>"$TMP/e"; rc=$?
  [ $rc -eq 0 ] && grep -q "cannot be used" "$TMP/e" && ok "read-only cache folder" || bad "read-only cache ($rc): $(cat "$TMP/e")"
  chmod 755 "$TMP/ro"
else
  echo "note: running as root, chmod cannot make a folder read-only; /proc stands in for it"
fi

# 7. A forged cache file (another table's valid file under this table's name) is rebuilt.
C="$TMP/cache"
RAILBENCH_TABLE_CACHE="$C" wb run $SC --set run.duration=0.05 --out "$TMP/a.h5" --quiet >/dev/null 2>&1
A=$(ls "$C"/*.kec)
RAILBENCH_TABLE_CACHE="$C" wb run $SC --set run.duration=0.05 --set profiles.gauge=1.437 --out "$TMP/b1.h5" --quiet >/dev/null 2>&1
B=$(ls "$C"/*.kec | grep -v "$A")
if [ -n "$A" ] && [ -n "$B" ] && cp "$A" "$B"; then
  RAILBENCH_TABLE_CACHE="$C" wb run $SC --set run.duration=0.05 --set profiles.gauge=1.437 --out "$TMP/b2.h5" --quiet >/dev/null 2>&1
  ! cmp -s "$A" "$B" && "$PY" - "$TMP" <<'PYEOF' && ok "forged cache file rebuilt, results unchanged" || bad "forged cache file"
import sys, h5py, numpy as np
d = sys.argv[1]
y = lambda n: h5py.File(f"{d}/{n}.h5")["bodies/ws/y"][:]
assert np.array_equal(y("b1"), y("b2")), "the forged table was used"
assert not np.array_equal(y("a"), y("b1")), "the two tables give the same result: no test"
PYEOF
else
  bad "forged cache set-up: A='$A' B='$B'"
fi

# 8. A run that does not end within --run-timeout is killed and reported, never waited for.
O="$TMP/o8"
start=$(date +%s)
wb study "$TMP/s/long.lua" --out "$O" --run-timeout 0.5 >/dev/null 2>"$TMP/e"; rc=$?
took=$(( $(date +%s) - start ))
n=$(grep -c "killed after 0.5 s" "$O/summary.csv" 2>/dev/null)
[ "$rc" -eq 2 ] && [ "$n" = 2 ] && [ "$took" -lt 60 ] && [ "$(stray "$O")" = 0 ] \
  && ok "hung runs killed after --run-timeout, reported in the summary" \
  || bad "run timeout (rc $rc, $n killed, ${took} s): $(tail -5 "$TMP/e")"

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
