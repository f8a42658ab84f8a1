#!/usr/bin/env python3
"""Prints how well a 2D or 3D run holds its sand's packing (quicksand.packing; issue 42, item 3):

  .venv/bin/python tools/packing.py CASE/output --min-porosity 0.32
"""
import sys

try:
    from quicksand.packing import main
except ImportError as e:
    sys.exit(f"packing.py: {e}")

if __name__ == "__main__":
    sys.exit(main())
