#!/usr/bin/env python3
"""Plot a quicksand run's time series: OUTPUT_DIR/series.csv -> OUTPUT_DIR/series.png
(quicksand.plots.series).

  .venv/bin/python tools/plot_series.py OUTPUT_DIR [--out FILE.png]
"""
import sys

try:
    from quicksand.plots.series import main
except ImportError as e:
    sys.exit(f"plot_series.py: {e}")

if __name__ == "__main__":
    sys.exit(main())
