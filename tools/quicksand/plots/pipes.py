"""Shows the pipes of a 2D or 3D run, from its output directory (fields.h5 and pipes.csv):

  pipes_frames.png  a strip of frames through the run: the sand's porosity per cell, the
                    fluidised cells outlined in white, the pipes of pipes.csv marked. In 3D each
                    frame is two sections: a vertical one through the pipe carrying most water
                    (or the middle, when there is none) and a horizontal one at the bed's mid height.
  pipes.gif         the same frames at every output time, as an animation (Pillow's GIF writer)
  pipes.png         pipes against time: their number, the share of the water they carry (and
                    that of every fluidised base cell), their heights and whether they touch a wall;
                    in 3D also where each pipe stands around the column: the angle of its centroid
                    about the column's axis (0 the wall at x max, 90 at y max, 180 at x = 0), which
                    shows a pipe migrating along the wall

Usage:
  .venv/bin/python tools/plot_pipes.py CASE/output [--frames 8] [--no-animation] [--fps 8]
  quicksand.plots.pipes.plot(CASE/output, frames=8, gif=True) -> (paths, series figure)

The cells' porosity and state are fields.h5's "cells" point set (one point per grid cell: state
0 no sand, 1 solid, 2 fluidised). ParaView opens the same fields through fields.xdmf.
"""
import argparse
import os
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402

from .. import results  # noqa: E402


def read_cells(path):
    """Per output time: (time, porosity grid, state grid) with the grids indexed [z][y][x]."""
    frames = []
    with h5py.File(path, "r") as h:
        dimension = int(h.attrs["dimension"])
        for key in sorted(k for k in h.keys() if k.startswith("step_")):
            g = h[key]
            if "cells" not in g:
                continue
            xyz = np.asarray(g["cells"]["positions"])
            axes = [np.unique(np.round(xyz[:, a], 9)) for a in range(3)]
            index = [np.searchsorted(axes[a], np.round(xyz[:, a], 9)) for a in range(3)]
            shape = (len(axes[2]), len(axes[1]), len(axes[0]))
            porosity = np.full(shape, np.nan)
            state = np.zeros(shape)
            porosity[index[2], index[1], index[0]] = g["cells"]["porosity"]
            state[index[2], index[1], index[0]] = g["cells"]["state"]
            frames.append((float(g.attrs["time"]), porosity, state, axes))
    if not frames:
        raise ValueError(f"{path} has no cells (a 1D run, or written before pipes were measured)")
    return dimension, frames


def read_pipes(path):
    if not os.path.exists(path):
        return []
    return results.read_pipes(path).to_dict("records")


def pipes_at(pipes, time):
    return [p for p in pipes if abs(p["time"] - time) < 1e-6 * max(1.0, time) and p["pipe"] > 0]


def edges(axis):
    h = axis[1] - axis[0] if len(axis) > 1 else 1.0
    return np.concatenate([axis - h / 2, [axis[-1] + h / 2]])


def draw_section(ax, x_axis, z_axis, porosity, state, limits, title):
    """One section: porosity image, fluidised cells outlined."""
    image = ax.pcolormesh(edges(x_axis) * 1e3, edges(z_axis) * 1e3, np.ma.masked_invalid(porosity),
                          cmap="viridis", vmin=limits[0], vmax=limits[1], shading="flat")
    fluid = (state == 2).astype(float)
    if fluid.any():
        ax.contour(x_axis * 1e3, z_axis * 1e3, fluid, levels=[0.5], colors="white", linewidths=1.2)
    ax.set_aspect("equal")
    ax.set_title(title, fontsize=8)
    ax.tick_params(labelsize=7)
    return image


def sand_rows(state):
    rows = np.where((state > 0).any(axis=(1, 2)))[0]
    return (rows[0], rows[-1]) if len(rows) else (0, state.shape[0] - 1)


def sand_window(frames):
    """The rows shown: from below the filter to above the highest sand of the whole run."""
    lo = min(sand_rows(f[2])[0] for f in frames)
    hi = max(sand_rows(f[2])[1] for f in frames)
    return lo, hi, slice(max(lo - 1, 0), min(hi + 3, frames[0][2].shape[0]))


def draw_frame(axes_row, dimension, frame, pipes, limits, window):
    time, porosity, state, (xs, ys, zs) = frame
    here = pipes_at(pipes, time)
    lo, hi, zcut = window
    if dimension == 2:
        image = draw_section(axes_row[0], xs, zs[zcut], porosity[zcut, 0, :], state[zcut, 0, :], limits,
                             f"t = {time:.2f} s, {len(here)} pipe{'s' if len(here) != 1 else ''}")
        for p in here:
            axes_row[0].plot(p["x"] * 1e3, (zs[lo] - (zs[1] - zs[0]) / 2 + p["height"]) * 1e3, "v", color="red", ms=5)
        return image
    # 3D: a vertical section through the pipe carrying most water (y = its centroid), and a
    # horizontal one at the bed's mid height
    y = here[0]["y"] if here else ys[len(ys) // 2]
    j = int(np.argmin(np.abs(ys - y)))
    k = (lo + hi) // 2
    image = draw_section(axes_row[0], xs, zs[zcut], porosity[zcut, j, :], state[zcut, j, :], limits,
                         f"t = {time:.2f} s\ny = {ys[j] * 1e3:.0f} mm")
    draw_section(axes_row[1], xs, ys, porosity[k], state[k], limits,
                 f"z = {zs[k] * 1e3:.0f} mm\n{len(here)} pipe{'s' if len(here) != 1 else ''}")
    for p in here:
        axes_row[1].plot(p["x"] * 1e3, p["y"] * 1e3, "x", color="red", ms=6)
    return image


def porosity_limits(frames):
    values = np.concatenate([f[1][np.isfinite(f[1])] for f in frames])
    return float(np.percentile(values, 1)), float(np.percentile(values, 99.5))


def strip(out, dimension, frames, pipes, count, limits):
    picks = sorted(set(np.linspace(0, len(frames) - 1, min(count, len(frames))).round().astype(int)))
    sections = 1 if dimension == 2 else 2
    # in 3D the horizontal sections are as tall as the column is wide
    _, _, _, (xs, ys, zs) = frames[0]
    lo, hi, zcut = sand_window(frames)
    heights = [1.0] if dimension == 2 else [len(zs[zcut]), len(ys)]
    fig, axes = plt.subplots(sections, len(picks), figsize=(1.6 * len(picks) + 1.2, 4.2 if dimension == 2 else 6.0),
                             squeeze=False, gridspec_kw={"height_ratios": heights})
    for c, i in enumerate(picks):
        image = draw_frame(axes[:, c], dimension, frames[i], pipes, limits, sand_window(frames))
        for r in range(sections):
            if c > 0:
                axes[r, c].set_yticklabels([])
    axes[0, 0].set_ylabel("z (mm)")
    fig.colorbar(image, ax=axes, label="porosity (white outline: fluidised)", shrink=0.8)
    fig.savefig(os.path.join(out, "pipes_frames.png"), dpi=130)
    plt.close(fig)


def animate(out, dimension, frames, pipes, limits, fps):
    sections = 1 if dimension == 2 else 2
    fig, axes = plt.subplots(1, sections, figsize=(3.2 * sections, 5), squeeze=False)

    window = sand_window(frames)

    def draw(i):
        for ax in axes[0]:
            ax.clear()
        draw_frame(axes[0], dimension, frames[i], pipes, limits, window)

    writer = animation.PillowWriter(fps=fps)
    anim = animation.FuncAnimation(fig, draw, frames=len(frames))
    anim.save(os.path.join(out, "pipes.gif"), writer=writer, dpi=90)
    plt.close(fig)


def around_the_axis(pipes, axes):
    """Each pipe's centroid as an angle about the column's axis, in degrees from the x-max wall
    towards the y-max wall, wrapped into [-135, 225) so that the cut is the corner at x = 0, y = 0."""
    xs, ys = axes[0], axes[1]
    xc, yc = (xs[0] + xs[-1]) / 2, (ys[0] + ys[-1]) / 2
    angles = np.degrees(np.arctan2([p["y"] - yc for p in pipes], [p["x"] - xc for p in pipes]))
    return np.where(angles < -135, angles + 360, angles)


def draw_around(ax, real, axes):
    """The pipes' places around the column (3D), dot size the share of the water each carries."""
    for wall, colour, label in ((1.0, "tab:red", "at a wall"), (0.0, "tab:blue", "interior")):
        sel = [p for p in real if p["wall"] == wall]
        if sel:
            ax.scatter([p["time"] for p in sel], around_the_axis(sel, axes),
                       s=[4 + 60 * p["flux_share"] for p in sel], c=colour, label=label)
    ax.set_ylim(-135, 225)
    ax.set_yticks([-90, 0, 90, 180])
    ax.set_yticklabels(["-90\ny = 0", "0\nx max", "90\ny max", "180\nx = 0"], fontsize=7)
    ax.set_ylabel("angle about the axis (deg)")
    for corner in (-45, 45, 135):
        ax.axhline(corner, color="0.8", lw=0.6, zorder=0)
    ax.legend(fontsize=8, title="dot size: share of the water", title_fontsize=7)


def series(out, pipes, dimension=2, axes=None):
    """pipes.png; returns its figure (None without pipes.csv)."""
    if not pipes:
        return None
    times = sorted({p["time"] for p in pipes})
    count = [next(p["pipes"] for p in pipes if p["time"] == t) for t in times]
    fluid = [next(p["fluidised_flux_share"] for p in pipes if p["time"] == t) for t in times]
    share = [sum(p["flux_share"] for p in pipes if p["time"] == t and p["pipe"] > 0) for t in times]
    panels = 4 if dimension == 3 else 3
    fig, ax = plt.subplots(panels, 1, figsize=(7, 2.3 * panels + 0.1), sharex=True)
    ax[0].step(times, count, where="post")
    ax[0].set_ylabel("pipes")
    ax[1].plot(times, share, label="through pipes")
    ax[1].plot(times, fluid, "--", label="through every fluidised base cell")
    ax[1].set_ylabel("share of the water")
    ax[1].set_ylim(-0.02, 1.02)
    ax[1].legend(fontsize=8)
    real = [p for p in pipes if p["pipe"] > 0]
    for wall, colour, label in ((1.0, "tab:red", "at a wall"), (0.0, "tab:blue", "interior")):
        sel = [p for p in real if p["wall"] == wall]
        ax[2].scatter([p["time"] for p in sel], [p["height"] * 1e3 for p in sel], s=8, c=colour, label=label)
    ax[2].set_ylabel("pipe height (mm)")
    ax[2].legend(fontsize=8)
    if dimension == 3:
        draw_around(ax[3], real, axes)
    ax[-1].set_xlabel("time (s)")
    fig.tight_layout()
    fig.savefig(os.path.join(out, "pipes.png"), dpi=120)
    plt.close(fig)
    return fig


def plot(output, frames=8, gif=True, fps=8):
    """The strip, the series and (gif) the animation of a run's pipes, in its output directory;
    returns the paths written and the series' figure. Raises OSError or ValueError for a run
    without fields.h5 or without cells (1D)."""
    fields = os.path.join(output, "fields.h5")
    if not os.path.exists(fields):
        raise OSError(f"no {fields} (was output.fields = false?)")
    dimension, cells = read_cells(fields)
    pipes = read_pipes(os.path.join(output, "pipes.csv"))
    limits = porosity_limits(cells)
    strip(output, dimension, cells, pipes, frames, limits)
    figure = series(output, pipes, dimension, cells[0][3])
    if gif:
        animate(output, dimension, cells, pipes, limits, fps)
    written = [os.path.join(output, f) for f in ("pipes_frames.png", "pipes.png", "pipes.gif")
               if os.path.exists(os.path.join(output, f))]
    return written, figure


def main():
    parser = argparse.ArgumentParser(prog="plot_pipes.py", description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", help="the run's output directory")
    parser.add_argument("--frames", type=int, default=8, help="frames in the strip (default 8)")
    parser.add_argument("--no-animation", action="store_true", help="skip pipes.gif")
    parser.add_argument("--fps", type=float, default=8, help="frames per second of pipes.gif")
    args = parser.parse_args()
    try:
        written, _ = plot(args.output, args.frames, not args.no_animation, args.fps)
    except (OSError, ValueError) as e:
        sys.exit(f"plot_pipes.py: {e}")
    print("plot_pipes.py: wrote " + ", ".join(written))


if __name__ == "__main__":
    main()
