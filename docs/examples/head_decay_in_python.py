"""A worked example to copy into a notebook: two reservoirs feeding the main job's lumped twin,
run from Python, their head decay and filter velocity compared, and a consolidating column
stepped from Python with its pore pressure read as arrays.

    source .venv/bin/activate            # bash tools/setup.sh made it
    python docs/examples/head_decay_in_python.py [WORK_DIRECTORY]

(tools/tests/test_examples.py runs it, with short runs, so that it keeps working.)
"""
import os
import shutil
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

import quicksand as qs  # noqa: E402

REPOSITORY = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
END = float(os.environ.get("EXAMPLE_END", "30"))  # s simulated (the test shortens it)


def copy_case(name, work):
    """A case of the repository copied into `work`, so that its output lands there."""
    target = os.path.join(work, os.path.basename(name))
    shutil.rmtree(target, ignore_errors=True)
    shutil.copytree(os.path.join(REPOSITORY, "cases", name), target,
                    ignore=shutil.ignore_patterns("output", "output.previous"))
    return target


def main(work):
    os.makedirs(work, exist_ok=True)
    case = copy_case("deltaresColumnLumped", work)

    # 1. two variants of one case, run as `quicksand run CASE --set ...` (nothing edited by hand)
    fig, (head, flux) = plt.subplots(2, 1, sharex=True, figsize=(7, 6))
    for area in (0.0083, 0.0166):
        run = qs.run(case, {"reservoir.area": area, "time.end": END, "output.fields": False,
                            "output.directory": f"output_{area}"}, threads=2)
        s = run.series()  # a pandas DataFrame; s.attrs["units"] has each column's unit
        head.plot(s["time"], s["reservoir_head"], label=f"reservoir area {area} m²")
        flux.plot(s["time"], 1e3 * s["gate_flux"] / 5.0014e-3, label=f"{area} m²")  # filter velocity, mm/s
        print(f"area {area} m2: head {s['reservoir_head'].iloc[0]:.3f} -> {s['reservoir_head'].iloc[-1]:.3f} m "
              f"({s.attrs['units']['reservoir_head']}), largest fluidised share {s['fluidised_share'].max():.2f}")
    head.set_ylabel("reservoir head (m)")
    flux.set_ylabel("filter velocity (mm/s)")
    flux.set_xlabel("time (s)")
    head.legend()
    fig.savefig(os.path.join(work, "head_decay.png"), dpi=100)

    # 2. a run stepped from Python (the solver's binding, when built): Terzaghi's column
    try:
        from quicksand.solver import Simulation, binding
        binding()
    except ImportError as e:
        print(f"(the solver's binding is not built: {e})")
        return
    sim = Simulation(os.path.join(REPOSITORY, "cases", "verification", "terzaghi"), write_files=False)
    for t in (0.05, 0.2):
        sim.advance_to(t)
        rows = sim.profile()
        print(f"t = {sim.time:.2f} s: pore pressure at the base {rows['pore_pressure'][2]:.0f} Pa, "
              f"{len(sim.points('liquid')['pore_pressure'])} water points")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "example_runs")
