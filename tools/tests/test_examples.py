"""docs/examples: the worked example runs (with short runs) and leaves its plot."""
import os
import subprocess
import sys

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))


def test_the_worked_example_runs(quicksand_binary, tmp_path):
    env = dict(os.environ, EXAMPLE_END="1.0", PYTHONPATH=os.path.join(REPOSITORY, "tools"), QUICKSAND=quicksand_binary)
    done = subprocess.run([sys.executable, os.path.join(REPOSITORY, "docs", "examples", "head_decay_in_python.py"),
                           str(tmp_path)], capture_output=True, text=True, env=env, timeout=300)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "area 0.0083 m2: head" in done.stdout and "area 0.0166 m2: head" in done.stdout
    assert os.path.getsize(tmp_path / "head_decay.png") > 10_000
