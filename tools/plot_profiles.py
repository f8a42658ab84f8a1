#!/usr/bin/env python3
"""Plot vertical profiles at one output time: OUTPUT_DIR/fields.h5 -> OUTPUT_DIR/profiles.png
(quicksand.plots.profiles).

  .venv/bin/python tools/plot_profiles.py OUTPUT_DIR [--step N] [--out FILE.png]
"""
import sys

try:
    from quicksand.plots.profiles import main
except ImportError as e:
    sys.exit(f"plot_profiles.py: {e}")

if __name__ == "__main__":
    sys.exit(main())
