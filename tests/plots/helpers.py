"""What the plots tests share: paths, the command line run as a process or in this process, the
one-line error check, and the work folder kept on a failure."""
import contextlib
import io
import os
import shutil
import subprocess
import types

import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.abspath(os.path.join(HERE, "..", ".."))
RBPLOT = os.path.join(ROOT, "plots", "rbplot")


def check(cond, msg):
    assert cond, msg


def rbplot(*args, timeout=120):
    """`plots/rbplot ARGS` as a process: .returncode, .stdout, .stderr."""
    return subprocess.run([RBPLOT, *args], capture_output=True, text=True, timeout=timeout)


def in_process(main, *args):
    """A command's main(argv) in this process (a new interpreter costs a matplotlib import)."""
    o, e = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(o), contextlib.redirect_stderr(e):
        code = main(list(args))
    return types.SimpleNamespace(returncode=code, stdout=o.getvalue(), stderr=e.getvalue())


def one_line_error(r, command, needle):
    """Exit status 1, one line "railbench COMMAND: error: ..." naming `needle`, nothing on
    stdout."""
    check(r.returncode == 1, f"exit {r.returncode}, expected 1")
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    check(len(lines) == 1, f"stderr has {len(lines)} lines: {r.stderr!r}")
    check(lines[0].startswith(f"railbench {command}: error:") and needle in lines[0],
          f"message {lines[0]!r} lacks {needle!r}")
    check(r.stdout.strip() == "", f"stdout {r.stdout!r}")


def work_folder(tmp, prepare=None):
    """A module fixture: runs `prepare` first, removes `tmp` when every test of the module
    passed (kept on a failure, or always with RB_KEEP_TMP=1)."""

    @pytest.fixture(scope="module", autouse=True)
    def fixture(request):
        failed = request.session.testsfailed
        if prepare:
            prepare()
        yield
        if request.session.testsfailed == failed and not os.environ.get("RB_KEEP_TMP"):
            shutil.rmtree(tmp, ignore_errors=True)
        else:
            print(f"work files kept in {tmp}")

    return fixture
