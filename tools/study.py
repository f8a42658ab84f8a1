#!/usr/bin/env python3
"""Runs a study: one base case over a set of parameter values (quicksand.studies, docs/studies.md).

  .venv/bin/python tools/study.py STUDY.toml [--check | --collect] [--retry-failed] [--no-plots]

The study tool lives in the package (tools/quicksand/studies.py); this is its entry point.
"""
import sys

try:  # the package needs numpy and pandas: say so at once, not after the runs
    from quicksand.studies import main
except ImportError as e:
    sys.exit(f"study.py: {e}")

if __name__ == "__main__":
    sys.exit(main())
