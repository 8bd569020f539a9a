#pragma once
// The compare report's section "Against the published study" (published_study.hpp): our figures beside a
// published study's for the same case, and which of its findings our runs reproduce.
#include <ostream>
#include <string>
#include <vector>

#include "conforma/published_study.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma::cli {

// The run's figures at the published step count (study.steps; the last step when the run has fewer or steps is 0).
RunFigures RunFiguresAt(const std::string& model, const WearSimulationResult& run, int steps);

// Writes the Markdown section; nothing when the study is empty. Returns the checks (for the command's summary).
std::vector<PublishedCheck> WritePublishedSection(std::ostream& md, const PublishedStudy& study,
                                                  const std::vector<RunFigures>& runs);

}  // namespace conforma::cli
