#pragma once
// `quicksand check CASE`: the derived quantities a user wants to see before a run.
#include <iosfwd>

#include "case/CaseConfig.hpp"

namespace qs {

/// Expected steady filter velocity (m/s) through the layers in series for the reservoir's
/// initial head, Darcy-Forchheimer in every layer plus the tube's loss (lumped reservoir).
/// Zero when there is no outflow level or the gate is not pressure-driven.
double expectedSteadyFilterVelocity(const CaseConfig& config);

/// Throws qs::Error, before printing anything, for a case that `run` would refuse before its first
/// step (validateRun, solver/RunPreconditions.hpp); else prints the report, ending "case OK".
void printCheckReport(const CaseConfig& config, std::ostream& out);

/// The run's size (cells, points, steps), estimated peak memory and wall time
/// (solver/RunSize.hpp).
void printRunSize(const CaseConfig& config, std::ostream& out);

}  // namespace qs
