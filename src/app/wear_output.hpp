#pragma once
// Output of a wear run (conforma wear / conforma compare): steps.csv, profiles of every step (.prw/.prr + CSV),
// wear distributions, and the progress display on stderr (progress.hpp).
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "conforma/wear_simulation.hpp"
#include "progress.hpp"

namespace conforma::cli {

// Creates dir.
void BeginWearOutput(const std::string& dir);
// Appends the files of one step (profiles, wear distribution CSV).
void WriteWearStep(const std::string& dir, const WearStepRecord& step);
// steps.csv (all steps), the initial profiles (wheel_step_000, rail_{left,right}_000) and the rails of the rail steps.
void FinishWearOutput(const std::string& dir, const WearSimulationResult& result);
// One line per step that lost wheel contacts or used a kinematics fallback ("WARNING: [label] step j: ..."), to
// stdout, so that a run that lost contacts never reads as a clean one.
void PrintRunWarnings(const std::string& label, const WearSimulationResult& result);
// The same for report.md: one bold "**WARNING: <label> step j: n of m wheel contacts failed; ...**" paragraph per
// step that lost contacts (compare and validate reports).
void WriteLostContactWarnings(std::ostream& md, const std::string& label, const WearSimulationResult& result);
// Throws IncompleteResult(PartialResult) naming every (label, result) whose IncompleteReason is not empty; call it
// after all outputs are written.
void ThrowIfIncomplete(const std::vector<std::pair<std::string, const WearSimulationResult*>>& runs);
// One run with all of the above in dir; its wall time in *wall_s. Progress on stderr in `mode`, labelled `label`,
// one unit per wheel step out of steps_total per rail step (detail: km, Sd, qR, wall time of the step).
WearSimulationResult RunWearWithOutput(const Scenario& scenario, WearSimulationOptions options, const std::string& dir,
                                       const std::string& label, int steps_total, double* wall_s,
                                       ProgressMode mode);

}  // namespace conforma::cli
