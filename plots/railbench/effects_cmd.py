"""Placeholder: filled by the command's implementation."""
import sys


def main(argv=None) -> int:
    print("railbench effects_cmd: not implemented yet", file=sys.stderr)
    return 1
