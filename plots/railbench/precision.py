"""Placeholder: filled by the command's implementation."""
import sys


def main(argv=None) -> int:
    print("railbench precision: not implemented yet", file=sys.stderr)
    return 1
