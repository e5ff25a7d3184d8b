#!/usr/bin/python3
"""Checks the shipped turnout scene's result (scenarios/turnout/diverging_r190.lua,
docs/turnouts.md): the leading wheelset's outer wheel meets the switch blade where the blade has
become a few millimetres wide and leaves the stock rail before the blade's top is level, the
contact per rail is written for the left side only, and the rails figure is drawn.

usage: check_turnout.py RESULT.h5
"""
import sys

import h5py
import numpy as np
from rails_figure import verdict

TOE = 60.0
LEFT_RADIUS = 190 + 1.435 / 2


def main(path):
    problems = []
    with h5py.File(path, "r") as f:
        if f["stats"].attrs["status"] not in (b"ok", "ok"):
            problems.append(f"run status {f['stats'].attrs['status']}")
        s = f["/bodies/ws1/s"][:]
        g = "/contact/ws1/left/rails/"
        stock, blade = f[g + "rail/normal_force"][:], f[g + "blade/normal_force"][:]
        if "rails" in f["/contact/ws1/right"]:
            problems.append("the right side has one rail: no /contact/ws1/right/rails expected")
        first = s[np.argmax(blade > 0)] - TOE
        last = s[np.nonzero(stock > 0)[0][-1]] - TOE
        width = lambda x: x * x / (2 * LEFT_RADIUS) * 1e3  # noqa: E731 [mm]
        # The flange meets the blade once the wheelset has moved out by its flangeway clearance
        # plus what the blade's lowered top costs it (about 9 mm, docs/turnouts.md); the tread
        # leaves the stock rail once the blade's top is nearly level (from 45 mm width).
        if not (5.0 < width(first) < 15.0):
            problems.append(f"first blade contact at x = {first:.2f} m (width {width(first):.1f} mm)")
        if not (25.0 < width(last) < 45.0):
            problems.append(f"last stock rail contact at x = {last:.2f} m "
                            f"(width {width(last):.1f} mm)")
        # After it the wheel is on the blade alone, carrying more than the static load (the
        # outer wheel in the curve).
        after = (s - TOE > last + 1.0)
        if not np.all(blade[after] > 50e3):
            problems.append("the wheel leaves the blade after the transfer")
        y = f[g + "blade/y"][:][after]
        if not (np.all(np.abs(y - 0.724) < 3e-3)):
            problems.append(f"blade contact position {y.min():.4f} .. {y.max():.4f} m, expected "
                            "the blade's gauge corner near 0.724 m")
    return verdict(path, "turnout_figures", problems,
                   f"blade from x = {first:.2f} m ({width(first):.1f} mm), stock rail until "
                   f"x = {last:.2f} m ({width(last):.1f} mm)")


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
