// The Python binding of the solver (pybind11, Debian's pybind11-dev): quicksand's Simulation as
// a Python object, for notebooks and scripts that drive a run step by step. The package's
// quicksand.solver (tools/quicksand/solver.py) wraps it:
//
//   sim = quicksand_solver.Simulation("cases/verification/terzaghi", ["time.end=0.5"], False, True)
//   sim.advance_to(0.1)                     # s; the GIL is released while it steps
//   sim.points(True)["porosity"]            # numpy arrays of the registry's point fields
//   sim.profile()["pore_pressure"]          # the cell rows' means along the vertical
//
// Errors are quicksand's messages as quicksand_solver.SolverError (a RuntimeError); Ctrl-C ends
// the step in progress, writes the checkpoint and raises KeyboardInterrupt with quicksand's
// message (solver/Interruption.hpp installs its handler only inside advance_to).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "case/CaseLoader.hpp"
#include "case/CaseOverride.hpp"
#include "core/BuildInfo.hpp"
#include "core/Error.hpp"
#include "solver/Interruption.hpp"
#include "solver/Simulation.hpp"

namespace py = pybind11;

namespace {

/// A run opened from a case directory and --set overrides, as `quicksand run` opens it.
class Session {
public:
    Session(const std::string& caseDirectory, const std::vector<std::string>& sets, bool writeFiles, bool quiet,
            bool resume) {
        std::vector<qs::CaseOverride> overrides;
        for (const std::string& set : sets) overrides.push_back(qs::parseOverride(set));
        const qs::CaseConfig config = qs::loadCase(caseDirectory, overrides);
        qs::RunOptions options;
        options.writeFiles = writeFiles;
        options.quiet = quiet;
        options.resume = resume;
        simulation_ = std::make_unique<qs::Simulation>(config, options);
    }

    qs::Simulation& simulation() { return *simulation_; }
    const qs::Simulation& simulation() const { return *simulation_; }

private:
    std::unique_ptr<qs::Simulation> simulation_;
};

/// `values` (n x components, point after point) as an n x components array (n if one component).
py::array_t<double> asArray(const std::vector<double>& values, int components) {
    const auto n = static_cast<py::ssize_t>(components > 0 ? values.size() / components : 0);
    py::array_t<double> a = components == 1 ? py::array_t<double>({n}) : py::array_t<double>({n, py::ssize_t(components)});
    std::copy(values.begin(), values.end(), a.mutable_data());
    return a;
}

py::dict stateOf(const qs::ColumnState& s) {
    py::dict d;
    d["time"] = s.time;
    d["gate_flux"] = s.gateFlux;
    d["gate_pressure"] = s.gatePressure;
    d["reservoir_head"] = s.reservoirHead;
    d["sand_surface"] = s.sandSurface;
    d["bed_height"] = s.bedHeight;
    d["fluidised_front"] = s.fluidisedFront;
    d["fluidised_share"] = s.fluidisedShare;
    d["water_surface"] = s.waterSurface;
    d["gradient"] = s.gradient;
    d["monitor_flux"] = s.monitorFlux;
    d["cumulative_inflow"] = s.cumulativeInflow;
    d["cumulative_outflow"] = s.cumulativeOutflow;
    d["cumulative_solid_outflow"] = s.cumulativeSolidOutflow;
    d["injected_volume"] = s.injectedVolume;
    d["ledger_residual"] = s.ledgerResidual;
    d["solid_mass"] = s.solidMass;
    d["liquid_mass"] = s.liquidMass;
    d["solid_points"] = s.solidPoints;
    d["liquid_points"] = s.liquidPoints;
    return d;
}

/// The profile's rows as columns (SI: m, Pa, -, m/s).
py::dict profileOf(const std::vector<qs::CellRow>& rows) {
    const auto column = [&](auto member) {
        std::vector<double> v;
        v.reserve(rows.size());
        for (const auto& r : rows) v.push_back(static_cast<double>(r.*member));
        return asArray(v, 1);
    };
    py::dict d;
    d["z"] = column(&qs::CellRow::z);
    d["pore_pressure"] = column(&qs::CellRow::porePressure);
    d["vertical_stress"] = column(&qs::CellRow::verticalStress);
    d["horizontal_stress"] = column(&qs::CellRow::horizontalStress);
    d["porosity"] = column(&qs::CellRow::porosity);
    d["fluidised_share"] = column(&qs::CellRow::fluidisedShare);
    d["filter_velocity"] = column(&qs::CellRow::filterVelocity);
    d["solid_count"] = column(&qs::CellRow::solidCount);
    d["liquid_count"] = column(&qs::CellRow::liquidCount);
    return d;
}

/// The cells (2D, 3D) as arrays indexed [row][column] in 2D, [row][y][x] in 3D.
py::dict cellsOf(const qs::SandCells& c) {
    std::vector<py::ssize_t> shape;
    for (int a = c.dimension - 1; a >= 0; --a) shape.push_back(static_cast<py::ssize_t>(c.cells[a]));
    py::array_t<double> porosity(shape), state(shape);
    std::copy(c.porosity.begin(), c.porosity.end(), porosity.mutable_data());  // NaN where no sand
    std::transform(c.state.begin(), c.state.end(), state.mutable_data(),  // 0 no sand, 1 solid, 2 fluidised
                   [](qs::CellSand s) { return static_cast<double>(static_cast<int>(s)); });
    py::dict d;
    d["porosity"] = porosity;
    d["state"] = state;
    d["base_flux"] = asArray(c.baseFlux, 1);
    d["h"] = c.h;
    d["filter_level"] = c.filterLevel;
    d["base_row"] = c.baseRow;
    return d;
}

}  // namespace

PYBIND11_MODULE(quicksand_solver, m) {
    m.doc() = "quicksand's solver: a double-point MPM column as a Python object (tools/quicksand/solver.py)";
    static py::exception<qs::Error> solverError(m, "SolverError", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const qs::Interrupted& e) {
            PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
        } catch (const qs::Error& e) {
            solverError(e.what());
        }
    });
    m.attr("build") = qs::buildLine();

    py::class_<Session>(m, "Simulation")
        .def(py::init<const std::string&, const std::vector<std::string>&, bool, bool, bool>(), py::arg("case"),
             py::arg("sets") = std::vector<std::string>{}, py::arg("write_files") = true, py::arg("quiet") = true,
             py::arg("resume") = false)
        .def_property_readonly("time", [](const Session& s) { return s.simulation().time(); })
        .def_property_readonly("dt", [](const Session& s) { return s.simulation().dt(); })
        .def_property_readonly("steps", [](const Session& s) { return s.simulation().steps(); })
        .def_property_readonly("dimension", [](const Session& s) { return s.simulation().dimension(); })
        .def("advance_to", [](Session& s, double end) { s.simulation().advanceTo(end); }, py::arg("end"),
             py::call_guard<py::gil_scoped_release>())
        .def("state", [](const Session& s) { return stateOf(s.simulation().state()); })
        .def("profile", [](const Session& s) { return profileOf(s.simulation().profile()); })
        .def("points",
             [](const Session& s, bool solid) {
                 py::dict d;
                 for (const auto& f : s.simulation().pointFields(solid)) d[f.name.c_str()] = asArray(f.values, f.components);
                 return d;
             },
             py::arg("solid"))
        .def("cells", [](const Session& s) { return cellsOf(s.simulation().sandCells()); })
        .def("write_output", [](Session& s) { s.simulation().writeOutput(); })
        .def("write_checkpoint", [](Session& s) { s.simulation().writeCheckpoint(); })
        .def("finish", [](Session& s) {
            const qs::RunSummary r = s.simulation().finish();
            py::dict d;
            d["final"] = stateOf(r.final);
            d["steps"] = r.steps;
            d["wall_seconds"] = r.wallSeconds;
            d["dt"] = r.dt;
            return d;
        });
}
