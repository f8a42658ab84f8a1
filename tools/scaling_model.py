#!/usr/bin/python3
"""A strong-scaling model of quicksand on MPI ranks, to 64 ranks (issue 41; docs/performance.md,
"A strong-scaling model to 64 ranks").

Usage:
    tools/scaling_model.py [--quicksand build/mpm/quicksand] [--out docs/images/scaling_model.png]

What it models, per step of the busiest rank (the others wait for it at the step's collectives):

  column, today's design (ghost points, parallel/RankShare.hpp):
      T = (a (P + G) + g C_grid + s (P + G)) (1 + f) + exchange
    P the rank's own points, G the ghost points copied into its window (both from
    `quicksand check CASE --ranks N`, which this script runs), C_grid the WHOLE grid's cells (every
    rank sweeps the whole grid's node and cell loops today), s the per-point price of the ranks'
    bookkeeping (the re-sort, the exchange's packing, the ghosts' removal), f the share lost
    waiting at the step's collectives (measured on 2 ranks, held constant: an assumption);
  column, the thin design (ghost points only as deep as the stencil, node sums exchanged:
  docs/parallel.md, "what is next"):
      T = (a P + g (C_own + C_halo)) (1 + f) + exchange of the node sums
    a node halo one cell deep, (6 + 4 D) values a halo node, exchanged twice a step;
  the OpenFOAM line (pimpleFoam's own decomposition):
      T = c n_cells / N / e + n_red alpha log2(N) + halo faces x values / beta
  the coupled run: the line's time plus the column's (a 1D column stepped whole on every rank is
  a constant: Amdahl's limit).

Which constants are measured on this 2-core machine and which are assumed is said beside each
(MEASURED / ASSUMED); the 2-rank points the model is checked against are measured, everything
beyond 2 ranks is a model.
"""
import argparse
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)

# --- MEASURED (docs/performance.md, "MPI ranks: the first measurements", this machine) ---------
# piping2D at 3.1 mm, explicit, 0.05 s: 7 515 steps, 22 672 points, 2 548 cells
P2D = dict(steps=7515, points=22672, cells=2548, t1=19.71, t2=23.92, t2threads=12.52)
# perf samples (999/s) of the serial run and of rank 0 of 2, 0.02 s of the same run
SERIAL_POINTS, SERIAL_GRID = 4740, 1524
RANK0_BOOKKEEPING = 1003 + 599 + 569  # the re-sort, the exchange's packing, the ghosts' removal
RANK0_WAIT, RANK0_COMPUTE = 947, 2616 + 1095 + 1003 + 599 + 569
# the other 2-rank points the model is checked against (one run each, 2026-12-07, fourth session:
# `bash tools/benchmark.sh --ranks`)
CHECKS = [
    # label, case, overrides, steps, 1x1 s, 2x1 s, 1x2 s
    ("piping3D, 6.2 mm, 0.01 s", "cases/piping3D", ["grid.cell_size=0.0062"], 751, 20.68, 26.57, 11.80),
    ("consolidation3d, 0.01 s", "cases/benchmark/consolidation3d", [], 1738, 25.27, 32.61, 16.68),
]
# bytes sent a step per ghost point (the run's summary line "sent to neighbouring ranks per step"
# on 2 ranks over check's ghost points): piping2D 3.1 mm 259 KiB / 2 616, piping3D 6.2 mm
# 3 MiB / 26 352 (a sand point's 19 to 28 values and its constitutive state, a water point's 9 to 13)
BYTES_PER_GHOST = {2: 259 * 1024 / 2616, 3: 3 * 2**20 / 26352}
# pitzDaily (12 225 cells), pimpleFoam itself, 300 steps: 1 rank 14.5 s, 2 ranks 8.4 s
LINE = dict(cells=12225, steps=300, t1=14.5, t2=8.4)

# --- ASSUMED (typical Open MPI figures, not measured here) -------------------------------------
ALPHA_NODE, BETA_NODE = 1e-6, 5e9   # s per message, B/s: shared memory within a node
ALPHA_NET, BETA_NET = 3e-6, 10e9    # s per message, B/s: InfiniBand between nodes
CORES_PER_NODE = 32
COLLECTIVES_PER_STEP = 12           # the column's per-step sums (docs/parallel.md's table)
LINE_REDUCTIONS_PER_STEP = 60       # pimpleFoam: GAMG and smoothSolver iterations' global sums
LINE_HALO_EXCHANGES_PER_STEP = 40   # processor-patch updates of p, U, k, epsilon a step
RANKS = [1, 2, 4, 8, 16, 32, 64]


def network(n):
    return (ALPHA_NODE, BETA_NODE) if n <= CORES_PER_NODE else (ALPHA_NET, BETA_NET)


def blocks(quicksand, case, overrides, ranks):
    """The busiest block of `quicksand check --ranks N`: own points, ghost points, its cells' ranges,
    the grid's cells and dimension, the memory per rank (bytes)."""
    cmd = [quicksand, "check", os.path.join(ROOT, case), "--ranks", str(ranks)]
    for o in overrides:
        cmd += ["--set", o]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    size = re.search(r"^size: (\d+) cells, (\d+) nodes, (\d+) solid \+ (\d+) liquid points", out, re.M)
    cells, points = int(size.group(1)), int(size.group(3)) + int(size.group(4))
    dimension = 3 if re.search(r"y-range", out) else 2
    if ranks == 1:
        return dict(own=points, ghost=0, block_cells=cells, halo_nodes=0, cells=cells, D=dimension,
                    memory=None, points=points)
    worst = None
    units = {"B": 1, "KiB": 2**10, "MiB": 2**20, "GiB": 2**30}
    for line in out.splitlines():
        m = re.match(r"^\s+(\d+)\s+(\d+)((?:\s+\d+-\d+)+)\s+(\d+)\s+(\d+)\s+(\d+)\s+(\d+)\s+([\d.]+) (\w+)$", line)
        if not m:
            continue
        ranges = [tuple(int(v) for v in r.split("-")) for r in m.group(3).split()]
        own = int(m.group(5)) + int(m.group(6))
        extents = [b - a for a, b in ranges]
        block_cells = math.prod(extents)
        # the thin design's node halo: one cell beyond the block on each cut side
        lateral = extents[:-1]
        halo = math.prod(e + 3 for e in lateral) - math.prod(e + 1 for e in lateral)
        b = dict(own=own, ghost=int(m.group(7)), block_cells=block_cells, halo_nodes=halo * (extents[-1] + 1),
                 cells=cells, D=dimension, memory=float(m.group(8)) * units[m.group(9)], points=points)
        if worst is None or b["own"] + b["ghost"] > worst["own"] + worst["ghost"]:
            worst = b
    return worst


class Column:
    """The column's per-step model, its constants from piping2D at 3.1 mm (MEASURED), scaled to a
    case by its own one-rank time (the point and grid shares of the 2D profile: ASSUMED alike)."""

    def __init__(self, steps, t1, one):
        share = SERIAL_POINTS / (SERIAL_POINTS + SERIAL_GRID)
        per_step = t1 / steps
        self.a = share * per_step / one["points"]                # s per point-step
        self.g = (1 - share) * per_step / one["cells"]           # s per cell-step
        serial_total = SERIAL_POINTS + SERIAL_GRID
        # the bookkeeping, per point held (own + ghosts) in the 2D run, in units of the point price
        own2, ghost2 = P2D["points"] / 2, 2616
        book = RANK0_BOOKKEEPING / serial_total * P2D["t1"] / P2D["steps"] / (own2 + ghost2)
        a2 = share * P2D["t1"] / P2D["steps"] / P2D["points"]
        self.s = book / a2 * self.a
        self.f = RANK0_WAIT / (RANK0_COMPUTE)                    # waiting share, 2 ranks
        self.steps = steps

    def today(self, b, n):
        alpha, beta = network(n)
        width = BYTES_PER_GHOST[b["D"]]
        bookkeeping = self.s * (b["own"] + b["ghost"]) if n > 1 else 0.0
        compute = self.a * (b["own"] + b["ghost"]) + self.g * b["cells"] + bookkeeping
        sync = self.f * compute if n > 1 else 0.0
        exchange = (b["ghost"] * width / beta + COLLECTIVES_PER_STEP * alpha * math.log2(n) + 6 * alpha) if n > 1 else 0
        return self.steps * (compute + sync + exchange)

    def thin(self, b, n):
        alpha, beta = network(n)
        halo_cells = b["halo_nodes"]  # about one cell a halo node
        compute = self.a * b["own"] + self.g * (b["block_cells"] + halo_cells)
        sync = self.f * compute if n > 1 else 0.0
        values = (6 + 4 * b["D"]) * b["halo_nodes"]
        exchange = (2 * values * 8 / beta + COLLECTIVES_PER_STEP * alpha * math.log2(n) + 8 * alpha) if n > 1 else 0
        return self.steps * (compute + sync + exchange)

    def sent_per_step(self, b):
        return b["ghost"] * BYTES_PER_GHOST[b["D"]]


def line_time(cells, n, steps=1):
    """pimpleFoam on `cells` cells over n ranks, s (its constants from pitzDaily: MEASURED)."""
    c = LINE["t1"] / (LINE["steps"] * LINE["cells"])             # s per cell-step, 1 rank
    efficiency = LINE["t1"] / (2 * LINE["t2"])                   # 0.86 on 2 ranks, held (ASSUMED)
    alpha, beta = network(n)
    if n == 1:
        return steps * c * cells
    faces = 6 * (cells / n) ** (2 / 3)
    comm = LINE_REDUCTIONS_PER_STEP * alpha * math.log2(n) + LINE_HALO_EXCHANGES_PER_STEP * (alpha + faces * 8 / beta)
    return steps * (c * cells / n / efficiency + comm)


def fmt(seconds):
    return f"{seconds:9.3g}"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--quicksand", default=os.path.join(ROOT, "build/mpm/quicksand"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs/images/scaling_model.png"))
    args = parser.parse_args()
    if not os.access(args.quicksand, os.X_OK):
        sys.exit(f"scaling_model.py: no quicksand at {args.quicksand} (build it: bash tools/build.sh), "
                 "or give --quicksand PATH")

    print("== the model against the 2-rank points measured here (2 ranks x 1 thread, s)")
    print(f"{'case':32s} {'1 rank':>9s} {'2 ranks, measured':>18s} {'model':>9s} {'model / measured':>17s}")
    one2 = blocks(args.quicksand, "cases/piping2D", ["grid.cell_size=0.0031"], 1)
    two2 = blocks(args.quicksand, "cases/piping2D", ["grid.cell_size=0.0031"], 2)
    m2 = Column(P2D["steps"], P2D["t1"], one2)
    print(f"{'piping2D, 3.1 mm (calibration)':32s} {P2D['t1']:9.2f} {P2D['t2']:18.2f} {m2.today(two2, 2):9.2f} "
          f"{m2.today(two2, 2) / P2D['t2']:17.2f}")
    for label, case, sets, steps, t1, t2, _ in CHECKS:
        one, two = blocks(args.quicksand, case, sets, 1), blocks(args.quicksand, case, sets, 2)
        m = Column(steps, t1, one)
        print(f"{label:32s} {t1:9.2f} {t2:18.2f} {m.today(two, 2):9.2f} {m.today(two, 2) / t2:17.2f}")
    print(f"{'pitzDaily line, pimpleFoam':32s} {LINE['t1']:9.2f} {LINE['t2']:18.2f} "
          f"{line_time(LINE['cells'], 2, LINE['steps']):9.2f} "
          f"{line_time(LINE['cells'], 2, LINE['steps']) / LINE['t2']:17.2f}  (calibration)")

    # piping3D at 3.1 mm, 1 s of simulated time, per design
    case, sets = "cases/piping3D", ["grid.cell_size=0.0031"]
    one = blocks(args.quicksand, case, sets, 1)
    steps = 150305  # 1 s at dt = 6.653e-6 s (quicksand check)
    # its one-rank time per point-step from piping3D at 6.2 mm (MEASURED): 20.68 s / 751 steps / 105 408 points
    t1 = 20.68 / 751 / 105408 * one["points"] * steps
    m = Column(steps, t1, one)
    rows = []
    for n in RANKS:
        b = blocks(args.quicksand, case, sets, n)
        rows.append((n, b, m.today(b, n), m.thin(b, n)))
    print("\n== piping3D at 3.1 mm (24 x 24 x 90 cells, %d points), 1 s simulated (%d steps): MODEL beyond 2 ranks"
          % (one["points"], steps))
    print(f"{'ranks':>5s} {'own pts':>8s} {'ghost pts':>9s} {'sent/step':>10s} {'memory':>9s} "
          f"{'today s':>9s} {'speed-up':>8s} {'thin s':>9s} {'speed-up':>8s}")
    for n, b, today, thin in rows:
        mem = f"{b['memory'] / 2**20:7.0f} MiB" if b["memory"] else "        -"
        print(f"{n:5d} {b['own']:8d} {b['ghost']:9d} {m.sent_per_step(b) / 2**20:7.2f} MiB {mem} "
              f"{fmt(today)} {rows[0][2] / today:8.2f} {fmt(thin)} {rows[0][3] / thin:8.2f}")

    print("\n== an OpenFOAM line of 1e6 cells, 1 s simulated at 1e-4 s steps (10 000 steps): MODEL beyond 2 ranks")
    line = [(n, line_time(1e6, n, 10000)) for n in RANKS]
    column1d = 0.01 * line[0][1]  # a 1D column beside it, stepped whole on every rank: 1 % (pitzDaily, MEASURED)
    print(f"{'ranks':>5s} {'cells/rank':>10s} {'line s':>9s} {'speed-up':>8s} {'with a 1D column s':>19s} {'speed-up':>8s}")
    for n, t in line:
        print(f"{n:5d} {1e6 / n:10.0f} {fmt(t)} {line[0][1] / t:8.2f} {fmt(t + column1d):>19s} "
              f"{(line[0][1] + column1d) / (t + column1d):8.2f}")

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(RANKS, RANKS, "k:", label="ideal")
    ax.plot(RANKS, [rows[0][2] / r[2] for r in rows], "o-", label="piping3D 3.1 mm, today's ghost points")
    ax.plot(RANKS, [rows[0][3] / r[3] for r in rows], "s-", label="piping3D 3.1 mm, thin halos (planned)")
    ax.plot(RANKS, [line[0][1] / t for _, t in line], "^-", label="1e6-cell OpenFOAM line")
    ax.plot(RANKS, [(line[0][1] + column1d) / (t + column1d) for _, t in line], "v--",
            label="1e6-cell line + a 1D column on every rank")
    ax.plot([2], [P2D["t1"] / P2D["t2"]], "r*", markersize=12, label="measured, piping2D 3.1 mm (2 cores)")
    ax.plot([2], [LINE["t1"] / LINE["t2"]], "m*", markersize=12, label="measured, pitzDaily pimpleFoam (2 cores)")
    ax.set_xscale("log", base=2)
    ax.set_yscale("log", base=2)
    ax.set_xlabel("MPI ranks (one thread each; %d cores a node assumed)" % CORES_PER_NODE)
    ax.set_ylabel("speed-up over one rank")
    ax.set_title("Strong scaling: a model beyond 2 ranks (tools/scaling_model.py)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    os.makedirs(os.path.dirname(args.out), exist_ok=True)
    fig.savefig(args.out, dpi=110)
    print(f"\nplot: {args.out}")


if __name__ == "__main__":
    main()
