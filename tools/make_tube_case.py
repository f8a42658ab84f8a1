#!/usr/bin/python3
"""Makes an OpenFOAM U-tube case (axisymmetric wedge pipe) from a template case.

    /usr/bin/python3 tools/make_tube_case.py TEMPLATE OUT --diameter D --length L
                     [--axial N] [--radial N]
                     [--valve-k K [--valve-at X]] [--bends N [--bend-k KB] [--bend-at X1,X2,..]]
                     [--zone-cells N]

TEMPLATE is an OpenFOAM tube case such as cases/deltaresColumn/reservoir (patches reservoir,
gate, wall, front, back, axis); OUT gets a copy with the pipe's diameter (m), developed length (m)
and cell counts changed in system/blockMeshDict (a 5-degree wedge, axis along x, x = 0 at the
reservoir patch). The tube's Hagen-Poiseuille resistance and inertial time are printed.

Minor losses (a partly open valve, the U-tube's bends) become porosity zones: short cellZones
made as named blocks by blockMesh, each with an fvOption explicitPorositySource of type
DarcyForchheimer (d = 0, f = 2 K / Lz on all three axes) in OUT/constant/fvOptions, so that the
zone of length Lz costs dp = K rho U^2 / 2 at the mean velocity U. The mesh's axial spacing
stays uniform (L / nAxial): a zone is --zone-cells whole cells, starting at the cell face
nearest to its position. One zone per loss: 'valve' and 'bend1', 'bend2', ... The sum of the
loss coefficients is printed. See docs/openfoam.md, "A valve or bends in your own case", for the
calibration (the zone acts on the local |u| u; tested within 2 % of K U^2 / 2).
"""
import argparse
import math
import os
import re
import shutil
import sys

# A smooth 90-degree bend (r/d ~ 1-2) in turbulent flow: K ~ 0.3 (White, Fluid Mechanics,
# Table 6.5: 90-degree regular flanged elbow 0.3, long-radius 0.2; the Hydraulic Institute's
# Pipe Friction Manual gives 0.1 at r/d = 5). Laminar bends cost more at low Re: measure or
# choose your own with --bend-k.
BEND_K_DEFAULT = 0.3


def fail(msg):
    sys.exit("make_tube_case.py: " + msg)


def strip_comments(text):
    """text with // and /* */ comments blanked (same length, so indices carry over)"""
    out, i, n = list(text), 0, len(text)
    while i < n:
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
        else:
            i += 1
            continue
        for k in range(i, j):
            if out[k] != "\n":
                out[k] = " "
        i = j
    return "".join(out)


def section_span(text, plain, key):
    """(start, end) of the 'key ( ... );' entry of blockMeshDict text (plain: comments blanked)"""
    m = re.search(r"^%s\b" % key, plain, flags=re.M)
    if not m:
        fail("blockMeshDict has no '%s' entry" % key)
    i = plain.find("(", m.end())
    depth = 0
    for j in range(i, len(plain)):
        if plain[j] == "(":
            depth += 1
        elif plain[j] == ")":
            depth -= 1
            if depth == 0:
                k = plain.find(";", j)
                return m.start(), k + 1
    fail("blockMeshDict: unbalanced '%s' entry" % key)


def blocks_text(stations, zones):
    """vertices, blocks, edges and boundary of a wedge pipe cut at the cell indices 'stations'
    (x = station * $dx); zones maps a block index to its cellZone name"""
    v = ["vertices", "("]
    for k, s in enumerate(stations):
        x = "$x%d" % k
        v.append("    (%s 0 0)  (%s $yR $mzR)  (%s $yR $zR)   // %d, %d, %d: axis, wall back, wall front"
                 % (x, x, x, 3 * k, 3 * k + 1, 3 * k + 2))
    v += [");", "", "blocks", "("]
    v.append("    // local x1 = axial, x2 = radial, x3 = azimuthal (back -> front); the axis face")
    v.append("    // collapses to an edge. A name after the vertices makes the block a cellZone.")
    for k in range(len(stations) - 1):
        a0, b0, f0, a1, b1, f1 = 3 * k, 3 * k + 1, 3 * k + 2, 3 * k + 3, 3 * k + 4, 3 * k + 5
        v.append("    hex (%d %d %d %d %d %d %d %d) %s(%d $nRadial 1) simpleGrading (1 $rGrade 1)"
                 % (a0, a1, b1, b0, a0, a1, f1, f0, zones[k] + " " if k in zones else "",
                    stations[k + 1] - stations[k]))
    v += [");", "", "edges", "(", ");", "", "boundary", "("]
    nb, last = len(stations) - 1, 3 * (len(stations) - 1)

    def patch(name, kind, faces, comment=None):
        v.extend(["    " + name, "    {"])
        if comment:
            v.extend("        // " + c for c in comment)
        v.append("        type %s;" % kind)
        v.append("        faces")
        v.append("        (")
        v.extend("            (%d %d %d %d)" % f for f in faces)
        v.extend(["        );", "    }"])

    patch("reservoir", "patch", [(0, 0, 2, 1)])
    patch("gate", "patch", [(last, last + 1, last + 2, last)])
    patch("wall", "wall", [(3 * k + 1, 3 * k + 2, 3 * k + 5, 3 * k + 4) for k in range(nb)])
    patch("front", "wedge", [(3 * k, 3 * k + 3, 3 * k + 5, 3 * k + 2) for k in range(nb)])
    patch("back", "wedge", [(3 * k, 3 * k + 1, 3 * k + 4, 3 * k + 3) for k in range(nb)])
    patch("axis", "empty", [(3 * k, 3 * k + 3, 3 * k + 3, 3 * k) for k in range(nb)],
          ["the collapsed faces on the axis: blockMesh drops their zero-area",
           "faces, so this patch has no faces; named so that it is not",
           "left as 'defaultFaces'"])
    v.append(");")
    return "\n".join(v)


FV_HEADER = """/*--------------------------------*- C++ -*----------------------------------*\\
  =========                 |
  \\\\      /  F ield         | OpenFOAM: The Open Source CFD Toolbox
   \\\\    /   O peration     | Version:  v1912
    \\\\  /    A nd           | Web:      www.openfoam.com
     \\\\/     M anipulation  |
\\*---------------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    location    "constant";
    object      fvOptions;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

// Minor losses as porosity zones (made by tools/make_tube_case.py). DarcyForchheimer (v1912,
// src/finiteVolume/cfdTools/general/porosityModel/DarcyForchheimer): the momentum sink is
//   S = -(mu d + rho |U| f / 2) U        (the code stores F = f / 2)
// so over a zone of length Lz a plug flow U loses dp / rho = (f Lz / 2) U^2: f = 2 K / Lz.
// f is the same on all three axes: the zone resists radial flow too, so the profile is made
// flat ahead of the zone and the zone's loss is K U^2 / 2 on the mean velocity.
"""


def fv_entry(name, k, lz, f, x0, x1):
    return """
%(name)s
{
    // K = %(k).6g over x = %(x0).6g .. %(x1).6g m (Lz = %(lz).6g m): f = 2 K / Lz
    type            explicitPorositySource;
    active          yes;

    explicitPorositySourceCoeffs
    {
        selectionMode   cellZone;
        cellZone        %(name)s;
        type            DarcyForchheimer;

        DarcyForchheimerCoeffs
        {
            d   (0 0 0);
            f   (%(f).10g %(f).10g %(f).10g);

            coordinateSystem
            {
                origin  (0 0 0);
                e1      (1 0 0);
                e2      (0 1 0);
            }
        }
    }
}
""" % dict(name=name, k=k, lz=lz, f=f, x0=x0, x1=x1)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("template")
    ap.add_argument("out")
    ap.add_argument("--diameter", type=float, required=True, help="inner diameter, m")
    ap.add_argument("--length", type=float, required=True, help="developed length, m")
    ap.add_argument("--axial", type=int, default=None, help="cells along the pipe")
    ap.add_argument("--radial", type=int, default=None, help="cells across the radius")
    ap.add_argument("--valve-k", type=float, default=0.0,
                    help="loss coefficient K of a partly open valve, dp = K rho U^2 / 2 on the "
                    "pipe's mean velocity (default 0: no valve)")
    ap.add_argument("--valve-at", type=float, default=None,
                    help="m from the reservoir end to the valve zone's upstream end "
                    "(default 10 diameters)")
    ap.add_argument("--bends", type=int, default=0, help="number of bends (default 0)")
    ap.add_argument("--bend-k", type=float, default=BEND_K_DEFAULT,
                    help="loss coefficient of one bend (default %g, a smooth 90-degree bend, "
                    "turbulent)" % BEND_K_DEFAULT)
    ap.add_argument("--bend-at", default=None,
                    help="comma-separated positions of the bends' zones, m from the reservoir "
                    "end (default: evenly spaced, at i L / (N + 1))")
    ap.add_argument("--zone-cells", type=int, default=2,
                    help="axial cells in each loss zone (default 2)")
    a = ap.parse_args()
    if a.diameter <= 0 or a.length <= 0:
        fail("diameter and length must be > 0 (m)")
    if a.valve_k < 0 or a.bend_k < 0 or a.bends < 0 or a.zone_cells < 1:
        fail("--valve-k, --bend-k and --bends must be >= 0, --zone-cells >= 1")
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
            fail("%s has no single '%s' entry" % (path, key))

    # minor losses: (name, K, position)
    losses = []
    if a.valve_k > 0:
        losses.append(("valve", a.valve_k, 10 * a.diameter if a.valve_at is None else a.valve_at))
    if a.bends > 0 and a.bend_k > 0:
        if a.bend_at:
            at = [float(s) for s in a.bend_at.split(",")]
            if len(at) != a.bends:
                fail("--bend-at has %d positions for %d bends" % (len(at), a.bends))
        else:
            at = [a.length * (i + 1) / (a.bends + 1) for i in range(a.bends)]
        losses += [("bend%d" % (i + 1), a.bend_k, x) for i, x in enumerate(at)]
    if losses:
        m = re.search(r"^nAxial\s+(\d+)\s*;", text, flags=re.M)
        if not m:
            fail("%s: nAxial is not a whole number" % path)
        n_axial = int(m.group(1))
        dx = a.length / n_axial
        nz = a.zone_cells
        cells = {}   # first cell index -> (name, K)
        for name, k, x in sorted(losses, key=lambda t: t[2]):
            i0 = int(round(x / dx))
            if x < 0 or x > a.length or i0 < 1 or i0 + nz > n_axial - 1:
                fail("the %s zone (%d cells of %.4g m from x = %.4g m) does not fit in the pipe "
                     "with a cell to spare at either end" % (name, nz, dx, x))
            if any(abs(i0 - j) < nz for j in cells):
                fail("the %s zone at x = %.4g m overlaps another loss zone (cells of %.4g m)" % (name, x, dx))
            cells[i0] = (name, k)
        stations, zones = [0], {}
        for i0 in sorted(cells):
            if i0 > stations[-1]:
                stations.append(i0)
            zones[len(stations) - 1] = cells[i0][0]
            stations.append(i0 + nz)
        stations.append(n_axial)
        plain = strip_comments(text)
        start = section_span(text, plain, "vertices")[0]
        end = section_span(text, plain, "boundary")[1]
        xs = "\n".join("x%-3d %.12g;" % (k, s * dx) for k, s in enumerate(stations))
        text = (text[:start]
                + "// blocks cut at the loss zones (tools/make_tube_case.py): x stations, m\n"
                + "// (the axial spacing stays $L / $nAxial = %.12g m)\n" % dx + xs + "\n\n"
                + blocks_text(stations, zones) + text[end:])
        fvo = [p for p in (a.out + "/constant/fvOptions", a.out + "/system/fvOptions") if os.path.exists(p)]
        fv_path = fvo[0] if fvo else a.out + "/constant/fvOptions"
        if fvo:
            body = open(fv_path).read()
            for name, _ in cells.values():
                if re.search(r"^%s\b" % name, strip_comments(body), flags=re.M):
                    fail("%s already has an entry '%s'" % (fv_path, name))
            body = body.rstrip("\n") + "\n\n// minor losses added by tools/make_tube_case.py\n"
        else:
            body = FV_HEADER
        lz = nz * dx
        for i0 in sorted(cells):
            name, k = cells[i0]
            body += fv_entry(name, k, lz, 2 * k / lz, i0 * dx, (i0 + nz) * dx)
            print("%s: %s zone x = %.6g .. %.6g m, K = %g, f = 2 K / Lz = %.6g 1/m"
                  % (a.out, name, i0 * dx, (i0 + nz) * dx, k, 2 * k / lz))
        body += "\n// ************************************************************************* //\n"
        open(fv_path, "w").write(body)
        print("%s: minor losses sum K = %g (%d zone%s in %s)"
              % (a.out, sum(k for _, k in cells.values()), len(cells), "s" * (len(cells) > 1),
                 os.path.relpath(fv_path, a.out)))
    open(path, "w").write(text)
    nu, g = 8.93e-7, 9.81
    rt = 128 * nu * a.length / (math.pi * g * a.diameter ** 4)
    print("%s: d = %g m, L = %g m, Hagen-Poiseuille R_t = %.4g s/m2, inertial time d^2/(32 nu) = %.3g s"
          % (a.out, a.diameter, a.length, rt, a.diameter ** 2 / (32 * nu)))


if __name__ == "__main__":
    main()
