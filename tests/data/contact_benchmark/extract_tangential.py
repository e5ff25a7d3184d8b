#!/usr/bin/env python3
"""Reads the tangential results of CONTACT's Manchester A-2.2 examples (mbench_a22_left.ref_out,
mbench_a22_right.ref_out of eve70a/CONTACT, Apache-2.0) and writes mbench_a22_tangential_reference.csv:
per wheel and case the patch's normal force, its creepages at the reference point and the total
tangential forces. Only numbers are read; usage: extract_tangential.py DIR_WITH_REF_OUT > CSV."""
import re
import sys


def blocks(text):
    """The cases of one .ref_out, each as its text."""
    parts = re.split(r"^ Case +(\d+)\s*$", text, flags=re.M)
    for k in range(1, len(parts), 2):
        yield int(parts[k]), parts[k + 1]


def row_after(text, header):
    """The numbers on the line after the first line that contains header (whitespace-normalised)."""
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if " ".join(line.split()).startswith(header):
            return [float(v) for v in lines[i + 1].split()]
    raise ValueError("no line " + header)


def main():
    d = sys.argv[1]
    print("# Manchester contact benchmark case A-2.2, tangential results of CONTACT (Kalker's exact theory, "
          "steady rolling, Coulomb friction FSTAT = FKIN = 0.3, G = 82 GPa, nu = 0.28)")
    print("# Read by tests/data/contact_benchmark/extract_tangential.py from eve70a/CONTACT "
          "examples/mbench_a22_{left,right}.ref_out, commit d431cdbd125084c79bd59df83b4ac4c63c570ac9, "
          "Apache-2.0")
    print("# CONTACT's conventions and units: creepages at the patch's reference point (CKSI, CETA "
          "dimensionless, CPHI in 1/mm); FN, FX, FS the patch's total forces in its tangent plane [N] "
          "(FX, FS oppose the creepages, as railbench's forces on the wheel do), MN [N mm]; "
          "FX/FSTAT/FN and FS/FSTAT/FN as printed")
    print("wheel,case,fn_N,fx_N,fs_N,mn_Nmm,cksi,ceta,cphi_per_mm,veloc_mm_s,fx_mu_fn,fs_mu_fn,ncon,nadh,nslip")
    for wheel in ("left", "right"):
        text = open(f"{d}/mbench_a22_{wheel}.ref_out").read()
        for case, t in blocks(text):
            if t.count("DATA FOR CONTACT PATCH") != 1:
                raise ValueError(f"{wheel} case {case}: expected one patch")
            _, _, veloc, cksi, ceta, cphi = row_after(t, "CHI DQ VELOC CKSI CETA CPHI")
            fn, fx, fs, mn, _, _ = row_after(t, "FN FX FS MN ELAST.EN. FRIC.POWER")
            _, fxr, fsr, _, _ = row_after(t, "FN/G FX/FSTAT/FN FS/FSTAT/FN APPROACH PMAX")
            _, ncon, nadh, nslip, _, _ = row_after(t, "NPOT NCON NADH NSLIP INORM ITANG")
            print(f"{wheel},{case},{fn:g},{fx:g},{fs:g},{mn:g},{cksi:g},{ceta:g},{cphi:g},{veloc:g},"
                  f"{fxr:g},{fsr:g},{int(ncon)},{int(nadh)},{int(nslip)}")


main()
