#!/usr/bin/env python3
"""Prints one run's figures, as study.csv has them (quicksand.figures, docs/studies.md):

  .venv/bin/python tools/study_figures.py CASE/output
"""
import sys

try:
    from quicksand.figures import main
except ImportError as e:
    sys.exit(f"study_figures.py: {e}")

if __name__ == "__main__":
    sys.exit(main())
