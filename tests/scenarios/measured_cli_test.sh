#!/usr/bin/env bash
# Measured irregularities and the track's work bounds through the command line: each problem is
# refused by `check` (and `run`) with exit 1 and a file:line message, quickly, and writes nothing;
# a good measured scenario runs.
# usage: measured_cli_test.sh WORKBENCH_BINARY   (run from the repository root)
set -u
WB="$1"
D=tests/scenarios/data/measured
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok: $1"; }
bad() { fail=$((fail + 1)); echo "FAILED: $1"; }

# expect_input_error NAME FIXED-STRING COMMAND...: exit 1 within 20 s, the message on stderr.
expect_input_error() {
  local name="$1" want="$2"; shift 2
  local rc=0
  timeout 20 "$@" </dev/null >"$TMP/o" 2>"$TMP/e" || rc=$?
  if [ $rc -eq 1 ] && grep -qF -- "$want" "$TMP/e"; then ok "$name"; else bad "$name (exit $rc): $(cat "$TMP/e")"; fi
}

expect_input_error "mm file read as m: check" \
  "track_in_mm.csv:3: irregularity csv: vertical = 2.5 m is larger than a track irregularity can be (0.1 m) here and on" \
  "$WB" check "$D/mm_read_as_m.lua"
grep -qF 'Declare it: measured { unit = "mm" }' "$TMP/e" && ok "mm hint" || bad "mm hint: $(cat "$TMP/e")"
grep -q "^$D/track_in_mm.csv:3: " "$TMP/e" && ok "csv named as below the working directory" || bad "csv name: $(cat "$TMP/e")"
expect_input_error "mm file read as m: run writes nothing" "track_in_mm.csv:4: irregularity csv: alignment" \
  "$WB" run "$D/mm_read_as_m.lua" --out "$TMP/mm.h5"
[ ! -e "$TMP/mm.h5" ] && ok "no result for a bad csv" || bad "result written for a bad csv"

"$WB" check "$D/mm_declared.lua" </dev/null >"$TMP/o" 2>&1 && ok "unit = mm passes check" || bad "unit = mm: $(cat "$TMP/o")"

expect_input_error "file shorter than the track" \
  "$D/shorter_than_track.lua:4: track.irregularities: the track is 300 m long but " \
  "$WB" check "$D/shorter_than_track.lua"
grep -qF 'ends at s = 100 m (line 203)' "$TMP/e" && ok "shorter: names the file's last s and line" || bad "shorter: $(cat "$TMP/e")"
if "$WB" run "$D/shorter_than_track.lua" --set 'track.irregularities.beyond=zero' --out "$TMP/z.h5" --quiet \
     </dev/null >"$TMP/o" 2>"$TMP/e" && [ -f "$TMP/z.h5" ] \
   && grep -qF "shorter_than_track.lua:4: warning: track.irregularities: " "$TMP/e" \
   && grep -qF "covers s = 0 .. 100 m of the 300 m track; the track is perfect" "$TMP/e"; then
  ok "beyond = zero runs with a warning"
else
  bad "beyond = zero: $(cat "$TMP/o" "$TMP/e")"
fi

expect_input_error "track.step = 1e-7 refused" \
  "manchester_r500.lua:5: track: 500 m at step 1e-07 m needs 5e+09 spline knots, more than track.max_points = 1e+06" \
  "$WB" check scenarios/tracks/manchester_r500.lua --set track.step=1e-7
expect_input_error "psd step = 1e-6 refused" \
  "track.irregularities: 500 m at step 1e-06 m needs 5e+08 spline knots, more than track.max_points" \
  "$WB" check scenarios/tracks/manchester_r500_irregular.lua --set track.irregularities.step=1e-6
expect_input_error "segment of 1e308 m refused" \
  "track.segments[1] (tangent): length must be <= 1e+07 m (longer than any railway line), got 1e+308" \
  "$WB" check scenarios/tracks/manchester_r500.lua --set 'track.segments[1].length=1e308'
expect_input_error "user PSD of 1e300 refused" \
  "$D/psd_huge.lua:4: track.irregularities: alignment: the synthesised irregularity has an RMS of" \
  "$WB" check "$D/psd_huge.lua"

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
