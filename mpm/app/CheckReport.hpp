#pragma once
// `quicksand check CASE`: the derived quantities a user wants to see before a run.
#include <iosfwd>

#include "io/CaseConfig.hpp"

namespace qs {

/// Expected steady filter velocity (m/s) through the layers in series for the reservoir's
/// initial head, Darcy-Forchheimer in every layer plus the tube's loss (lumped reservoir).
/// Zero when there is no outflow level or the gate is not pressure-driven.
double expectedSteadyFilterVelocity(const CaseConfig& config);

void printCheckReport(const CaseConfig& config, std::ostream& out);

/// The run's size (cells, points, steps), estimated peak memory and wall time; throws qs::Error
/// when the memory exceeds the machine's (solver/RunSize.hpp).
void printRunSize(const CaseConfig& config, std::ostream& out);

}  // namespace qs
