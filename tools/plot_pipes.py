#!/usr/bin/env python3
"""Shows the pipes of a 2D or 3D run (quicksand.plots.pipes): pipes_frames.png, pipes.png, pipes.gif.

  .venv/bin/python tools/plot_pipes.py CASE/output [--frames 8] [--no-animation] [--fps 8]
"""
import sys

try:
    from quicksand.plots.pipes import main
except ImportError as e:
    sys.exit(f"plot_pipes.py: {e}")

if __name__ == "__main__":
    sys.exit(main())
