#!/bin/sh
# `workbench effects` on a small scene (case 1, R = 500 m, a single wheelset: bump stops, series
# dampers, creep forces, patches, assessment), without callgrind, 0.2 s: the table, the figure and
# every case's check; then the hostile inputs (exit 1, nothing run).
#   effects_cmd_test.sh WORKBENCH PYTHON
set -u
BIN=$1
PY=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

"$BIN" effects scenarios/validation/case1_R500_kec.lua --no-callgrind --duration 0.2 --repeats 1 \
  --jobs 2 --out "$TMP/e" >"$TMP/log" 2>&1 || { cat "$TMP/log"; fail "exit $?"; }
grep -q "effect switched off" "$TMP/log" || { cat "$TMP/log"; fail "no table on stdout"; }
grep -q "flange_contact *always on" "$TMP/log" || { cat "$TMP/log"; fail "flange contact not reported"; }
[ -s "$TMP/e/effects.png" ] || fail "no figure"
"$PY" tests/effects/check_effects.py "$TMP/e" --expect series_dampers creep_forces patches \
  assessment "(all of them)" || fail "effects.csv"
# Resume: a second call runs nothing again.
"$BIN" effects scenarios/validation/case1_R500_kec.lua --no-callgrind --duration 0.2 --repeats 1 \
  --out "$TMP/e" >"$TMP/log2" 2>&1 || fail "second call"
grep -q "running 0 with" "$TMP/log2" || { cat "$TMP/log2"; fail "resume re-ran cases"; }

# Every switch of the schema has its on/off check in the table's code (flange contact is always on).
"$BIN" help scenario | "$PY" -c '
import re, sys
sys.path.insert(0, "plots")
from railbench.effects_cmd import CHECKS
text = sys.stdin.read().split("run.effects = { ... }")[1].split("\n\n")[0]
names = set(re.findall(r"^  (\w+) \(boolean", text, re.M))
missing = names - set(CHECKS) - {"flange_contact"}
sys.exit(1 if missing or len(names) < 9 else 0)' || fail "a switch without its check in effects_cmd.py"

# Hostile input: exit 1 with the problem named, no output folder made.
expect1() {
  want=$1; shift
  "$BIN" effects "$@" --no-callgrind --out "$TMP/bad" >"$TMP/bad.log" 2>&1
  rc=$?
  [ $rc -eq 1 ] || { cat "$TMP/bad.log"; fail "exit $rc for $*"; }
  grep -q "$want" "$TMP/bad.log" || { cat "$TMP/bad.log"; fail "no '$want' for $*"; }
  [ ! -e "$TMP/bad" ] || fail "output folder made for bad input $*"
}
expect1 "unknown_effect.lua:8: run.effects: unknown key 'bump_stop'" tests/effects/data/unknown_effect.lua
expect1 "did you mean 'bump_stops'" scenarios/validation/case1_R500_kec.lua --set run.effects.bump_stop=false
expect1 "nothing to switch off, the track has no irregularities" \
  scenarios/validation/case1_R500_kec.lua --set run.effects.irregularities=false
expect1 "flange_off.lua:8: .*cannot be switched off" tests/effects/data/flange_off.lua
expect1 "no vehicle" tests/effects/data/no_vehicle.lua
expect1 "unknown quantity 'lateral'" scenarios/validation/case1_R500_kec.lua --quantities y,lateral
expect1 "either --duration or --distance" scenarios/validation/case1_R500_kec.lua --duration 1 --distance 5
echo "ok"
