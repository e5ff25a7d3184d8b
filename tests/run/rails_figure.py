"""What the turnout scenes' checks share (check_turnout.py, check_crossing.py): the run's rails
figure drawn by `plots/rbplot run`, and the verdict they print."""
import os
import subprocess


def rails_figure_problem(path: str, folder: str) -> str:
    """Draws the figures of result `path` into `folder` beside it; '' when its rails figure
    (<stem>_rails.png) exists, else the problem."""
    out = os.path.join(os.path.dirname(os.path.abspath(path)), folder)
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    r = subprocess.run([os.path.join(root, "plots", "rbplot"), "run", path, "--outdir", out],
                       capture_output=True, text=True)
    stem = os.path.splitext(os.path.basename(path))[0]
    if r.returncode != 0 or not os.path.exists(os.path.join(out, f"{stem}_rails.png")):
        return f"no rails figure: {r.stdout[-300:]} {r.stderr[-300:]}"
    return ""


def verdict(path: str, folder: str, problems: list, ok: str) -> int:
    """The check's exit code: every problem (and a missing rails figure, drawn into `folder`)
    printed as FAIL, or `ok` when there is none."""
    figure = rails_figure_problem(path, folder)
    if figure:
        problems.append(figure)
    for p in problems:
        print("FAIL:", p)
    if not problems:
        print("ok:", ok)
    return 1 if problems else 0
