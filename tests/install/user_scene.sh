#!/bin/sh
# The installed program as a user meets it (issue 50, docs/install.md): `cmake --install` into a
# scratch prefix, then, from an empty folder outside the checkout and without RAILBENCH_ROOT, a
# scene of the user's own that requires a shipped vehicle and the turnout library (whose rail
# slices resolve beside the library, in the installed data directory) is checked, run briefly and
# reported (rbplot report from the installed plots package).
#   user_scene.sh CMAKE BUILD_DIR
set -eu
cmake=$1
build=$2
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rb_install_XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "install test: $*" >&2; exit 1; }

"$cmake" --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1 ||
  { cat "$tmp/install.log" >&2; fail "cmake --install failed"; }
bin="$tmp/prefix/bin"
data="$tmp/prefix/share/railbench"
[ -x "$bin/railbench" ] || fail "no $bin/railbench"
[ "$(readlink "$bin/workbench")" = railbench ] || fail "$bin/workbench is not a link to railbench"
for f in profiles/s1002_worn_0.3mm.txt scenarios/turnout/lib.lua scenarios/turnout/slices/60e1.txt \
         scenarios/vehicles/manchester_wagon1.lua scenarios/validation/common.lua \
         plots/rbplot plots/railbench/__main__.py; do
  [ -f "$data/$f" ] || fail "not installed: share/railbench/$f"
done

unset RAILBENCH_ROOT
mkdir "$tmp/project"
cd "$tmp/project"
version=$("$bin/railbench" --version)
echo "$version"
case "$version" in
  "railbench "*"(commit "?*")") ;;
  *) fail "--version names no commit: $version" ;;
esac

# The diverging route of the shipped turnout (scenarios/turnout/diverging_r190.lua), written as a
# user would in a folder of their own: the running rail's profile from the data directory.
cat >turnout.lua <<'LUA'
local c = require "validation.common"
local wagon = require "vehicles.manchester_wagon1"
local turnout = require "turnout.lib"
local toe, after, speed = 60, 60, 40 / 3.6
local stock, blade = turnout.switch_rails(toe, toe + turnout.curve_length + after)
track { segments = turnout.diverging_track(toe, after), step = 0.25 }
profiles { wheel = "s1002", rail = "scenarios/turnout/slices/60e1.txt", back_to_back = 1.360,
           gauge = 1.435, r0 = 0.46, inclination = 0.025,
           rail_slices = { left = stock }, extra_rails = { left = { blade } } }
contact { method = "elastic", creep = "polach", mu = 0.2364 }
vehicle (wagon { speed = speed, start = 39.22 })
c.abm(speed, 2.5e-4)
run { output = { every = 0.005 }, distance = 0.2 }
LUA
"$bin/railbench" check turnout.lua || fail "railbench check turnout.lua failed"
"$bin/railbench" run turnout.lua --out result.h5 --quiet || fail "railbench run turnout.lua failed"
[ -s result.h5 ] || fail "no result.h5"
# The run's report from the installed plots package: one page with the run's table and figures.
"$data/plots/rbplot" report result.h5 --out report.html >report.log 2>&1 ||
  { cat report.log >&2; fail "rbplot report failed"; }
grep -q "<table" report.html || fail "the report has no table"
grep -q "data:image/png;base64," report.html || fail "the report has no embedded figure"
for f in LICENSE NOTICE; do
  [ -f "$tmp/prefix/share/doc/railbench/$f" ] || fail "not installed: share/doc/railbench/$f"
done

# A file not found names the installed data directory among the places looked in and suggests
# the shipped file of that name.
cat >worn.lua <<'LUA'
track { segments = { tangent { length = 100 } } }
profiles { wheel = "s1002_worn_0.3mm.txt" }
LUA
if "$bin/railbench" check worn.lua >out.txt 2>&1; then fail "worn.lua passed check"; fi
cat out.txt
grep -qF "$data/s1002_worn_0.3mm.txt (the data directory)" out.txt ||
  fail "the installed data directory is not where the file was looked for"
grep -qF "did you mean 'profiles/s1002_worn_0.3mm.txt'" out.txt || fail "no hint"
echo "install test: ok"
