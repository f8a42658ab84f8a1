#!/usr/bin/env python3
"""Plots how a column fluidises (quicksand.plots.fluidisation): fluidisation.png, front_fit.csv.

  .venv/bin/python tools/plot_fluidisation.py CASE/output [--analytic-q Q] [--fit-from T0] [--fit-to T1]
"""
import sys

try:
    from quicksand.plots.fluidisation import main
except ImportError as e:
    sys.exit(f"plot_fluidisation.py: {e}")

if __name__ == "__main__":
    sys.exit(main())
