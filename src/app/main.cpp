// conforma: command-line entry point. Subcommands are registered in their own files (src/app/cmd_*.cpp).
#include <CLI/CLI.hpp>
#include <glog/logging.h>
#include <iostream>

#include "commands.hpp"
#include "exit_status.hpp"
#include "conforma/error.hpp"

int main(int argc, char** argv) {
  // Ceres reports failed residual evaluations through glog; the curving solver treats them as a normal outcome
  // (counted in its status), so only fatal messages reach the terminal.
  FLAGS_minloglevel = google::GLOG_FATAL;
  CLI::App app{"Conforma: conformal wheel-rail contact and wear"};
  app.option_defaults()->always_capture_default();
  app.require_subcommand(1);
  app.set_version_flag("--version", "conforma 0.1.0");
  // exit 0 with an incomplete result (not converged, partial): the output still carries the status
  bool allow_partial = false;
  app.add_flag("--allow-partial", allow_partial,
               "exit 0 even when the result is incomplete (the output still says what is missing)");
  // the progress display of the long commands on stderr (progress.hpp); read by each command (ProgressModeOf)
  app.add_flag("--quiet", "no progress display on stderr (results on stdout, warnings and errors are unchanged)");
  app.fallthrough();  // --allow-partial and --quiet may follow the subcommand
  conforma::cli::RegisterContactCommand(app);
  conforma::cli::RegisterSweepCommand(app);
  conforma::cli::RegisterProfileCommand(app);
  conforma::cli::RegisterMbenchCommand(app);
  conforma::cli::RegisterWearCommand(app);
  conforma::cli::RegisterCompareCommand(app);
  conforma::cli::RegisterBenchCommand(app);
  conforma::cli::RegisterThresholdCommand(app);
  conforma::cli::RegisterStressCommand(app);
  conforma::cli::RegisterCurvingCommand(app);
  conforma::cli::RegisterValidateCommand(app);
  conforma::cli::RegisterTrackCommand(app);
  conforma::cli::RegisterDynamicsCommand(app);
  conforma::cli::RegisterLutCommand(app);
  conforma::cli::RegisterRigAdhesionCommand(app);
  conforma::cli::RegisterRigCommand(app);
  conforma::cli::RegisterCampaignCommand(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help / --version: CLI11 prints them (exit 0); a malformed command line is an input error like any other
    // (CLI11's own codes 104-114 and messages without the prefix before: fuzzing, session 25)
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return app.exit(e);
    std::cerr << "conforma: error: " << e.what() << " (see --help)\n";
    return static_cast<int>(conforma::cli::ExitCode::InputError);
  } catch (const conforma::cli::IncompleteResult& e) {
    std::cerr << "conforma: " << (allow_partial ? "warning" : "error") << ": incomplete result: " << e.what()
              << (allow_partial ? " (--allow-partial: exit 0)" : "") << "\n";
    return allow_partial ? 0 : static_cast<int>(e.code());
  } catch (const conforma::InputError& e) {
    std::cerr << "conforma: error: " << e.what() << "\n";
    return static_cast<int>(conforma::cli::ExitCode::InputError);
  } catch (const std::exception& e) {
    std::cerr << "conforma: internal error: " << e.what() << "\n";
    return static_cast<int>(conforma::cli::ExitCode::InternalError);
  }
  return 0;
}
