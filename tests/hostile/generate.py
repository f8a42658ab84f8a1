#!/usr/bin/env python3
"""Writes the catalogue of hostile inputs, tests/hostile/<name>/, from one good case.

    /usr/bin/python3 tests/hostile/generate.py        (rewrites every case directory it knows)

Each case directory holds the input (case.toml, or what stands in for it) and `expect`:
  line 1: the quicksand commands to try, separated by '|' (e.g. "check|run", "run --resume");
  line 2: a setup step for tests/hostile/run_hostile.cmake, or "-" (see there);
  further lines: texts that must all appear in what quicksand prints on stderr.
Every command must exit non-zero and leave the earlier output/ untouched. To add a case, add a
line to CASES below (or a directory by hand) and run this script; ctest picks it up (label
`hostile`).
"""
import os
import re
import shutil

HERE = os.path.dirname(os.path.abspath(__file__))
BASE = open(os.path.join(HERE, "..", "..", "cases", "verification", "geostatic", "case.toml")).read()
FILE = r"case.toml:[0-9]+: key '"  # the file:line: key prefix every case-file error starts with


def sub(old, new, text=BASE):
    assert old in text, old
    return text.replace(old, new, 1)


def drop(line):
    return sub(line + "\n", "")


def add(section, lines):
    return sub(section + "\n", section + "\n" + lines + "\n")


OPENFOAM = sub('[reservoir]\nmodel = "constant_head"\nhead = 0.2046',
               '[reservoir]\nmodel = "openfoam"\nopenfoam_case = "no_such_case"\nhead = 0.3\narea = 7.85e-3')

# name: (case.toml text or None, commands, setup, [expected texts])
CASES = {
    # missing keys and tables
    "missing_cell_size": (drop("cell_size = 0.0093"), "check|run", "-", ["key 'grid.cell_size'", "missing required key"]),
    "missing_cross_section": (drop("cross_section_area = 5.0014e-3"), "check", "-", ["grid.cross_section_area"]),
    "missing_time_end": (drop("end = 0.5"), "check", "-", ["time.end", "missing required"]),
    "missing_layers": (sub('[[layers]]\nmaterial = "sand"\nthickness = 0.186\n', ""), "check", "-", ["layers"]),
    "missing_materials": (re.sub(r"\[materials\.sand\][^\[]*", "", BASE), "check", "-", ["materials"]),
    "missing_reservoir_head": (drop("head = 0.2046"), "check", "-", ["reservoir.head"]),
    "missing_chamber_height": (drop("chamber_height = 0.0186"), "check", "-", ["column.chamber_height"]),
    "missing_monitor_name": (drop('name = "mid"'), "check", "-", ["monitors[0].name"]),
    # unknown keys and choices
    "unknown_top_level_key": (sub("gravity = 9.81", "gravty = 9.81"), "check", "-", ["gravty", "gravity"]),
    "unknown_grid_key": (sub("cell_size = 0.0093", "cellsize = 0.0093"), "check", "-", ["cellsize", "cell_size"]),
    "unknown_material_key": (sub("k0 = 0.5", "kzero = 0.5"), "check", "-", ["kzero"]),
    "unknown_model": (add("[materials.sand]", 'model = "mohr"'), "check", "-", ["materials.sand.model", "mohr_coulomb"]),
    "unknown_permeability_mode": (sub('mode = "constant"', 'mode = "darcy"'), "check", "-", ["permeability", "darcy"]),
    "unknown_reservoir_model": (sub('model = "constant_head"', 'model = "tank"'), "check", "-", ["reservoir.model", "tank"]),
    "unknown_gate_mode": (BASE + '\n[gate]\nmode = "open"\n', "check", "-", ["gate.mode", "open"]),
    "unknown_initial_state": (BASE + '\n[initial]\nstate = "liquid"\n', "check", "-", ["initial.state", "liquid"]),
    "unknown_layer_material": (sub('material = "sand"', 'material = "snad"'), "check", "-", ["layers[0].material", "Did you mean \"sand\""]),
    "unknown_section": (BASE + "\n[solver]\norder = 2\n", "check", "-", ["solver"]),
    # wrong types
    "cell_size_string": (sub("cell_size = 0.0093", 'cell_size = "0.0093"'), "check", "-", ["grid.cell_size", "write numbers without quotes"]),
    "dimension_float": (sub("dimension = 1", "dimension = 1.0"), "check", "-", ["grid.dimension", "integer"]),
    "porosity_boolean": (sub("porosity = 0.38", "porosity = true"), "check", "-", ["materials.sand.porosity", "number"]),
    "layers_not_tables": (sub('[[layers]]\nmaterial = "sand"\nthickness = 0.186\n', "layers = 1\n"), "check", "-", ["layers"]),
    "monitors_not_tables": (sub('[[monitors]]\nname = "mid"\nelevation = 0.1116', "monitors = [1, 2]"), "check", "-", ["monitors"]),
    "grid_not_table": (sub("[grid]\ndimension = 1\ncell_size = 0.0093\ncross_section_area = 5.0014e-3\n", "grid = 1\n"), "check", "-", ["grid"]),
    "boolean_as_string": (BASE + '\n[initial]\nrigid_skeleton = "yes"\n', "check", "-", ["initial.rigid_skeleton"]),
    "title_number": (sub('title = "Geostatic column (P0 data), water at the sand top"', "title = 3"), "check", "-", ["title"]),
    # out of range
    "dimension_four": (sub("dimension = 1", "dimension = 4"), "check", "-", ["grid.dimension"]),
    "cell_size_negative": (sub("cell_size = 0.0093", "cell_size = -0.0093"), "check", "-", ["grid.cell_size"]),
    "cell_size_zero": (sub("cell_size = 0.0093", "cell_size = 0"), "check", "-", ["grid.cell_size"]),
    "porosity_negative": (sub("porosity = 0.38", "porosity = -0.38"), "check|run", "-", ["materials.sand.porosity"]),
    "porosity_above_one": (sub("porosity = 0.38", "porosity = 1.38"), "check|run", "-", ["materials.sand.porosity"]),
    "max_porosity_below_porosity": (sub("max_porosity = 0.41", "max_porosity = 0.35"), "check", "-", ["max_porosity"]),
    "min_porosity_above_porosity": (sub("min_porosity = 0.32", "min_porosity = 0.40"), "check", "-", ["min_porosity"]),
    "grain_density_zero": (sub("grain_density = 2650", "grain_density = 0"), "check", "-", ["grain_density"]),
    "youngs_modulus_negative": (sub("youngs_modulus = 1.0e6", "youngs_modulus = -1.0e6"), "check", "-", ["youngs_modulus"]),
    "poisson_ratio_half": (sub("poisson_ratio = 0.3", "poisson_ratio = 0.5"), "check", "-", ["poisson_ratio"]),
    # a mirror image needs a mid-plane: 2D plane or 3D
    "porosity_field_mirror_in_1d": (BASE + "\n[initial.porosity_field]\nstandard_deviation = 0.01\n"
                                    "correlation_length = 0.01\nmirror = true\n", "check|run", "-",
                                    ["initial.porosity_field.mirror", "needs a 2D plane or a 3D grid", "1D"]),
    "gravity_negative": (sub("gravity = 9.81", "gravity = -9.81"), "check", "-", ["gravity"]),
    "courant_too_large": (BASE.replace("end = 0.5", "end = 0.5\ncourant = 0.9"), "check", "-", ["time.courant"]),
    "time_end_negative": (sub("end = 0.5", "end = -0.5"), "check", "-", ["time.end"]),
    "output_interval_zero": (sub("output_interval = 0.01", "output_interval = 0"), "check", "-", ["time.output_interval"]),
    "bulk_modulus_zero": (sub("bulk_modulus = 2.128e7", "bulk_modulus = 0"), "check", "-", ["liquid.bulk_modulus"]),
    "pic_share_above_half": (sub("bulk_modulus = 2.128e7", "bulk_modulus = 2.128e7\npic_share = 0.8"), "check", "-",
                             ["liquid.pic_share", "0.5"]),
    "pic_share_and_damping_time": (sub("bulk_modulus = 2.128e7",
                                       "bulk_modulus = 2.128e7\npic_share = 0.01\npic_damping_time = 0.002"),
                                   "check", "-", ["liquid.pic_damping_time", "not both"]),
    "pic_damping_time_zero": (sub("bulk_modulus = 2.128e7", "bulk_modulus = 2.128e7\npic_damping_time = 0"),
                              "check", "-", ["liquid.pic_damping_time", "> 0 s"]),
    "monitor_above_top": (sub("elevation = 0.1116", "elevation = 0.5"), "check", "-", ["monitors[0].elevation"]),
    "head_not_finite": (sub("head = 0.2046", "head = nan"), "check", "-", ["reservoir.head", "finite"]),
    "points_per_cell_zero": (BASE + "\n[points]\nsolid_per_cell = 0\n", "check", "-", ["points.solid_per_cell"]),
    # inconsistent geometry and choices
    "layer_not_whole_cells": (sub("thickness = 0.186", "thickness = 0.19"), "check", "-", ["layers[0].thickness", "cell"]),
    "chamber_zero": (sub("chamber_height = 0.0186", "chamber_height = 0"), "check", "-", ["column.chamber_height"]),
    "chamber_not_whole_cells": (sub("chamber_height = 0.0186", "chamber_height = 0.02"), "check", "-", ["column.chamber_height"]),
    "water_above_top": (sub("water_level = 0.2046", "water_level = 0.3"), "check", "-", ["column.top", "water_level = 0.3"]),
    "overflow_above_water_level": (sub("water_level = 0.2046", "water_level = 0.2046\noverflow_level = 0.2139"), "check|run", "-",
                                   ["column.overflow_level", "differs from water_level = 0.2046", "expected overflow_level = water_level"]),
    "overflow_not_whole_cells": (sub("water_level = 0.2046", "water_level = 0.21\noverflow_level = 0.21"), "check", "-",
                                 ["column.overflow_level", "not a whole number of cells"]),
    "top_below_sand": (sub("top = 0.2232", "top = 0.1"), "check", "-", ["column.top"]),
    "width_in_2d_missing": (sub("dimension = 1", "dimension = 2"), "check", "-", ["grid.width"]),
    "cross_section_disagrees_in_3d": (sub("dimension = 1", "dimension = 3\nwidth = 0.0744"), "check|run", "-",
                                      ["case.toml:12", "grid.cross_section_area", "disagrees", "width^2 = 0.00553536"]),
    "head_below_overflow": (sub("water_level = 0.2046", "water_level = 0.2139\noverflow_level = 0.2139"), "check|run", "-",
                            ["reservoir.head", "below the overflow level", "expected head >= overflow_level"]),
    "axisymmetric_with_gimp": (sub("dimension = 1", 'dimension = 2\ngeometry = "axisymmetric"\nwidth = 0.0372\nshape_functions = "gimp"').replace("cross_section_area = 5.0014e-3\n", ""), "check", "-",
                               ["grid.geometry", "linear"]),
    "axisymmetric_unequal_points": (sub("dimension = 1", 'dimension = 2\ngeometry = "axisymmetric"\nwidth = 0.0372').replace("cross_section_area = 5.0014e-3\n", "") + "\n[points]\nsolid_per_cell = 1\nliquid_per_cell = 2\n", "check", "-",
                                    ["grid.geometry", "solid_per_cell = 1", "liquid_per_cell = 2"]),
    "axisymmetric_in_3d": (sub("dimension = 1", 'dimension = 3\ngeometry = "axisymmetric"\nwidth = 0.0372'), "check|run", "-",
                           ["grid.geometry", "axisymmetric", "grid.dimension = 2"]),
    "axisymmetric_cross_section_disagrees": (sub("dimension = 1", 'dimension = 2\ngeometry = "axisymmetric"\nwidth = 0.0372'), "check", "-",
                                             ["grid.cross_section_area", "disagrees", "pi width^2 = 0.004347"]),
    "geometry_misspelt": (sub("dimension = 1", 'dimension = 2\ngeometry = "axisymetric"\nwidth = 0.0372'), "check", "-",
                          ["grid.geometry", "axisymetric", "axisymmetric"]),
    "min_porosity_near_zero": (sub("min_porosity = 0.32", "min_porosity = 1e-300"), "check|run", "-",
                               ["materials.sand.min_porosity", "implausibly small", ">= 0.05"]),
    "zones_in_1d": (sub("thickness = 0.186", 'thickness = 0.186\n\n[[layers.zones]]\nmaterial = "sand"\nx = [0.0, 0.01]'), "check", "-", ["layers[0].zones", "dimension"]),
    "monitor_range_in_1d": (sub("elevation = 0.1116", "elevation = 0.1116\nx = [0.0, 0.01]"), "check", "-", ["monitors[0].x"]),
    "duplicate_monitor_names": (BASE + '\n[[monitors]]\nname = "mid"\nelevation = 0.05\n', "check", "-", ["monitors[1].name", "unique"]),
    "flux_with_pressure_gate": (BASE + '\n[gate]\nmode = "pressure"\nflux = 1e-3\n', "check", "-", ["gate.flux"]),
    "mohr_coulomb_key_on_linear": (add("[materials.sand]", "friction_angle = 30"), "check", "-", ["friction_angle"]),
    "undrained_without_surcharge": (BASE + "\n[initial]\nundrained_surcharge = true\n", "check", "-", ["initial.undrained_surcharge", "surcharge"]),
    "porosity_field_negative_deviation": (BASE + '\n[initial.porosity_field]\nstandard_deviation = -0.01\ncorrelation_length = 0.02\n',
                                          "check", "-", ["initial.porosity_field.standard_deviation", "-0.01"]),
    "porosity_field_misspelt_key": (BASE + '\n[initial.porosity_field]\nstandard_deviaton = 0.01\ncorrelation_length = 0.02\n',
                                    "check", "-", ["standard_deviaton", "standard_deviation"]),
    "porosity_field_in_a_fluidised_start": (sub("porosity = 0.38", "porosity = 0.45") + '\n[initial]\nstate = "fluidised"\n\n[initial.porosity_field]\nstandard_deviation = 0.01\ncorrelation_length = 0.02\n',
                                            "check", "-", ["initial.porosity_field", "fluidised"]),
    "fluidised_below_max_porosity": (BASE + '\n[initial]\nstate = "fluidised"\nstress = "k0"\n', "check", "-", ["initial.stress"]),
    "time_scheme_misspelt": (sub("end = 0.5", 'end = 0.5\nscheme = "semi-implicit"'), "check|run", "-",
                             ["time.scheme", "semi-implicit", "semi_implicit"]),
    "checkpoint_of_other_scheme": (BASE, "run --resume --set time.scheme='\"semi_implicit\"'", "scheme_checkpoint",
                                   ["checkpoint", "explicit", "time.scheme"]),
    "dt_beyond_stable": (BASE.replace("end = 0.5", "end = 0.5\ndt = 1.0e-3"), "check|run", "-", ["time.dt", "stable step"]),
    # unit mistakes
    "viscosity_in_kpa_s": (sub("viscosity = 8.91e-4", "viscosity = 8.91e-7"), "check", "-", ["liquid.viscosity", "kPa s"]),
    "permeability_in_m_per_s": (sub("value = 1.49e-10", "value = 1.5e-3"), "check", "-", ["permeability", "m/s"]),
    "grain_density_in_g_per_cm3": (sub("grain_density = 2650", "grain_density = 2.65"), "check", "-", ["grain_density", "g/cm3"]),
    "cell_size_in_mm": (sub("cell_size = 0.0093", "cell_size = 9.3"), "check", "-", ["cell"]),
    # broken files
    "toml_syntax_error": (sub("[grid]", "[grid"), "check|run", "-", ["TOML syntax error"]),
    "unterminated_string": (sub('title = "Geostatic column (P0 data), water at the sand top"', 'title = "Geostatic'), "check", "-", ["TOML syntax error"]),
    "duplicate_key": (sub("cell_size = 0.0093", "cell_size = 0.0093\ncell_size = 0.0093"), "check", "-", ["TOML syntax error"]),
    "empty_file": ("", "check|run", "-", ["case.toml"]),
    "binary_file": (None, "check", "binary", ["case.toml"]),
    "one_megabyte_line": (None, "check", "long_line", ["case.toml"]),
    "deep_nesting": (None, "check", "deep_nesting", ["case.toml"]),
    "no_case_file": (None, "check|run", "-", ["case.toml"]),
    "case_file_is_a_directory": (None, "check", "case_is_directory", ["is a directory"]),
    # OpenFOAM
    "openfoam_case_missing": (OPENFOAM, "check|run", "-", ["no_such_case"]),
    # checkpoints and output
    "resume_without_checkpoint": (BASE, "run --resume", "-", ["checkpoint"]),
    "truncated_checkpoint": (BASE, "run --resume", "truncated_checkpoint", ["checkpoint"]),
    "foreign_checkpoint": (BASE, "run --resume", "foreign_checkpoint", ["checkpoint"]),
    "checkpoint_of_another_case": (BASE, "run --resume", "other_case_checkpoint", ["checkpoint"]),
    "case_directory_read_only": (BASE, "run", "read_only", ["output"]),
    "output_directory_is_a_file": (BASE + '\n[output]\ndirectory = "results"\n', "run", "output_is_file", ["output.directory", "is a file"]),
}


def main():
    for name, (text, commands, setup, expected) in CASES.items():
        d = os.path.join(HERE, name)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        if text is not None:
            with open(os.path.join(d, "case.toml"), "w") as f:
                f.write(text)
        with open(os.path.join(d, "expect"), "w") as f:
            f.write(commands + "\n" + setup + "\n" + "\n".join(expected) + "\n")
    print(f"{len(CASES)} hostile cases written to {HERE}")


if __name__ == "__main__":
    main()
