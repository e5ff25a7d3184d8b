#!/usr/bin/env bash
# The README's complete example (the first ```lua block after "A complete example") must pass
# `workbench check`: a documented scenario that the workbench refuses is the first thing a new
# user tries. usage: readme_example_test.sh WORKBENCH_BINARY   (run from the repository root)
set -u
WB="$1"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
/usr/bin/python3 - README.md "$TMP/example.lua" <<'PY' || exit 1
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
at = text.find("A complete example")
m = re.search(r"```lua\n(.*?)```", text[at:], re.S) if at >= 0 else None
if not m:
    sys.exit("README.md: no ```lua block after 'A complete example'")
open(sys.argv[2], "w", encoding="utf-8").write(m.group(1))
PY
if "$WB" --root "$PWD" check "$TMP/example.lua" </dev/null >"$TMP/out" 2>&1; then
  echo "ok: the README example passes check"
else
  echo "FAILED: the README example is refused by check:"; cat "$TMP/out"; exit 1
fi
