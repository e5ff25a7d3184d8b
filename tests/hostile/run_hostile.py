#!/usr/bin/python3
"""Hostile-input corpus driver: runs the workbench on every case under cases/ and checks that it
fails cleanly (right exit code, message fragments), never hangs, crashes or reports an internal
error. The directive format is described in README.md beside this file."""
import argparse
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import forge_result  # noqa: E402  (beside this driver)

SANITIZER_MARKS = ("AddressSanitizer", "LeakSanitizer", "UndefinedBehaviorSanitizer",
                   "runtime error:", "ThreadSanitizer")
DIRECTIVE = re.compile(r"^--\s*hostile:\s*(.*)$")


def parse_case(path):
    """Directives of one case: dict of lists, from its leading comment lines."""
    d = {"args": [], "exit": [], "expect": [], "reject": [], "timeout": [], "symlink": [],
         "fifo": [], "env": [], "skip_root": [], "forge": [], "unchanged": []}
    for line in path.read_text(errors="replace").splitlines():
        if not line.startswith("--"):
            break
        m = DIRECTIVE.match(line)
        if not m:
            continue
        for tok in shlex.split(m.group(1)):
            key, sep, value = tok.partition("=")
            if not sep or key not in d:
                raise ValueError(f"{path.name}: bad directive '{tok}'")
            d[key].append(value)
    return d


def run_case(case, binary, root, outside, default_timeout):
    """Returns a list of failure strings (empty when the case passes)."""
    name = case.stem
    d = parse_case(case)
    fails = []
    with tempfile.TemporaryDirectory(prefix=f"hostile_{name}_") as tmp:
        work = Path(tmp) / "work"
        work.mkdir()
        shutil.copy(case, work / case.name)
        data = case.with_suffix(".d")
        if data.is_dir():
            for item in data.iterdir():
                if item.is_dir():
                    shutil.copytree(item, work / item.name)
                else:
                    shutil.copy(item, work / item.name)
        subst = {"{case}": case.name, "{outside}": str(outside), "{work}": str(work)}

        def expand(text):
            for k, v in subst.items():
                text = text.replace(k, v)
            return text

        for kind in d["forge"]:
            forge_result.forge(kind, work)
        # The files that must be byte for byte the same after the run (a file outside the work
        # folder that a forged link names).
        before = {}
        for spec in d["unchanged"]:
            target = work / expand(spec)
            before[spec] = target.read_bytes() if target.exists() else None
        for spec in d["symlink"]:
            link, _, target = expand(spec).partition(":")
            (work / link).parent.mkdir(parents=True, exist_ok=True)
            os.symlink(target, work / link)
        for spec in d["fifo"]:
            os.mkfifo(work / expand(spec))
        env = dict(os.environ)
        env["RAILBENCH_ROOT"] = str(root)
        env.setdefault("ASAN_OPTIONS", "detect_leaks=1")
        for spec in d["env"]:
            k, _, v = expand(spec).partition(":")
            env[k] = v
        args = shlex.split(expand(d["args"][-1] if d["args"] else "check"))
        # The case file goes after the subcommand unless the command names its input itself: a .lua
        # file, or a .h5 result (from the case's .d folder) for the commands that read results.
        if not any(a.endswith((".lua", ".h5")) for a in args):
            args.insert(1, case.name)
        timeout = float(d["timeout"][-1]) if d["timeout"] else default_timeout
        want_exit = int(d["exit"][-1]) if d["exit"] else 1
        try:
            p = subprocess.run([str(binary)] + args, cwd=work, env=env, stdin=subprocess.DEVNULL,
                               capture_output=True, text=True, errors="replace",
                               timeout=timeout)
        except subprocess.TimeoutExpired:
            return [f"hang: no exit within {timeout:g} s"]
        out = p.stdout + p.stderr
        if p.returncode < 0:
            fails.append(f"killed by signal {signal.Signals(-p.returncode).name}")
        elif p.returncode == 3 and want_exit != 3:
            fails.append("exit 3 (internal error) for an input problem")
        if p.returncode != want_exit:
            fails.append(f"exit {p.returncode}, expected {want_exit}")
        for mark in SANITIZER_MARKS:
            if mark in out:
                fails.append(f"sanitizer report ({mark})")
        for frag in d["expect"]:
            if expand(frag) not in out:
                fails.append(f"missing in output: {expand(frag)!r}")
        for frag in d["reject"]:
            if expand(frag) in out:
                fails.append(f"unwanted in output: {expand(frag)!r}")
        for spec, data in before.items():
            target = work / expand(spec)
            if (target.read_bytes() if target.exists() else None) != data:
                fails.append(f"{spec} changed: the command wrote outside its work folder")
        if fails:
            tail = "\n".join(out.strip().splitlines()[-12:])
            fails.append("command: " + " ".join(shlex.quote(a) for a in args) + "\n" + tail)
    return fails


def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--bin", required=True, help="the workbench executable")
    ap.add_argument("--root", default=str(Path(__file__).resolve().parents[2]),
                    help="project root (scenarios/, profiles/)")
    ap.add_argument("--cases", default=str(Path(__file__).resolve().parent / "cases"))
    ap.add_argument("--timeout", type=float, default=90.0, help="default seconds per case")
    ap.add_argument("only", nargs="*", help="case names to run (default: all)")
    a = ap.parse_args()
    cases = sorted(Path(a.cases).glob("*.lua"))
    if a.only:
        cases = [c for c in cases if c.stem in a.only]
    if not cases:
        print("no cases found", file=sys.stderr)
        return 1
    failed = 0
    with tempfile.TemporaryDirectory(prefix="hostile_outside_") as outside:
        # A folder outside every allowed root, holding files a scenario must never read.
        out = Path(outside)
        (out / "secret.lua").write_text("return { stolen = 'SECRET-OUTSIDE-TEXT' }\n")
        (out / "pkg").mkdir()
        (out / "pkg" / "secret.lua").write_text("return { stolen = 'SECRET-OUTSIDE-TEXT' }\n")
        for case in cases:
            try:
                fails = run_case(case, Path(a.bin).resolve(), Path(a.root).resolve(), out,
                                 a.timeout)
            except (ValueError, OSError) as e:
                fails = [f"driver: {e}"]
            status = "ok" if not fails else "FAIL"
            print(f"{status:4} {case.stem}", flush=True)
            for f in fails:
                print("     " + f.replace("\n", "\n     "))
            failed += bool(fails)
    print(f"{len(cases) - failed}/{len(cases)} hostile cases passed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
