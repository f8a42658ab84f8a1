#include "solver/Run.hpp"

#include "solver/Simulation.hpp"

namespace qs {

std::vector<std::string> seriesColumns(const CaseConfig& config) {
    std::vector<std::string> c = {"time",         "gate_flux",  "gate_pressure",   "reservoir_head",
                                  "sand_surface", "bed_height", "fluidised_front", "fluidised_share",
                                  "water_surface", "gradient"};
    for (const auto& m : config.monitors) c.push_back("q_" + m.name);
    for (const char* k : {"cumulative_inflow", "cumulative_outflow", "injected_volume", "ledger_residual",
                          "solid_mass", "liquid_mass", "solid_points", "liquid_points", "cumulative_solid_outflow"})
        c.push_back(k);
    return c;
}

RunSummary runCase(const CaseConfig& config, const RunOptions& options) {
    Simulation simulation(config, options);
    simulation.advanceTo(options.endTime >= 0 ? options.endTime : config.time.end);
    return simulation.finish();
}

}  // namespace qs
