#!/usr/bin/env python3
"""The 3D consolidation benchmark run longer, against Terzaghi (issue 7).

    cp -r cases/benchmark/consolidation3d /tmp/c3d           # T = c_v t / H^2 = 0.65 at 0.05 s:
    OMP_NUM_THREADS=2 build/mpm/quicksand run /tmp/c3d --set time.end=0.05 --set time.output_interval=0.0025
    /usr/bin/python3 tools/consolidation3d_terzaghi.py /tmp/c3d

Reads CASE/case.toml and CASE/output/checkpoint.h5 (the state at the end). Prints, per cell row
of the sand, the mean pore pressure of the liquid points over u0 = q m_v / (m_v + n / K_L) against
u/u0 = sum 2/M sin(M Z) exp(-M^2 T) (Z from the drained top, H the sand's height), and the row's
lateral spread (the column is laterally uniform: any spread is a lateral error).
"""
import math
import sys
import tomllib

import h5py
import numpy as np


def main():
    case = sys.argv[1]
    with open(f"{case}/case.toml", "rb") as f:
        c = tomllib.load(f)
    m = c["materials"]["sand"]
    E, nu, n = m["youngs_modulus"], m["poisson_ratio"], m["porosity"]
    kappa = m["permeability"]["value"]
    KL, mu = c["liquid"]["bulk_modulus"], c["liquid"]["viscosity"]
    q = c["loads"]["surcharge"]
    h = c["grid"]["cell_size"]
    base = c["column"]["chamber_height"]
    H = c["layers"][0]["thickness"]
    top = base + H
    Eoed = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu))
    mv = 1 / Eoed
    u0 = q * mv / (mv + n / KL)
    cv = (kappa / mu) / (mv + n / KL)

    with h5py.File(f"{case}/output/checkpoint.h5", "r") as f:
        t = f["time"][()]
        x = f["liquid/position"][:].reshape(-1, 3)
        p = f["liquid/pore_pressure"][:]
    T = cv * t / H**2

    def exact(Z):
        return sum(2 / M * math.sin(M * Z) * math.exp(-M * M * T)
                   for M in (math.pi * (2 * k + 1) / 2 for k in range(200)))

    print(f"t = {t:.4g} s, T = {T:.3f}, u0 = {u0:.1f} Pa, c_v = {cv:.4g} m2/s")
    print(f"{'z (m)':>8}{'u/u0':>10}{'Terzaghi':>10}{'error':>10}{'spread/u0':>12}")
    worst = spread = 0.0
    rows = int(round(H / h))
    for r in range(rows):
        z0, z1 = base + r * h, base + (r + 1) * h
        sel = (x[:, 2] > z0) & (x[:, 2] < z1)
        if not sel.any():
            continue
        z = 0.5 * (z0 + z1)
        u, e = p[sel].mean() / u0, exact((top - z) / H)
        s = (p[sel].max() - p[sel].min()) / u0
        worst, spread = max(worst, abs(u - e)), max(spread, s)
        print(f"{z:>8.3f}{u:>10.4f}{e:>10.4f}{u - e:>10.4f}{s:>12.2e}")
    print(f"largest |u/u0 - Terzaghi| {worst:.4f}; largest lateral spread in a row {spread:.2e} u0")


if __name__ == "__main__":
    main()
