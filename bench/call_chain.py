#!/usr/bin/env python3
"""What a reader meets who follows a run from the command line through the code.

Runs a debug (-O0 -g: nothing inlined, every call visible) build of the program under callgrind
on a short run of a scenario, then walks the calls that really happen from a root function
(default: the `run` command's runScenario) depth first, each function once, the calls of a
function in the order of their lines in its source, as a reader would follow them. Calls through
code outside workbench/ (the standard library, Eigen, std::function, HDF5) are followed through to
the workbench functions they reach. Reported:

  functions  the workbench functions the run enters below the root
  files      the files they are in ("rooms"; headers count: their functions are read there)
  stops      calls from a function in one file to a function in another (a change of room)
  climbs     stops into a folder on a higher floor than the caller's (a call back up the layers:
             a callback or virtual call into a folder that depends on the caller's folder)
  returns    stops into a file the walk had already entered and left

Floors come from the folders' CMake libraries: a folder's floor is one above the highest floor
of the libraries it links (core is floor 0). The numbers depend on the scenario (which stages run)
and on the definition above; compare them only with numbers from this script.

With --folders app,run,io the walk follows only the run path (the command, the run and its
writing) and counts every call into the physics folders as one stop without following it.

usage: call_chain.py --bin BUILD/workbench/app/workbench --root SRC [--scenario S] [--set K=V ...]
                     [--folders F,G] [--profile CALLGRIND_FILE]
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
from collections import defaultdict


def floors(root):
    """Floor of each workbench/ folder from its CMakeLists' target_link_libraries."""
    deps, lib_of = {}, {}
    wb = os.path.join(root, "workbench")
    for folder in sorted(os.listdir(wb)):
        cm = os.path.join(wb, folder, "CMakeLists.txt")
        if not os.path.isfile(cm):
            continue
        text = open(cm).read()
        for lib in re.findall(r"add_library\(\s*(rb_\w+)", text):
            lib_of[lib] = folder
        links = set()
        for block in re.findall(r"target_link_libraries\(([^)]*)\)", text):
            links |= set(re.findall(r"\b(rb_\w+)\b", block))
        deps[folder] = links
    memo = {}

    def floor(folder, seen=()):
        if folder in memo:
            return memo[folder]
        below = [lib_of[l] for l in deps.get(folder, ()) if l in lib_of and lib_of[l] != folder]
        f = 1 + max((floor(b, seen + (folder,)) for b in below if b not in seen), default=-1)
        memo[folder] = f
        return f

    return {folder: floor(folder) for folder in deps}


def parse(path):
    """Call edges per function from a callgrind file written with --dump-line=yes and
    --compress-strings=no: {(file, fn): [(call line, (file, callee))]}."""
    calls = defaultdict(list)
    fl = fn = None
    cfl = None
    pending = None
    with open(path, errors="replace") as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("fl="):
                fl = line[3:]
            elif line.startswith("fn="):
                fn = line[3:]
                cfl = None
            elif line.startswith(("cfl=", "cfi=")):
                cfl = line[4:]
            elif line.startswith("cfn="):
                pending = (cfl if cfl is not None else fl, line[4:])
            elif line.startswith("calls="):
                pass
            elif pending is not None and line[:1].isdigit():
                site = int(line.split()[0])
                calls[(fl, fn)].append((site, pending))
                pending, cfl = None, None
    return calls


def inside(file, root):
    return file is not None and os.path.realpath(file).startswith(
        os.path.join(os.path.realpath(root), "workbench") + os.sep)


def walk(calls, root_fn, root, folders=None):
    """Depth-first walk from root_fn; returns the list of workbench functions in visiting order
    with their caller. With `folders`, functions of other folders are entered (a stop) but their
    calls are not followed."""
    starts = [k for k in calls if k[1] and re.search(root_fn, k[1])]
    if not starts:
        sys.exit("call_chain: no function matching %r in the profile" % root_fn)
    start = starts[0]
    seen = {start}
    order = []  # (caller key, callee key)

    memo = {}

    def reached(key, through=None):
        """Workbench functions reached from key's calls in their line order, passing through
        functions outside workbench/ (memoised per outside function)."""
        if key in memo:
            return memo[key]
        out = []
        through = set() if through is None else through
        for site, callee in sorted(calls.get(key, []), key=lambda c: c[0]):
            if inside(callee[0], root):
                out.append(callee)
            elif callee not in through:
                through.add(callee)
                out.extend(reached(callee, through))
        if not inside(key[0], root):
            memo[key] = out
        return out

    stack = [(start, iter(reached(start)))]
    while stack:
        key, it = stack[-1]
        nxt = next(it, None)
        if nxt is None:
            stack.pop()
            continue
        if nxt in seen:
            continue
        seen.add(nxt)
        order.append((key, nxt))
        if folders is None or folder_of(nxt[0], root) in folders:
            stack.append((nxt, iter(reached(nxt))))
    return start, order


def folder_of(file, root):
    rel = os.path.relpath(os.path.realpath(file), os.path.join(os.path.realpath(root), "workbench"))
    return rel.split(os.sep)[0]


def measure(calls, root_fn, root, folders=None):
    fl = floors(root)
    start, order = walk(calls, root_fn, root, folders)
    entered = {start[0]}
    stops = climbs = returns = 0
    files = set([start[0]])
    for caller, callee in order:
        files.add(callee[0])
        if callee[0] == caller[0]:
            continue
        stops += 1
        if fl.get(folder_of(callee[0], root), 0) > fl.get(folder_of(caller[0], root), 0):
            climbs += 1
        if callee[0] in entered:
            returns += 1
        entered.add(callee[0])
    return {"root": start[1], "functions": len(order), "files": len(files), "stops": stops,
            "climbs": climbs, "returns": returns}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True, help="the workbench program of a -O0 -g build")
    ap.add_argument("--root", required=True, help="the source tree the program was built from")
    ap.add_argument("--scenario", default="scenarios/default/case3_kec_fast.lua")
    ap.add_argument("--set", action="append", default=["run.distance=2"],
                    help="overrides for the short run (default run.distance=2)")
    ap.add_argument("--function", default=r"runScenario", help="root function (a regex)")
    ap.add_argument("--profile", help="an existing callgrind file instead of running")
    ap.add_argument("--folders", help="comma-separated workbench/ folders whose functions are "
                    "followed (others are entered but not followed), e.g. app,run,io")
    a = ap.parse_args()
    prof = a.profile
    if not prof:
        tmp = tempfile.mkdtemp(prefix="call_chain.")
        prof = os.path.join(tmp, "callgrind.out")
        cmd = ["valgrind", "--tool=callgrind", "--dump-line=yes", "--dump-instr=no",
               "--compress-strings=no", "--compress-pos=no", "--callgrind-out-file=" + prof,
               a.bin, "run", os.path.join(a.root, a.scenario), "--out",
               os.path.join(tmp, "run.h5"), "--quiet"]
        for s in a.set:
            cmd += ["--set", s]
        r = subprocess.run(cmd, cwd=a.root, capture_output=True, text=True)
        if r.returncode not in (0, 2):
            sys.exit("call_chain: the run failed (%d): %s" % (r.returncode, r.stderr[-2000:]))
        print("profile  ", prof)
    folders = set(a.folders.split(",")) if a.folders else None
    m = measure(parse(prof), a.function, a.root, folders)
    for k in ("root", "functions", "files", "stops", "climbs", "returns"):
        print("%-10s %s" % (k, m[k]))


if __name__ == "__main__":
    main()
