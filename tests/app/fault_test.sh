#!/usr/bin/env bash
# Fault experiments on the result file life cycle, through the real command line:
#  - disk full (a 4 MiB tmpfs, when running as root): the run fails cleanly (exit 2, a message,
#    no crash), an earlier result under that name is left byte for byte, no temporary is left;
#  - two runs to one --out at once: both complete, the result is a whole file of one of them;
#  - SIGKILL during a run: the earlier result is untouched;
#  - --out naming a FIFO or a non-HDF5 file: refused (exit 1), nothing blocks or is replaced;
#  - assess on a full disk: exit 1, the file unchanged; a killed run's temporary removed by the
#    next run; an unusable --track-store refused with exit 1.
# usage: fault_test.sh WORKBENCH_BINARY   (run from the repository root)
set -u
WB="$1"
TMP="$(mktemp -d)"
MNT=""
cleanup() {
  [ -n "$MNT" ] && umount "$MNT" 2>/dev/null
  rm -rf "$TMP"
}
trap cleanup EXIT
pass=0; fail=0; skipped=0
ok()   { pass=$((pass + 1)); echo "ok: $1"; }
bad()  { fail=$((fail + 1)); echo "FAILED: $1"; }
skip() { skipped=$((skipped + 1)); echo "skipped: $1"; }
h5ok() {  # FILE STATUS [NTIME]: a complete result with /stats/status == STATUS (and NTIME outputs)
  /usr/bin/python3 - "$@" <<'PYEOF'
import sys, h5py
f = h5py.File(sys.argv[1], "r")
s = f["/stats"].attrs["status"]
s = s.decode() if isinstance(s, bytes) else s
assert s == sys.argv[2], s
if len(sys.argv) > 3:
    assert len(f["/time"]) == int(sys.argv[3]), len(f["/time"])
PYEOF
}
TRACK=scenarios/tracks/manchester_r500_irregular.lua
SHORT=(scenarios/validation/case1_R500_kec.lua --set run.duration=0.5 --quiet)

# 1. Disk full.
if [ "$(id -u)" -eq 0 ] && mkdir -p "$TMP/mnt" && mount -t tmpfs -o size=4m tmpfs "$TMP/mnt" 2>/dev/null; then
  MNT="$TMP/mnt"
  if "$WB" run "$TRACK" --out "$MNT/r.h5" --quiet </dev/null >"$TMP/log" 2>&1 &&
     "$WB" run "${SHORT[@]}" --set run.assessment.safety=true --out "$MNT/a.h5" </dev/null \
       >>"$TMP/log" 2>&1; then
    sum_before=$(md5sum <"$MNT/r.h5")
    sum_a=$(md5sum <"$MNT/a.h5")
    # Fill the disk, leaving too little for a second result.
    dd if=/dev/zero of="$MNT/fill" bs=64k 2>/dev/null
    rm -f "$MNT/fill"; dd if=/dev/zero of="$MNT/fill" bs=1k count=$(( $(df --output=avail -k "$MNT" | tail -1) - 200 )) 2>/dev/null
    "$WB" run "$TRACK" --out "$MNT/r.h5" --quiet </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
    [ $rc -eq 2 ] && ok "disk full: exit 2" || bad "disk full: exit $rc: $(cat "$TMP/e")"
    grep -q "cannot write the result" "$TMP/e" && ok "disk full: message" || bad "disk full: message: $(cat "$TMP/e")"
    [ "$(md5sum <"$MNT/r.h5")" = "$sum_before" ] && ok "disk full: earlier result unchanged" || bad "disk full: earlier result changed"
    ls "$MNT" | grep -q "\.tmp\." && bad "disk full: temporary left: $(ls "$MNT")" || ok "disk full: no temporary left"
    # assess on a full disk: nothing was run, the file is as it was: exit 1 (not 2) with a message.
    "$WB" assess "$MNT/a.h5" </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
    [ $rc -eq 1 ] && grep -q "the file is unchanged" "$TMP/e" && ok "assess on a full disk: exit 1" || bad "assess on a full disk: exit $rc: $(cat "$TMP/e")"
    [ "$(md5sum <"$MNT/a.h5")" = "$sum_a" ] && ok "assess on a full disk: file unchanged" || bad "assess on a full disk: file changed"
    ls "$MNT" | grep -q "\.tmp\." && bad "assess on a full disk: temporary left: $(ls "$MNT")" || ok "assess on a full disk: no temporary left"
  else
    bad "disk full: first run failed: $(cat "$TMP/log")"
  fi
else
  skip "disk full (needs root and a tmpfs mount)"
fi

# 2. Two runs to one --out at the same time.
out="$TMP/same.h5"
"$WB" run "${SHORT[@]}" --out "$out" </dev/null >"$TMP/a" 2>&1 & a=$!
"$WB" run "${SHORT[@]}" --out "$out" </dev/null >"$TMP/b" 2>&1 & b=$!
wait $a; ra=$?; wait $b; rb=$?
[ $ra -eq 0 ] && [ $rb -eq 0 ] && ok "concurrent runs: both exit 0" || bad "concurrent runs: exit $ra/$rb: $(cat "$TMP/a" "$TMP/b")"
h5ok "$out" ok 51 && ok "concurrent runs: one whole result" || bad "concurrent runs: result incomplete"
ls "$TMP" | grep -q "same.h5.tmp" && bad "concurrent runs: temporary left" || ok "concurrent runs: no temporary left"

# 3. SIGKILL in the middle of a run leaves the earlier result.
out="$TMP/kill.h5"
"$WB" run "${SHORT[@]}" --out "$out" </dev/null >/dev/null 2>&1
sum_before=$(md5sum <"$out")
# A run of many seconds (case 3 at 0.0625 ms steps), killed after 2 s while it is still running.
"$WB" run scenarios/validation/case3_kec.lua --set solver.step=6.25e-5 --out "$out" --quiet \
  </dev/null >/dev/null 2>&1 & k=$!
sleep 2
if kill -0 $k 2>/dev/null; then
  kill -9 $k 2>/dev/null; wait $k 2>/dev/null
  [ "$(md5sum <"$out")" = "$sum_before" ] && ok "SIGKILL: earlier result unchanged" || bad "SIGKILL: earlier result changed"
else
  wait $k; bad "SIGKILL: the run ended before the kill (make it longer)"
fi
# The killed run's temporary is removed by the next writer of that result (its process is gone).
ls "$TMP" | grep -q "kill.h5.tmp." && ok "SIGKILL: the killed run left its temporary" || skip "SIGKILL: no temporary left to clean"
"$WB" run "${SHORT[@]}" --out "$out" </dev/null >/dev/null 2>&1
ls "$TMP" | grep -q "kill.h5.tmp." && bad "SIGKILL: stale temporary not removed: $(ls "$TMP")" || ok "SIGKILL: stale temporary removed by the next run"

# 4. --out that is a FIFO or not an HDF5 file.
mkfifo "$TMP/fifo.h5"
timeout 20 "$WB" run "$TRACK" --out "$TMP/fifo.h5" --quiet </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
[ $rc -eq 1 ] && grep -q "is not an HDF5 result" "$TMP/e" && ok "--out FIFO refused" || bad "--out FIFO: exit $rc: $(cat "$TMP/e")"
echo "my notes" >"$TMP/notes.txt"
"$WB" run "$TRACK" --out "$TMP/notes.txt" --quiet </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
[ $rc -eq 1 ] && [ "$(cat "$TMP/notes.txt")" = "my notes" ] && ok "--out text file refused" || bad "--out text file: exit $rc"

# 5. --track-store that cannot be used (a file, a FIFO): refused before anything runs, exit 1.
for store in "$TMP/notes.txt" "$TMP/fifo.h5"; do
  timeout 20 "$WB" run "${SHORT[@]}" --track-store "$store" --out "$TMP/ts.h5" </dev/null >"$TMP/o" 2>"$TMP/e"; rc=$?
  [ $rc -eq 1 ] && grep -q -- "--track-store" "$TMP/e" && [ ! -e "$TMP/ts.h5" ] && ok "--track-store $(basename "$store") refused" || bad "--track-store $(basename "$store"): exit $rc: $(cat "$TMP/e")"
done

echo "$pass passed, $fail failed, $skipped skipped"
[ $fail -eq 0 ]
