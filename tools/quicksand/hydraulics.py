"""The hydraulics of a quicksand case, as the plots and the study tool draw them beside a run.

Read from a case's TOML (a dict from tomllib):
  churchill(re)                 a smooth pipe's Darcy friction factor, every regime (Churchill 1977)
  feed_line(case, case_dir)     the reservoir's line: (d, L, sum K, turbulent?) or None
  line_loss(line, Q, ...)       m, the line's head loss at flux Q
  bed_coefficients(case)        the fixed bed's Darcy-Forchheimer loss a q + b q^2 and i_c H
  analytic_lines(case, ...)     quasi-steady filter velocities for a head series: fixed and fluidised bed
  head_decay(case, case_dir, t) the reservoir's head through a fixed bed: the laminar closed form
                                (exponential) and the ODE with the line's friction and minor losses

The same physics as mpm/physics (ClosedForms, PipeFriction, Permeability); these are the plots'
reference lines, not the solver.
"""
import math
import os

import numpy as np


def churchill(re):
    """Darcy friction factor of a smooth pipe in every regime (Churchill 1977; mpm/physics/PipeFriction)."""
    re = max(re, 1e-12)
    A = (2.457 * math.log(1 / ((7 / re) ** 0.9))) ** 16
    B = (37530 / re) ** 16
    return 8 * ((8 / re) ** 12 + (A + B) ** -1.5) ** (1 / 12)


def feed_line(case, case_dir):
    import re

    """The reservoir's line: (d, L, sum K, turbulent friction?) from the lumped keys, or from an
    OpenFOAM wedge pipe (blockMeshDict's L and radius; the porousBafflePressure baffles' I in 0/p,
    plus 1 for the kinetic energy leaving at the gate); None without a line."""

    res = case.get("reservoir", {})
    if res.get("model") == "openfoam":
        base = os.path.join(case_dir, res.get("openfoam_case", "reservoir"))
        try:
            text = open(os.path.join(base, "system", "blockMeshDict")).read()
            L = float(re.search(r"^L\s+([0-9.eE+-]+);", text, re.M).group(1))
            y = float(re.search(r"^yR\s+([0-9.eE+-]+);", text, re.M).group(1))
        except (OSError, AttributeError, ValueError):
            return None
        rv = y / math.cos(math.radians(2.5))  # the area-true radius of the wedge's vertices
        d = 2 * rv / math.sqrt(2 * math.pi / (72 * math.sin(math.radians(5))))
        K = 1.0
        try:
            p = open(os.path.join(base, "0", "p")).read()
            for block in re.findall(r"_half0\s*\{([^}]*)\}", p):
                if "porousBafflePressure" in block:
                    K += float(re.search(r"\bI\s+([0-9.eE+-]+);", block).group(1))
        except (OSError, AttributeError, ValueError):
            pass
        turbulent = True
        try:
            tp = open(os.path.join(base, "constant", "turbulenceProperties")).read()
            turbulent = not re.search(r"^simulationType\s+laminar;", tp, re.M)
        except OSError:
            pass
        return d, L, K, turbulent
    d, L = res.get("tube_diameter", 0.0), res.get("tube_length", 0.0)
    if d <= 0 or L <= 0:
        return None
    return d, L, res.get("minor_loss", 0.0), res.get("tube_friction", "smooth_pipe") == "smooth_pipe"


def line_loss(line, Q, g, mu, rho):
    """m, the line's head loss at flux Q (m3/s): wall friction f L/d and minor losses, on U^2/2g."""
    if line is None:
        return 0.0
    d, L, K, turbulent = line
    U = abs(Q) / (math.pi * d * d / 4)
    re = rho * U * d / mu
    f = churchill(re) if turbulent else 64 / max(re, 1e-12)
    return (f * L / d + K) * U * U / (2 * g)


def analytic_lines(case, case_dir, t, head):
    """Quasi-steady filter velocities for the reservoir head at each time: fixed bed, fluidised bed."""

    g = case.get("gravity", 9.81)
    liquid = case.get("liquid", {})
    rho, mu = liquid.get("density", 998.2), liquid.get("viscosity", 8.91e-4)
    grid, column = case["grid"], case["column"]
    area = grid.get("cross_section_area")
    if not area or case.get("gate", {}).get("mode", "pressure") != "pressure":
        return None
    tail = column.get("overflow_level", column.get("water_level"))
    line = feed_line(case, case_dir)
    a, b, icH = bed_coefficients(case)

    def solve(loss, dh):  # the filter velocity q whose loss is dh (the loss grows with q): bisection
        if dh <= 0:
            return 0.0
        lo, hi = 0.0, 1.0
        for _ in range(100):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if loss(mid) < dh else (lo, mid)
        return 0.5 * (lo + hi)

    column_loss = lambda q: a * q + b * q * q
    tube = lambda q: line_loss(line, q * area, g, mu, rho)
    dh = head - tail
    fixed = np.array([solve(lambda q: column_loss(q) + tube(q), h) for h in dh])
    fluid = np.array([solve(tube, h - icH) for h in dh]) if line is not None else None
    return fixed, fluid


def bed_coefficients(case):
    """The fixed bed's loss a q + b q^2 (m of head, q the filter velocity in m/s) over its layers,
    and i_c H (m): the head a fluidised bed takes whatever the flux."""
    g = case.get("gravity", 9.81)
    liquid = case.get("liquid", {})
    rho, mu = liquid.get("density", 998.2), liquid.get("viscosity", 8.91e-4)
    layers, mats = case["layers"], case["materials"]
    coeff, icH = [], 0.0
    for layer in layers:
        m = mats[layer["material"]]
        n0, A, B = m["porosity"], m.get("ergun_a", 150.0), m.get("ergun_b", 1.75)
        perm = m["permeability"]
        shape = lambda n: min(n, 0.95) ** 3 / (1 - min(n, 0.95)) ** 2
        if perm["mode"] == "constant":
            kappa = perm["value"]
        elif perm["mode"] == "kozeny_carman":
            kappa = perm["grain_size"] ** 2 * shape(n0) / A
        else:
            kappa = perm["value"]
        F = B / (math.sqrt(A) * n0 ** 1.5) if m.get("ergun", True) else 0.0
        L = layer["thickness"]
        coeff.append((L * mu / (kappa * rho * g), L * F / (g * math.sqrt(kappa))))
        icH += (m.get("grain_density", 2650) / rho - 1) * (1 - n0) * L
    return sum(c[0] for c in coeff), sum(c[1] for c in coeff), icH




def head_decay(case, case_dir, t):
    """The reservoir's head above the tailwater through a fixed bed (a lumped or OpenFOAM
    reservoir of plan area A_r, or area_table), from its initial head, at times t (s):
      laminar:   u = u0 exp(-t / tau), tau = A_r (L / (K A_s) + R_t), the line's wall friction
                 Hagen-Poiseuille's and no minor loss (problem 6);
      turbulent: A_r du/dt = -Q(u), u = a q + b q^2 + (f L_t / d + K) U^2 / 2g, f the line's
                 own law (line_loss: a smooth pipe's, Churchill 1977, which is Blasius' within 3 %
                 for Re 4e3 to 1e5 and 64/Re in laminar flow, as the solver's; 64/Re for
                 tube_friction = "laminar"), K the line's minor losses: integrated (RK4).
    Returns (tail m, laminar u m, turbulent u m, tau s) or None (no reservoir that falls)."""
    res = case.get("reservoir", {})
    if res.get("model") not in ("lumped", "openfoam"):
        return None
    g = case.get("gravity", 9.81)
    liquid = case.get("liquid", {})
    rho, mu = liquid.get("density", 998.2), liquid.get("viscosity", 8.91e-4)
    column = case["column"]
    As = case["grid"]["cross_section_area"]
    tail = column.get("overflow_level", column.get("water_level"))
    a, b, _ = bed_coefficients(case)
    line = feed_line(case, case_dir)
    table = res.get("area_table")
    area = (lambda h: float(np.interp(h, [r[0] for r in table], [r[1] for r in table]))) if table else (lambda h: res["area"])
    h0 = res["head"]
    # laminar: the bed's Darcy term and Hagen-Poiseuille's tube, head per flow (s/m2)
    Rt = 0.0
    if line is not None:
        d, L = line[0], line[1]
        Rt = 128 * mu * L / (math.pi * rho * g * d ** 4)
    R = a / As + Rt
    tau = area(h0) * R
    t = np.asarray(t, dtype=float)
    if table:  # A(u) du/dt = -u / R, integrated like the turbulent one
        laminar = _integrate(lambda u: u / R, area, tail, h0 - tail, t)
    else:
        laminar = (h0 - tail) * np.exp(-t / tau)

    def flow(u):  # Q (m3/s) whose losses are u: bisection on the monotone loss
        if u <= 0:
            return 0.0
        def loss(Q):
            q = Q / As
            extra = 0.0
            if line is not None:
                extra = line_loss(line, Q, g, mu, rho)
            return a * q + b * q * q + extra
        lo, hi = 0.0, 1e-6
        while loss(hi) < u:
            hi *= 2
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            lo, hi = (mid, hi) if loss(mid) < u else (lo, mid)
        return 0.5 * (lo + hi)

    turbulent = _integrate(flow, area, tail, h0 - tail, t)
    return tail, laminar, turbulent, tau


def _integrate(flow, area, tail, u0, t):
    """u(t) of A(tail + u) du/dt = -flow(u), RK4 on a step 1/2000 of the span, read at t"""
    if len(t) == 0:
        return np.array([])
    T = float(np.max(t))
    n = 2000
    dt = T / n if T > 0 else 1.0
    ts, us, u = [0.0], [u0], u0
    f = lambda u: -flow(max(u, 0.0)) / area(tail + max(u, 0.0))
    for k in range(n):
        k1 = f(u); k2 = f(u + 0.5 * dt * k1); k3 = f(u + 0.5 * dt * k2); k4 = f(u + dt * k3)
        u = max(u + dt * (k1 + 2 * k2 + 2 * k3 + k4) / 6, 0.0)
        ts.append((k + 1) * dt); us.append(u)
    return np.interp(t, ts, us)
