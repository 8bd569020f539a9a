#pragma once
// Exit codes of the conforma executable (documented in README.md, "Exit codes") and the exception a command throws
// when its result is incomplete. A command writes whatever output it has first (with the status in it), then throws
// IncompleteResult; main() prints the reason to stderr and exits with its code, or with 0 under --allow-partial.
#include <stdexcept>
#include <string>

namespace conforma::cli {

enum class ExitCode : int {
  Ok = 0,              // complete result
  InputError = 2,      // bad option, file, profile or scenario: nothing (or nothing useful) was computed
  InternalError = 3,   // a bug: please report it
  NotConverged = 4,    // a solve did not reach its tolerance (e.g. load control); the output says which
  PartialResult = 5,   // some parts of the result are missing (failed contacts, cases, plots); the output says which
};

class IncompleteResult : public std::runtime_error {
 public:
  IncompleteResult(ExitCode code, const std::string& what) : std::runtime_error(what), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

}  // namespace conforma::cli
