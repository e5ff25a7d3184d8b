"""The command line of the railbench plots:  plots/rbplot COMMAND [ARGS ...]

    run FILE.h5 [--outdir DIR] [--dpi N]     figures of a run (railbench/run.py)
    report FILE.h5 [--out FILE.html]         one self-contained HTML page of a run (report.py)
    tables FILE.h5 [--outdir DIR] [--dpi N]  figures of a contact-tables file (tables.py)
    study DIR [--dpi N]                      figures and CSVs of a study folder (study.py)
    compare-runs A.h5 B.h5 [...]             overlaid vehicle results, steady state (compare.py)
    docs OUT_DIR [--build DIR] [...]         the generated blocks of docs/ (docs.py)
    provenance record FILE.json [--root DIR] the source tree of a set of runs (provenance.py)
    validation-tables OUT_DIR                the CSVs of docs/validation.md (validation.py)
    three-way OUT_DIR                        the CSVs and figures of docs/three_way.md (three_way.py)
    effects-instructions OUT/effects [...]   callgrind instructions per evaluation (effects.py)
    precision DIR [...]                      `workbench precision`: errors, Pareto front (precision.py)
    stress DIR [...]                         `workbench stress`: the stability map (stress.py)
    effects DIR [...]                        `workbench effects`: cost and change per effect (effects_cmd.py)
    critical-speed DIR [...]                 `workbench critical-speed`: bifurcation diagram (critical_speed.py)
    modes DIR [--dpi N]                      `workbench modes`: root locus, damping vs speed (modes.py)

Each command's own --help tells its options.  Exit status 0 on success, 1 on an error (one line
"railbench COMMAND: error: ..." on stderr).
"""
import importlib
import sys

# command -> module of this package with main(argv) -> exit status
COMMANDS = {
    "run": "run",
    "report": "report",
    "tables": "tables",
    "study": "study",
    "compare-runs": "compare",
    "docs": "docs",
    "provenance": "provenance",
    "validation-tables": "validation",
    "three-way": "three_way",
    "effects-instructions": "effects",
    "precision": "precision",
    "stress": "stress",
    "effects": "effects_cmd",
    "critical-speed": "critical_speed",
    "modes": "modes",
}


def main(argv=None) -> int:
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv or argv[0] in ("-h", "--help") or argv[0] not in COMMANDS:
        out = sys.stdout if argv and argv[0] in ("-h", "--help") else sys.stderr
        if argv and argv[0] not in ("-h", "--help"):
            print(f"railbench: error: unknown command '{argv[0]}'", file=out)
        print(__doc__.strip(), file=out)
        return 0 if out is sys.stdout else 2
    module = importlib.import_module(f"railbench.{COMMANDS[argv[0]]}")
    return module.main(argv[1:])


if __name__ == "__main__":
    sys.exit(main())
