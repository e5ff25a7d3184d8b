#!/bin/sh
# `workbench effects --quick` on every shipped vehicle scenario (docs/effects.md): each exits 0 with
# every case checked (the effect on in the full scene, off in its case), the wheel-lift
# reproducer exits 2 (every case ends in its clean failure).
#   effects_all_scenarios.sh WORKBENCH PYTHON
set -u
BIN=$1
PY=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
export RAILBENCH_TABLE_CACHE="$TMP/.table-cache"
bad=0
for s in scenarios/validation/case*.lua scenarios/validation/variants/*.lua scenarios/hard/*.lua \
         scenarios/vehicle/manchester_guided_r500.lua scenarios/studies/case3_base.lua; do
  case "$s" in */lib.lua) continue ;; esac
  out="$TMP/$(echo "$s" | tr '/' '_')"
  "$BIN" effects "$s" --quick --jobs 2 --out "$out" >"$out.log" 2>&1
  rc=$?
  if [ $rc -ne 0 ]; then echo "FAIL $s: exit $rc"; tail -5 "$out.log"; bad=1; continue; fi
  "$PY" tests/effects/check_effects.py "$out" || { echo "FAIL $s: table"; bad=1; continue; }
  echo "ok   $s"
done
s=tests/app/data/wheel_lift/my_wheelset.lua
"$BIN" effects "$s" --quick --out "$TMP/lift" >"$TMP/lift.log" 2>&1
rc=$?
if [ $rc -ne 2 ]; then echo "FAIL $s: exit $rc (expected 2: every case ends in wheel lift)"; tail -5 "$TMP/lift.log"; bad=1; else echo "ok   $s (exit 2)"; fi
exit $bad
