#!/usr/bin/python3
"""Makes an OpenFOAM U-tube case (axisymmetric wedge pipe) from a template case.

    /usr/bin/python3 tools/make_tube_case.py TEMPLATE OUT --diameter D --length L
                     [--axial N] [--radial N]
                     [--valve-k K [--valve-at X]] [--bends N [--bend-k KB] [--bend-at X1,X2,..]]

TEMPLATE is an OpenFOAM tube case such as tools/tube_template (k-omega SST) or
cases/verification/openfoam_utube/reservoir (laminar), one block with patches reservoir,
gate, wall, front, back, axis); OUT gets a copy with the pipe's diameter (m), developed length (m)
and cell counts changed in system/blockMeshDict (a 5-degree wedge, axis along x, x = 0 at the
reservoir patch). The tube's Hagen-Poiseuille resistance and inertial time are printed.

Minor losses (a partly open valve, the U-tube's bends) become pressure-jump baffles: a pair of
cyclic patches NAME_half0 / NAME_half1 across the pipe, made by blockMesh at the cell face
nearest to the loss's position, with p of type porousBafflePressure (D 0, I K, length 1,
uniformJump true) and U (and any other field in 0/) cyclic. The jump is K U^2 / 2 (kinematic,
U = the mean velocity through the baffle, either direction) and uniform over the section, so it
changes the pressure level downstream and nothing else. porousBafflePressure's uniformJump
takes the plain (not area-weighted) mean of the face velocities, so with losses the radial cells
are equal-area rings (vertices at R sqrt(i / nRadial)); the axial spacing stays L / nAxial.
One baffle per loss: 'valve' and 'bend1', 'bend2', ... The sum of the loss coefficients is
printed. See docs/openfoam.md, "A valve or bends in your own case".
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


def blocks_text(stations, baffles):
    """vertices, blocks, edges and boundary of a wedge pipe cut at the stations x = $x0, $x1, ...;
    baffles maps a station's index to the name of the cyclic baffle there"""
    v, idx, n = ["vertices", "("], [], 0   # idx[k]: first vertex (upstream side, downstream side)
    for k in range(len(stations)):
        sides = 2 if k in baffles else 1
        for side in range(sides):
            what = "" if sides == 1 else " (%s side of %s)" % (("upstream", "downstream")[side], baffles[k])
            v.append("    ($x%d 0 0)  ($x%d $yR $mzR)  ($x%d $yR $zR)   // %d, %d, %d: axis, wall back, wall front%s"
                     % (k, k, k, n, n + 1, n + 2, what))
            n += 3
        idx.append((n - 3 * sides, n - 3))
    v += [");", "", "blocks", "("]
    v.append("    // local x1 = axial, x2 = radial, x3 = azimuthal (back -> front); the axis face")
    v.append("    // collapses to an edge")
    nb = len(stations) - 1
    blk = [(idx[k][1], idx[k + 1][0]) for k in range(nb)]   # (upstream axis vertex, downstream)
    for k, (a, b) in enumerate(blk):
        v.append("    hex (%d %d %d %d %d %d %d %d) (%d $nRadial 1) simpleGrading (1 $rEqualArea 1)"
                 % (a, b, b + 1, a + 1, a, b, b + 2, a + 2, stations[k + 1] - stations[k]))
    v += [");", "", "edges", "(", ");", "", "boundary", "("]

    def patch(name, kind, faces, comment=(), extra=None):
        v.extend(["    " + name, "    {"])
        v.extend("        // " + c for c in comment)
        v.append("        type %s;" % kind)
        if extra:
            v.append("        " + extra)
        v.extend(["        faces", "        ("])
        v.extend("            (%d %d %d %d)" % f for f in faces)
        v.extend(["        );", "    }"])

    first, last = idx[0][1], idx[-1][0]
    patch("reservoir", "patch", [(first, first, first + 2, first + 1)])
    patch("gate", "patch", [(last, last + 1, last + 2, last)])
    for k in sorted(baffles):
        up, down = idx[k]
        patch(baffles[k] + "_half0", "cyclic", [(up, up + 1, up + 2, up)],
              ["a pressure-jump baffle (porousBafflePressure in 0/p): its upstream side"],
              "neighbourPatch %s_half1;" % baffles[k])
        patch(baffles[k] + "_half1", "cyclic", [(down, down, down + 2, down + 1)],
              ["the downstream side (its own vertices: blockMesh keeps the two apart)"],
              "neighbourPatch %s_half0;" % baffles[k])
    patch("wall", "wall", [(a + 1, a + 2, b + 2, b + 1) for a, b in blk])
    patch("front", "wedge", [(a, b, b + 2, a + 2) for a, b in blk])
    patch("back", "wedge", [(a, a + 1, b + 1, b) for a, b in blk])
    patch("axis", "empty", [(a, b, b, a) for a, b in blk],
          ["the collapsed faces on the axis: blockMesh drops their zero-area",
           "faces, so this patch has no faces; named so that it is not",
           "left as 'defaultFaces'"])
    v.append(");")
    return "\n".join(v)


def add_patch_entries(path, entries):
    """inserts the text 'entries' at the end of the boundaryField of the field file 'path'"""
    text = open(path).read()
    plain = strip_comments(text)
    m = re.search(r"^boundaryField\b", plain, flags=re.M)
    if not m:
        fail("%s has no boundaryField" % path)
    depth = 0
    for j in range(plain.find("{", m.end()), len(plain)):
        depth += {"{": 1, "}": -1}.get(plain[j], 0)
        if depth == 0:
            break
    else:
        fail("%s: unbalanced boundaryField" % path)
    for name in re.findall(r"^    (\w+_half[01])$", entries, flags=re.M):
        if re.search(r"^\s*%s\s*$" % name, plain[m.end():j], flags=re.M):
            fail("%s already has an entry %s" % (path, name))
    k = text.rfind("\n", 0, j) + 1
    open(path, "w").write(text[:k] + entries + text[k:])


def p_entries(name, k, x):
    return """    %(name)s_half0
    {
        // a localised loss at x = %(x).6g m (tools/make_tube_case.py):
        // jump = -(D nu + I |U| / 2) U length, U = the mean of the face velocities
        // (uniformJump; the faces are equal-area rings, so U = Q / A), so the
        // kinematic pressure drops by K U |U| / 2 across it, K = I length = %(k).6g
        type            porousBafflePressure;
        patchType       cyclic;
        D               0;
        I               %(k).10g;
        length          1;
        uniformJump     true;
        jump            uniform 0;
        value           uniform 0;
    }
    %(name)s_half1
    {
        $%(name)s_half0;
    }
""" % dict(name=name, k=k, x=x)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("template")
    ap.add_argument("out")
    ap.add_argument("--diameter", type=float, required=True, help="inner diameter, m")
    ap.add_argument("--length", type=float, required=True, help="developed length, m")
    ap.add_argument("--axial", type=int, default=None, help="cells along the pipe")
    ap.add_argument("--radial", type=int, default=None, help="cells across the radius")
    ap.add_argument("--valve-k", type=float, default=0.0,
                    help="loss coefficient K of a partly open valve: dp = K rho U^2 / 2 at the "
                    "pipe's mean velocity U (default 0: no valve)")
    ap.add_argument("--valve-at", type=float, default=None,
                    help="the valve's distance from the reservoir end, m (default 10 diameters)")
    ap.add_argument("--bends", type=int, default=0, help="number of bends (default 0)")
    ap.add_argument("--bend-k", type=float, default=BEND_K_DEFAULT,
                    help="loss coefficient of one bend (default %g: a smooth 90-degree bend, "
                    "turbulent flow)" % BEND_K_DEFAULT)
    ap.add_argument("--bend-at", default=None,
                    help="the bends' distances from the reservoir end, m, comma-separated "
                    "(default: evenly spaced, i L / (N + 1))")
    a = ap.parse_args()
    if a.diameter <= 0 or a.length <= 0:
        fail("diameter and length must be > 0 (m)")
    if a.valve_k < 0 or a.bend_k < 0 or a.bends < 0:
        fail("--valve-k, --bend-k and --bends must be >= 0")
    losses = []   # (name, K, position)
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
    path = a.template + "/system/blockMeshDict"   # checked and changed before OUT is made
    text = open(path).read()
    if re.search(r"^x1\s", text, flags=re.M):
        fail("%s already has loss baffles (a case made by this script); start from a single-block "
             "template such as tools/tube_template" % path)
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

    if losses:
        whole = {}
        for key in ("nAxial", "nRadial"):
            m = re.search(r"^%s\s+(\d+)\s*;" % key, text, flags=re.M)
            if not m:
                fail("%s: %s is not a whole number" % (path, key))
            whole[key] = int(m.group(1))
        n_axial, n_radial = whole["nAxial"], whole["nRadial"]
        dx = a.length / n_axial
        at_face = {}   # cell face index -> (name, K)
        for name, k, x in sorted(losses, key=lambda t: t[2]):
            if not 0 <= x <= a.length:
                fail("the %s at x = %g m is outside the pipe (0 .. %g m)" % (name, x, a.length))
            # the nearest interior cell face (a cell at least between the baffle and either end)
            i = min(max(int(round(x / dx)), 1), n_axial - 1)
            if i in at_face:
                fail("the %s and the %s fall on the same cell face (x = %.6g m, cells of %.4g m): "
                     "move one (--valve-at, --bend-at) or give more axial cells"
                     % (at_face[i][0], name, i * dx, dx))
            at_face[i] = (name, k)
        stations = [0] + sorted(at_face) + [n_axial]
        baffles = {s: at_face[i][0] for s, i in enumerate(stations) if i in at_face}
        plain = strip_comments(text)
        start = section_span(text, plain, "vertices")[0]
        end = section_span(text, plain, "boundary")[1]
        # equal-area radial rings: vertex i at R sqrt(i / N), one cell per grading section
        rings = [math.sqrt(i / n_radial) for i in range(n_radial + 1)]
        grading = " ".join("(%.10f 1 1)" % (rings[i + 1] - rings[i]) for i in range(n_radial))
        head = ["// Made by tools/make_tube_case.py with %d loss baffle%s: the pipe is cut into blocks"
                % (len(at_face), "s" * (len(at_face) > 1)),
                "// at x = $x1 ... (m; the axial spacing stays $L / $nAxial = %.12g m), and the" % dx,
                "// radial cells are equal-area rings (vertex i at R sqrt(i / nRadial); these",
                "// %d sections of one cell each replace $rGrade), so that porousBafflePressure's" % n_radial,
                "// plain mean of the face velocities is the mean velocity Q / A"]
        head += ["x%-3d %.12g;" % (k, s * dx) for k, s in enumerate(stations)]
        head += ["rEqualArea (%s);" % grading, ""]
        text = text[:start] + "\n".join(head) + "\n" + blocks_text(stations, baffles) + text[end:]
    shutil.copytree(a.template, a.out, ignore=shutil.ignore_patterns("polyMesh", "[1-9]*", "0.*"))
    open(a.out + "/system/blockMeshDict", "w").write(text)
    if losses:
        # the fields: p jumps, everything else is plain cyclic
        for field in sorted(os.listdir(a.out + "/0")):
            fpath = a.out + "/0/" + field
            if not os.path.isfile(fpath) or "boundaryField" not in open(fpath).read():
                continue
            if field == "p":
                entries = "".join(p_entries(name, k, i * dx) for i, (name, k) in sorted(at_face.items()))
            else:
                entries = "".join("    %s_half0\n    {\n        type            cyclic;\n    }\n"
                                  "    %s_half1\n    {\n        type            cyclic;\n    }\n"
                                  % (name, name) for name, _ in at_face.values())
            add_patch_entries(fpath, entries)
        if not os.path.isfile(a.out + "/0/p"):
            fail("%s has no 0/p for the baffles' pressure jumps" % a.template)
        for i, (name, k) in sorted(at_face.items()):
            print("%s: %s baffle at x = %.6g m, K = %g" % (a.out, name, i * dx, k))
        print("%s: minor losses sum K = %g (%d baffle%s; dp = sum K rho U^2 / 2)"
              % (a.out, sum(k for _, k in at_face.values()), len(at_face), "s" * (len(at_face) > 1)))
    nu, g = 8.93e-7, 9.81
    rt = 128 * nu * a.length / (math.pi * g * a.diameter ** 4)
    print("%s: d = %g m, L = %g m, Hagen-Poiseuille R_t = %.4g s/m2, inertial time d^2/(32 nu) = %.3g s"
          % (a.out, a.diameter, a.length, rt, a.diameter ** 2 / (32 * nu)))


if __name__ == "__main__":
    main()
