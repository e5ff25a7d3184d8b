"""pytest set-up of the plots tests: the railbench package is imported from plots/ of this
checkout (the ctest registrations also set PYTHONPATH; this keeps a bare `python3 -m pytest
tests/plots` working)."""
import os
import sys

PLOTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "plots")
if os.path.abspath(PLOTS) not in (os.path.abspath(p) for p in sys.path):
    sys.path.insert(0, os.path.abspath(PLOTS))
