#!/usr/bin/env bash
# End-to-end checks of the workbench command line: shipped scenarios run and plot, bad input exits
# 1 with file:line messages and writes nothing, help and --version work, nothing prompts.
# usage: cli_test.sh WORKBENCH_BINARY   (run from the repository root)
set -u
WB="$1"
PY=/usr/bin/python3
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
pass=0; fail=0
ok()  { pass=$((pass + 1)); echo "ok: $1"; }
bad() { fail=$((fail + 1)); echo "FAILED: $1"; }

# 1. Every shipped track scenario runs, writes HDF5, and the plots are drawn.
for sc in scenarios/tracks/*.lua; do
  [ "$(basename "$sc")" = lib.lua ] && continue
  out="$TMP/$(basename "$sc" .lua).h5"
  if "$WB" run "$sc" --out "$out" --quiet </dev/null >"$TMP/log" 2>&1 && [ -f "$out" ] && [ ! -f "$out.tmp" ]; then
    ok "run $sc"
  else
    bad "run $sc: $(cat "$TMP/log")"; continue
  fi
  if plots/rbplot run "$out" >"$TMP/plog" 2>&1; then ok "plots $sc"; else bad "plots $sc: $(cat "$TMP/plog")"; fi
done
n=$(ls "$TMP"/manchester_r500_irregular_*.png 2>/dev/null | wc -l)
[ "$n" -ge 4 ] && ok "irregular track gives >= 4 figures ($n)" || bad "irregular track gave $n figures"

# 1b. Vehicle runs: guided wagon, single wheelset with KEC and LUT contact (shortened), plotted.
for sc in scenarios/vehicle/manchester_guided_r500.lua scenarios/validation/case1_R500_kec.lua \
          scenarios/validation/case1_R500_lut.lua; do
  out="$TMP/$(basename "$sc" .lua).h5"
  if "$WB" run "$sc" --out "$out" --quiet --set run.duration=2 </dev/null >"$TMP/log" 2>&1 \
     && plots/rbplot run "$out" >"$TMP/plog" 2>&1; then ok "run+plot $sc"; else bad "run $sc: $(cat "$TMP/log" "$TMP/plog")"; fi
done
"$PY" - "$TMP/case1_R500_kec.h5" <<'PYEOF' && ok "contact outputs: loads balance the weight" || bad "contact outputs"
import sys, h5py, numpy as np
f = h5py.File(sys.argv[1])
n = f["contact/ws/left/normal_force"][0] + f["contact/ws/right/normal_force"][0]
assert f["/contact"].attrs["method"] in (b"kec", "kec"), f["/contact"].attrs["method"]
assert 1.0e5 < n < 1.2e5, n   # quarter wagon on one wheelset: ~109 kN with the wheelset weight
assert np.all(np.isfinite(f["bodies/ws/y"][:]))
PYEOF

# 2. Bad input: exit code 1, the file:line message on stderr, no result file.
out="$TMP/bad.h5"
"$WB" run tests/scenario/bad/many.lua --out "$out" </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
[ $rc -eq 1 ] && ok "bad scenario exits 1" || bad "bad scenario exit code $rc"
grep -q "^tests/scenario/bad/many.lua:5: track.segments\[2\] (curve): unknown key 'raduis' (did you mean 'radius'?)$" "$TMP/e" \
  && ok "bad scenario message" || bad "bad scenario message: $(cat "$TMP/e")"
grep -q "^6 problems found; nothing was run.$" "$TMP/e" && ok "problem count" || bad "problem count: $(cat "$TMP/e")"
[ ! -e "$out" ] && [ ! -e "$out.tmp" ] && ok "no result for bad input" || bad "result written for bad input"

"$WB" check scenarios/tracks/manchester_r500.lua --set track.step=-1 </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
[ $rc -eq 1 ] && grep -q "^<command line>: track: step must be > 0 m, got -1$" "$TMP/e" \
  && ok "check with bad --set" || bad "check with bad --set ($rc): $(cat "$TMP/e")"
"$WB" check scenarios/tracks/manchester_r500.lua </dev/null >"$TMP/o" 2>&1 && ok "check ok" || bad "check: $(cat "$TMP/o")"

# 3. Help, version, usage errors.
"$WB" help scenario >"$TMP/h" 2>&1 && grep -q "irregularities" "$TMP/h" && grep -q "rail_inclination (number, rad) default 0.025" "$TMP/h" \
  && ok "help scenario" || bad "help scenario: $(head -5 "$TMP/h")"
"$WB" --version 2>&1 | grep -q "^railbench [0-9]" && ok "--version" || bad "--version"
"$WB" frobnicate </dev/null >/dev/null 2>&1; rc=$?
[ $rc -ne 0 ] && ok "unknown command fails" || bad "unknown command exit $rc"

# 4. A study: every case runs in its own process; a case with bad options is recorded as an error
#    without aborting the study; a second run resumes (runs nothing new).
"$WB" study tests/scenarios/data/study_small.lua --out "$TMP/study" </dev/null >"$TMP/so" 2>"$TMP/se"; rc=$?
nok=$(grep -c ",ok," "$TMP/study/summary.csv" 2>/dev/null || true)
nerr=$(grep -c ",error," "$TMP/study/summary.csv" 2>/dev/null || true)
[ $rc -eq 0 ] && [ "$nok" = 4 ] && [ "$nerr" = 4 ] && [ -f "$TMP/study/summary.h5" ] \
  && ok "study runs 8 cases (4 ok, 4 failing runs recorded)" || bad "study rc=$rc ok=$nok err=$nerr: $(cat "$TMP/se")"
grep -q "is not a multiple of the" "$TMP/study/summary.csv" && ok "study records the reason" || bad "study reason"
# A case whose scenario does not load (an option the method does not have) is refused before any
# run, at the study line where it is written: the study runs nothing and writes nothing.
sed 's/\["solver.step"\] = 3e-3/["solver.rtol"] = 1e-6/' tests/scenarios/data/study_small.lua >"$TMP/bad_option.lua"
cp tests/scenarios/data/study_base.lua "$TMP/"
"$WB" study "$TMP/bad_option.lua" --out "$TMP/study_bad" </dev/null >/dev/null 2>"$TMP/se3"; rc=$?
[ $rc -eq 1 ] && grep -q "bad_option.lua:7: solver: rtol has no effect with method 'rk4'" "$TMP/se3" \
  && grep -q "nothing was run" "$TMP/se3" && [ ! -e "$TMP/study_bad" ] \
  && ok "a case that does not load: refused before any run" || bad "bad-option study rc=$rc: $(cat "$TMP/se3")"
"$WB" study tests/scenarios/data/study_small.lua --out "$TMP/study" </dev/null >/dev/null 2>"$TMP/se2"
grep -q "4 already done, running 4" "$TMP/se2" && ok "study resumes" || bad "study resume: $(head -2 "$TMP/se2")"

# 4b. Study keys of a case (label, role, per-case base) and the study's figures and tables, drawn
#     by `workbench study` itself (plots/rbplot study) from the summary and the case files.
"$WB" study tests/scenarios/data/study_plots.lua --out "$TMP/sp" </dev/null >"$TMP/spo" 2>"$TMP/spe"; rc=$?
[ $rc -eq 0 ] && [ "$(grep -c ",ok," "$TMP/sp/summary.csv" 2>/dev/null)" = 7 ] \
  && ok "study with labels, roles and a per-case base" || bad "study_plots rc=$rc: $(cat "$TMP/spe" "$TMP/spo")"
grep -q "^case_[0-9a-f]*,0,no bump stops,,.*bases/no_bumpstops.lua," "$TMP/sp/summary.csv" \
  && grep -q ",KEC abm,baseline," "$TMP/sp/summary_cases.csv" \
  && grep -q ",LUT K=1e10,," "$TMP/sp/summary_cases.csv" \
  && ok "study labels, roles and bases in the summaries" || bad "study summaries: $(head -3 "$TMP/sp/summary.csv")"
missing=""
for f in study_cost.png study_cost.csv study_failures.csv study_accuracy_lut_vs_kec.csv \
         study_accuracy_lut_vs_kec.png study_lut_integrators.png study_work_precision.csv \
         study_work_precision.png study_work_precision_rms.png study_effects.csv study_effects.png; do
  [ -s "$TMP/sp/$f" ] || missing="$missing $f"
done
[ -z "$missing" ] && ok "study figures and tables" || bad "study outputs missing:$missing ($(cat "$TMP/spe"))"
"$PY" - "$TMP/sp" <<'PYEOF' && ok "study tables: accuracy, work precision, effects" || bad "study tables"
import csv, os, sys
d = sys.argv[1]
rows = lambda n: list(csv.DictReader(open(os.path.join(d, n))))
acc = rows("study_accuracy_lut_vs_kec.csv")
assert {r["wheelset"] for r in acc} == {"ws1", "ws2", "ws3", "ws4", "all"}, acc
assert all(float(r["max_abs_mm"]) >= float(r["mean_abs_mm"]) >= 0 for r in acc)
wp = {r["label"]: r for r in rows("study_work_precision.csv")}
chk = [r for r in wp.values() if r["note"].startswith("reference_check")]
assert len(chk) == 1 and float(chk[0]["y_max_mm"]) < 1e-2, chk
assert float(wp["KEC abm"]["y_max_mm"]) > 0 and wp["LUT K=1e10"]["note"], wp
eff = {r["label"]: r for r in rows("study_effects.csv")}
assert float(eff["KEC abm"]["relative_to_baseline"]) == 1.0
assert float(eff["no bump stops"]["us_per_eval"]) > 0
assert eff["no bump stops"]["rhs_evals"] == eff["KEC abm"]["rhs_evals"]
PYEOF
plots/rbplot study "$TMP/nonexistent" >/dev/null 2>"$TMP/pe"; rc=$?
[ $rc -eq 1 ] && grep -q "^railbench study: error: " "$TMP/pe" && ok "rbplot study on a non-study folder" || bad "rbplot study error ($rc)"

# 5. Contact tables of the default profiles, and their figures.
if "$WB" tables scenarios/tracks/manchester_r500.lua --out "$TMP/tables.h5" </dev/null >"$TMP/to" 2>&1 \
   && grep -q "two-point contact (left wheel) at y = 6.2" "$TMP/to"; then ok "tables"; else bad "tables: $(cat "$TMP/to")"; fi
if plots/rbplot tables "$TMP/tables.h5" >"$TMP/tp" 2>&1 && [ "$(grep -c '\.png$' "$TMP/tp")" -ge 5 ]; then
  ok "tables figures"; else bad "tables figures: $(cat "$TMP/tp")"; fi

echo "$pass passed, $fail failed"
[ $fail -eq 0 ]
