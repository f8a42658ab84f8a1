#!/usr/bin/python3
"""Makes an OpenFOAM U-tube case (axisymmetric wedge pipe) from a template case.

    /usr/bin/python3 tools/make_tube_case.py TEMPLATE OUT --diameter D --length L
                     [--axial N] [--radial N]

TEMPLATE is an OpenFOAM tube case such as cases/deltaresColumn/reservoir (patches reservoir,
gate, wall, front, back, axis); OUT gets a copy with the pipe's diameter (m), developed length (m)
and cell counts changed in system/blockMeshDict (a 5-degree wedge, axis along x, x = 0 at the
reservoir patch). The tube's Hagen-Poiseuille resistance and inertial time are printed.
"""
import argparse
import math
import re
import shutil
import sys


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("template")
    ap.add_argument("out")
    ap.add_argument("--diameter", type=float, required=True, help="inner diameter, m")
    ap.add_argument("--length", type=float, required=True, help="developed length, m")
    ap.add_argument("--axial", type=int, default=None, help="cells along the pipe")
    ap.add_argument("--radial", type=int, default=None, help="cells across the radius")
    a = ap.parse_args()
    if a.diameter <= 0 or a.length <= 0:
        sys.exit("make_tube_case.py: diameter and length must be > 0 (m)")
    shutil.copytree(a.template, a.out, ignore=shutil.ignore_patterns("polyMesh", "[1-9]*", "0.*"))
    path = a.out + "/system/blockMeshDict"
    text = open(path).read()
    # outer vertices at the radius whose flat-sided 5-degree wedge has exactly pi r^2 / 72 of
    # cross-section (0.5 Rv^2 sin(5 deg) = pi r^2 / 72), so that a flux Q maps to Q / (pi d^2 / 4)
    r = a.diameter / 2
    rv = r * math.sqrt(2 * math.pi / (72 * math.sin(math.radians(5))))
    half = math.radians(2.5)
    values = {"L": a.length, "yR": rv * math.cos(half), "zR": rv * math.sin(half), "mzR": -rv * math.sin(half)}
    if a.axial:
        values["nAxial"] = a.axial
    if a.radial:
        values["nRadial"] = a.radial
    for key, v in values.items():
        text, n = re.subn(r"^(%s\s+)[^;]+;.*$" % key, lambda m: m.group(1) + repr(v) + ";", text, flags=re.M)
        if n != 1:
            sys.exit("make_tube_case.py: %s has no single '%s' entry" % (path, key))
    open(path, "w").write(text)
    nu, g = 8.93e-7, 9.81
    rt = 128 * nu * a.length / (math.pi * g * a.diameter ** 4)
    print("%s: d = %g m, L = %g m, Hagen-Poiseuille R_t = %.4g s/m2, inertial time d^2/(32 nu) = %.3g s"
          % (a.out, a.diameter, a.length, rt, a.diameter ** 2 / (32 * nu)))


if __name__ == "__main__":
    main()
