#pragma once
// Output of the rail steps of a wear run (paper 003 §6 and Fig. 11; conforma/rail_step_summary.hpp), next to the
// files of wear_output.hpp: rail_steps.csv (one row per rail step: wheel sequence, each rail's removed area and
// depth, the mean of the virtual rails' areas and the relative difference, validity), rail_step_NNN_depth.csv
// (depth of every virtual rail and of the averaged rail along the rail before the step), rail_cumulative_depth.csv
// (each rail against the initial one), rail_steps.md, and the plots of scripts/plot_rail_steps.py.
#include <string>
#include <vector>

#include "conforma/rail_step_summary.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma::cli {

// Largest relative difference between a rail's removed area and the weighted mean of its virtual rails' areas that
// rail_steps.md and the summary call "holds" (the acceptance level; rail_step_summary.hpp).
inline constexpr double kRailAreaIdentityTolerance = 1e-9;

// Writes the CSV files; returns the summary they were written from (empty with a fixed rail: nothing written).
std::vector<RailStepSummary> WriteRailStepFiles(const std::string& dir, const WearSimulationResult& result);
// rail_steps.md: the table and (unless plot_note says why not) the plots.
void WriteRailStepReport(const std::string& dir, const Scenario& scenario, const std::vector<RailStepSummary>& rail,
                         const std::string& label, const std::string& plot_note);
// One line per rail step on stdout, and whether every rail step holds the identity with valid profiles.
bool PrintRailStepSummary(const std::vector<RailStepSummary>& rail);

}  // namespace conforma::cli
