#!/usr/bin/env python3
"""Grid convergence of the fluidisation verification problems (physics.md section 4):
problem 7 (bed expansion) and problem 9 (batch settling) at three cell sizes.

    /usr/bin/python3 tools/convergence.py [--build build] [--work /tmp/quicksand-convergence]
                                          [--cells 0.0124,0.0062,0.0031]

Copies cases/verification/bed_expansion and batch_settling into the work directory with each
cell size, runs them with the built quicksand, and prints a Markdown table of the errors against
the drift-flux closed forms (the same measurements as tests/verification/test_BedExpansion.cpp and
test_BatchSettling.cpp), for docs/verification.md. The 3.1 mm runs take several minutes each.
"""
import argparse
import math
import os
import shutil
import sys

import numpy as np

import quicksand as qs

# P0 sand of both cases: Kozeny-Carman from D = 0.261 mm, Ergun A = 150, B = 1.75
MU, RHO, RHOS, G, D, A, B = 8.91e-4, 998.2, 2650.0, 9.81, 2.61e-4, 150.0, 1.75


def kappa(n):
    n = min(n, 0.95)
    return D * D * n ** 3 / (A * (1 - n) ** 2)


def qeq(n):
    """Filter velocity of the equilibrium suspension at porosity n (drag carries its weight)."""
    i = (RHOS / RHO - 1) * (1 - n)
    a = MU / kappa(n)
    b = B / (math.sqrt(A) * min(n, 0.95) ** 1.5) * RHO / math.sqrt(kappa(n))
    return (-a + math.sqrt(a * a + 4 * b * i * RHO * G)) / (2 * b)


def neq(q):
    lo, hi = 1e-3, 0.95
    for _ in range(200):
        m = 0.5 * (lo + hi)
        lo, hi = (m, hi) if qeq(m) < q else (lo, m)
    return 0.5 * (lo + hi)


def fit(t, y, t0, t1):
    s = (t >= t0) & (t <= t1)
    b, a = np.polyfit(t[s], y[s], 1)
    return b


def run(build, src, work, name, cell):
    out = os.path.join(work, f"{name}_{cell}")
    shutil.rmtree(out, ignore_errors=True)
    shutil.copytree(src, out, ignore=shutil.ignore_patterns("output*"))
    binary = qs.find_quicksand(os.path.join(build, "mpm", "quicksand"))
    return qs.arrays(qs.run(out, {"grid.cell_size": cell, "output.fields": False}, binary=binary).series())


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--build", default="build")
    ap.add_argument("--work", default="/tmp/quicksand-convergence")
    ap.add_argument("--cells", default="0.0124,0.0062,0.0031")
    a = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    os.makedirs(a.work, exist_ok=True)
    cells = [float(c) for c in a.cells.split(",")]

    # problem 7: n1 = 0.38 at U_mf, stepped to U2 = 1.380e-3
    n1, U2, H1, filt = 0.38, 1.380e-3, 0.186, 0.0124
    U1 = qeq(n1)
    n2 = neq(U2)
    s = (1 - n1) * (U2 - U1) / (n2 - n1)
    plug, H2 = U2 - U1, H1 * (1 - n1) / (1 - n2)
    T = H1 / (s - plug)
    print("Problem 7, bed expansion (closed form: H2 = %.1f mm, plug %.4e m/s, front %.4e m/s)\n" % (1e3 * H2, plug, s))
    print("| cell | final height | plug speed | front speed (r^2) |")
    print("|---|---|---|---|")
    for h in cells:
        d = run(a.build, os.path.join(root, "cases/verification/bed_expansion"), a.work, "bed_expansion", h)
        t = d["time"]
        pl = fit(t, d["bed_height"], 2.0, 0.8 * T)
        sel = (t >= 3.0) & (t <= 0.85 * T)
        b, c = np.polyfit(t[sel], d["fluidised_front"][sel], 1)
        r2 = 1 - np.sum((d["fluidised_front"][sel] - (c + b * t[sel])) ** 2) / np.sum(
            (d["fluidised_front"][sel] - d["fluidised_front"][sel].mean()) ** 2)
        print(f"| {1e3 * h:.1f} mm | {100 * (d['bed_height'][-1] / H2 - 1):+.2f} % | {100 * (pl / plug - 1):+.2f} % "
              f"| {100 * (b / s - 1):+.2f} % ({r2:.4f}) |")
        sys.stdout.flush()

    # problem 9: n0 = 0.55 settling onto a sediment at n_max = 0.41
    n0, nmax, H0 = 0.55, 0.41, 0.186
    top = qeq(n0)
    front = (1 - n0) * top / (n0 - nmax)
    meet = H0 / (top + front)
    Hf = H0 * (1 - n0) / (1 - nmax)
    print("\nProblem 9, batch settling (closed form: top %.4e m/s, front %.4e m/s, meeting %.2f s, final %.1f mm)\n"
          % (top, front, meet, 1e3 * Hf))
    print("| cell | final height | top speed | sediment front | meeting time |")
    print("|---|---|---|---|---|")
    for h in cells:
        d = run(a.build, os.path.join(root, "cases/verification/batch_settling"), a.work, "batch_settling", h)
        t = d["time"]
        tp = -fit(t, d["bed_height"], 1.0, 0.8 * meet)
        fr = fit(t, d["fluidised_front"] - filt, 2.0, 0.8 * meet)
        done = t[(t > 1.0) & (d["fluidised_share"] < 0.01)]
        m = done[0] if done.size else float("nan")
        print(f"| {1e3 * h:.1f} mm | {100 * (d['bed_height'][-1] / Hf - 1):+.2f} % | {100 * (tp / top - 1):+.2f} % "
              f"| {100 * (fr / front - 1):+.2f} % | {100 * (m / meet - 1):+.2f} % |")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
