"""Issue 47 for Python's reader of result files (plots/railbench/h5.py): `rbplot run` on the
forged files of the hostile corpus (forge_result.py) refuses each with exit 1 and one line naming
the dataset or link, reads nothing through a link and leaves the linked file as it was."""
import os
import sys
import tempfile

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "plots"))
sys.path.insert(0, os.path.join(ROOT, "tests", "plots"))
sys.path.insert(0, HERE)

import forge_result  # noqa: E402
from helpers import in_process, one_line_error  # noqa: E402
from railbench import run as run_command  # noqa: E402


@pytest.fixture()
def work():
    with tempfile.TemporaryDirectory(prefix="rbplot_hostile_") as tmp:
        w = os.path.join(tmp, "work")
        os.mkdir(w)
        yield w


def _plot(work, kind):
    forge_result.forge(kind, work)
    return in_process(run_command.main, os.path.join(work, "result.h5"), "--outdir",
                      os.path.join(work, "figs"))


def test_plain_forged_result_draws(work):
    r = _plot(work, "plain")
    assert r.returncode == 0, r.stderr


def test_external_link_refused(work):
    victim = os.path.join(work, "..", "victim.h5")
    r = _plot(work, "external_schema")
    one_line_error(r, "run", "/schema is an external link to '../victim.h5:/schema'")
    with open(victim, "rb") as f:
        assert b"not railbench" in f.read()


def test_fifo_track_store_refused(work):
    r = _plot(work, "fifo_store")
    one_line_error(r, "run", "tracks/0123456789abcdef.h5: is a FIFO")


def test_huge_declared_refused(work):
    r = _plot(work, "huge_declared")
    one_line_error(r, "run", "/contact/ws1/left/Q declares 100000000000 values")


def test_nan_sample_refused(work):
    r = _plot(work, "nan_signal")
    one_line_error(r, "run", "/bodies/ws1/y holds nan at sample 100")
