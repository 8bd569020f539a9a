#pragma once
// Checks a command makes BEFORE it computes, so that a user mistake is an input error at once and not an internal
// error after minutes (issue 13): the output folder, the plotting interpreter, the contact models of a wear run.
#include <string>
#include <vector>

#include "conforma/contact_model.hpp"
#include "conforma/scenario.hpp"

namespace conforma::cli {

// Creates `dir` (and its parents) and checks that a file can be written in it; InputError naming `option` otherwise.
void EnsureOutputFolder(const std::string& dir, const std::string& option);
// Runs `python -c "import matplotlib"`; InputError naming `option` when the interpreter is missing or lacks
// matplotlib (the plots of compare / validate would be missing).
void RequirePlotPython(const std::string& python, const std::string& option);
// A contact model that can drive the wear loop (IsWearContactModel); InputError naming `option` and the usable
// models otherwise (reference: normal problem only).
ContactModel ParseWearModel(const std::string& name, const std::string& option);
// A comma-separated list of such models (at least one); the names as given.
std::vector<std::string> ParseWearModelList(const std::string& list, const std::string& option);
// A wear run's optional limits as given on the command line (`given`: the option was used): --steps a whole number
// >= 0, --km finite and >= 0; InputError naming the option otherwise (a negative or NaN value meant "the
// scenario's" silently before).
void CheckRunLimits(bool steps_given, int steps, bool km_given, double km);
// An OpenMP thread count given on the command line: 0 (the default) ... kMaxThreads; InputError naming `option`
// (stress --threads 100000 segfaulted in libgomp: fuzzing, session 25).
void RequireThreads(long threads, const std::string& option);
// A file the command writes at its end: created (truncated) now, so that an unwritable path is an InputError naming
// `option` before the work (stress --json to an unwritable path wrote nothing and exited 0).
void EnsureWritableFile(const std::string& path, const std::string& option);
// Warns on stderr for every track class whose friction coefficient lies outside the plausible range of wheel-rail
// contact (kMinPlausibleFriction ... kMaxPlausibleFriction, as `contact` and `dynamics` warn): friction 1e-300 ran a
// wear step of ~1e300 km with exit 0 and no word (probe of wear --set, session 27).
void WarnImplausibleFriction(const Scenario& scenario);
// Help text of a wear run's --model(s) option: "<what> (hertz, kp, kpec, conformal, auto)".
std::string WearModelHelp(const std::string& what);

}  // namespace conforma::cli
