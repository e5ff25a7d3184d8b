"""The readers of a compact study case whose track is in a track store (workbench run
--track-store DIR --compact): plots/railbench/result.py loads the track from the store file, a
missing, corrupt or foreign store file is a clear ResultFileError, `workbench assess` and the run
figures work on such a case, and runs writing the same store file at once leave one complete file.

Usage: test_stored_track.py WORKBENCH   (from the repository root; exits 1 on the first failure)
"""
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "plots"))
from railbench.h5 import ResultFileError  # noqa: E402
from railbench.result import load_result  # noqa: E402

SCENARIO = os.path.join(ROOT, "scenarios", "studies", "case3_base.lua")
# 200 Hz outputs so that `assess` can work from the outputs alone.
CASE = ["--set", "run.duration=0.3", "--set", "run.output.every=0.005"]


def check(cond, what):
    if not cond:
        print(f"FAIL: {what}")
        sys.exit(1)
    print(f"ok: {what}")


def run(wb, out, *extra):
    cmd = [wb, "run", SCENARIO, *CASE, "--out", out, "--quiet", *extra]
    p = subprocess.run(cmd, capture_output=True, text=True)
    check(p.returncode == 0, f"run {' '.join(cmd[3:])}\n{p.stdout}{p.stderr}")


def error_of(path):
    try:
        load_result(path)
    except ResultFileError as e:
        return str(e)
    return None


def slice_of(part, whole, key="s"):
    """The arrays of `part` are a run of those of `whole` (the stretch a plain run writes of the
    whole track a store holds), starting where part[key] starts."""
    if len(part[key]) == 0:
        return False
    i = int(np.searchsorted(whole[key], part[key][0]))
    n = len(part[key])
    return set(part) == set(whole) and all(np.array_equal(part[k], whole[k][i:i + n])
                                           for k in part)


def compare_loaded(plain, stored):
    a, b = load_result(plain), load_result(stored)
    check(b.track.attrs.get("stored_in", "").startswith("tracks/"), "compact result references")
    check(slice_of(a.track.centreline, b.track.centreline),
          "centreline of the plain run's stretch equals the store's")
    check(all(np.array_equal(a.track.segments[k], b.track.segments[k])
              for k in a.track.segments), "segments from the store equal the plain run's")
    check(slice_of(a.irregularities.data, b.irregularities.data)
          and all(np.array_equal(a.irregularities.target[k], b.irregularities.target[k])
                  for k in a.irregularities.target),
          "irregularities of the plain run's stretch and target PSD equal the store's")
    check(a.irregularities.attrs == b.irregularities.attrs, "irregularity attributes equal")
    check(all(np.array_equal(a.bodies[n].data[k], b.bodies[n].data[k])
              for n in a.bodies for k in a.bodies[n].data), "body signals equal")
    check(all(np.array_equal(a.contact.wheelsets[w].sides[s][k], b.contact.wheelsets[w].sides[s][k])
              for w in a.contact.wheelsets for s in ("left", "right")
              for k in b.contact.wheelsets[w].sides[s]), "wheel signals equal")


def broken_stores(tmp, stored, other_store):
    """A missing, a corrupt and a foreign store file: each a ResultFileError naming it."""
    bad = os.path.join(tmp, "missing")
    os.makedirs(bad)
    shutil.copy(stored, bad)
    e = error_of(os.path.join(bad, os.path.basename(stored)))
    check(e is not None and "track store" in e and "no such file" in e, f"missing store: {e}")

    with h5py.File(stored, "r") as f:
        rel = f["track"].attrs["stored_in"]
        rel = rel.decode() if isinstance(rel, bytes) else str(rel)
    for name, make in (("corrupt", lambda p: open(p, "wb").write(b"not an HDF5 file")),
                       ("foreign", lambda p: shutil.copy(other_store, p))):
        d = os.path.join(tmp, name)
        os.makedirs(os.path.join(d, "tracks"))
        shutil.copy(stored, d)
        make(os.path.join(d, rel))
        e = error_of(os.path.join(d, os.path.basename(stored)))
        check(e is not None and "track store" in e, f"{name} store: {e}")
    check("references track" in (e or ""), "a foreign store names the hash it should have")


def concurrent(wb, tmp):
    """Four runs of the same track started together into an empty store."""
    d = os.path.join(tmp, "concurrent")
    os.makedirs(d)
    procs = [subprocess.Popen([wb, "run", SCENARIO, *CASE, "--out", os.path.join(d, f"c{k}.h5"),
                               "--quiet", "--compact", "--track-store", os.path.join(d, "tracks")],
                              stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
             for k in range(4)]
    rcs = [p.wait() for p in procs]
    check(rcs == [0, 0, 0, 0], f"concurrent runs ok: {rcs}")
    files = os.listdir(os.path.join(d, "tracks"))
    check(len(files) == 1 and files[0].endswith(".h5"), f"one store file, no temporary: {files}")
    with h5py.File(os.path.join(d, "tracks", files[0]), "r") as f:
        h = f["track"].attrs["track_hash"]
        h = h.decode() if isinstance(h, bytes) else str(h)
        check(h + ".h5" == files[0] and f["track/centreline/s"].size > 1,
              "the store file is complete and carries its hash")
    for k in range(4):
        check(load_result(os.path.join(d, f"c{k}.h5")).track.centreline["s"].size > 1,
              f"concurrent result {k} loads its track")


def figures(stored, tmp):
    from railbench.common import write_figures
    from railbench.run import FIGURES, build_figure
    r = load_result(stored)
    specs = [s for s in FIGURES if s.suffix in ("track_plan", "irregularities", "wheelsets")]
    check(len(specs) == 3 and all(s.is_available(r) for s in specs),
          "track and wheelset figures available on a compact case with a stored track")
    paths = write_figures(specs, r, os.path.join(tmp, "figs"), None, 60, "png", build_figure)
    check(len(paths) == 3 and all(os.path.getsize(p) > 0 for p in paths), f"figures {paths}")


def planted(wb, tmp):
    """A store file with the right hash attribute but other data (planted, or damaged in place)
    is not reused: the next run with that track writes it again."""
    folder = os.path.join(tmp, "planted")
    store = os.path.join(folder, "tracks")
    run(wb, os.path.join(folder, "a.h5"), "--compact", "--track-store", store)
    name = os.path.join(store, os.listdir(store)[0])
    with h5py.File(name, "r+") as f:
        ds = f["track/centreline/s"]
        good = float(ds[1])
        ds[1] = good + 1.0
    run(wb, os.path.join(folder, "b.h5"), "--compact", "--track-store", store)
    with h5py.File(name, "r") as f:
        check(float(f["track/centreline/s"][1]) == good,
              "a store file whose data differ from its hash is written again")


def main():
    wb = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="rb_study_output_")
    os.environ["RAILBENCH_TABLE_CACHE"] = os.path.join(tmp, "table-cache")
    try:
        plain = os.path.join(tmp, "plain.h5")
        study = os.path.join(tmp, "study")
        stored = os.path.join(study, "case.h5")
        run(wb, plain)
        run(wb, stored, "--compact", "--track-store", os.path.join(study, "tracks"))
        run(wb, os.path.join(study, "seed7.h5"), "--set", "track.irregularities.seed=7",
            "--compact", "--track-store", os.path.join(study, "tracks"))
        compare_loaded(plain, stored)
        with h5py.File(stored, "r") as f:
            check("compact" in f.attrs and "patch0" not in f["contact/ws1/left"],
                  "the compact case states what it left out and has no patch datasets")
        other = [os.path.join(study, "tracks", n) for n in os.listdir(os.path.join(study, "tracks"))
                 if load_result(os.path.join(study, "seed7.h5")).track.attrs["track_hash"] in n]
        check(len(other) == 1, "the other seed has its own store file")
        broken_stores(tmp, stored, other[0])

        p = subprocess.run([wb, "assess", stored], capture_output=True, text=True)
        check(p.returncode == 0 and "replaced /assessment" in p.stdout,
              f"workbench assess on the compact stored case\n{p.stdout}{p.stderr}")
        check(load_result(stored).track is not None, "the assessed case still loads its track")
        figures(stored, tmp)
        concurrent(wb, tmp)
        planted(wb, tmp)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print("all checks passed")


if __name__ == "__main__":
    main()
