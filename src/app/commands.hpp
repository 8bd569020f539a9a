#pragma once
// Subcommands of the conforma executable; each file src/app/cmd_<name>.cpp registers one.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "conforma/wheel_contact_options.hpp"

namespace conforma::cli {

void RegisterContactCommand(CLI::App& app);  // conforma contact: one wheelset pose, any model
void RegisterSweepCommand(CLI::App& app);    // conforma sweep: lateral sweep table (the default main job)
void RegisterProfileCommand(CLI::App& app);  // conforma profile: info / write standard profiles
void RegisterMbenchCommand(CLI::App& app);   // conforma mbench: Manchester against CONTACT
void RegisterWearCommand(CLI::App& app);     // conforma wear: wear loop of a scenario
void RegisterCompareCommand(CLI::App& app);  // conforma compare: several contact models on one scenario, report
void RegisterBenchCommand(CLI::App& app);    // conforma bench: run time against error per model and grid
void RegisterThresholdCommand(CLI::App& app);  // conforma threshold: conformity-index threshold study
void RegisterStressCommand(CLI::App& app);     // conforma stress: numerical stability stress suite
void RegisterCurvingCommand(CLI::App& app);    // conforma curving: curving kinematics and wheel forces per class
void RegisterValidateCommand(CLI::App& app);   // conforma validate: wear simulation against measured wheels
void RegisterTrackCommand(CLI::App& app);      // conforma track: track irregularities from a PSD
void RegisterDynamicsCommand(CLI::App& app);   // conforma dynamics: time-domain lateral vehicle dynamics, eigenvalues
void RegisterLutCommand(CLI::App& app);        // conforma lut: contact look-up table build / info / eval / check
void RegisterRigAdhesionCommand(CLI::App& app);  // conforma rig-adhesion: roller-rig adhesion tests (paper 000)
void RegisterRigCommand(CLI::App& app);        // conforma rig run|replay: roller-rig wear test plan, replay (paper 000)
void RegisterCampaignCommand(CLI::App& app);   // conforma campaign: many runs of generated scenarios (Python, Dask)

// Run-time files of the commands (conforma/data_paths.hpp), resolved when a command runs, not when it is declared
// (src/app/run_time_paths.cpp):
// scripts/<name> in the share dir ($CONFORMA_SHARE_DIR, the installed share/conforma, else this build's sources).
std::string PlotScript(const std::string& name);
// --data: the given folder, else $CONFORMA_DATA_DIR, else the built-in default.
std::string DataDirOr(const std::string& given);
// --python: the given interpreter, else $CONFORMA_PYTHON, else python3 on PATH.
std::string PythonOr(const std::string& given);
inline constexpr const char* kDataHelp =
    "shared data folder (default: $CONFORMA_DATA_DIR, else the build's CONFORMA_SHARED_DATA)";
// --kp-spin-about-centre and --kp-local-flexibilities: the FASTSIM variants on the KP patches
// (WheelContactOptions::kp_spin_about_patch_centre, kp_local_flexibilities; docs/physics-reference.md §5.4), off by
// default as in WheelContactOptions.
inline void AddKpFastsimFlags(CLI::App* sub, bool* spin_centre, bool* local_flex) {
  *spin_centre = WheelContactOptions{}.kp_spin_about_patch_centre;
  *local_flex = WheelContactOptions{}.kp_local_flexibilities;
  sub->add_flag("--kp-spin-about-centre", *spin_centre,
                "kp, kpec, conformal: FASTSIM's spin about the patch centre (docs/physics-reference.md §5.4)");
  sub->add_flag("--kp-local-flexibilities", *local_flex,
                "kp, kpec, conformal: strip-wise FASTSIM flexibilities from the local half-length (§5.4)");
}
// --set KEY=VALUE (repeatable): overrides of the scenario file's keys (LoadScenario with overrides, scenario.hpp).
inline void AddScenarioOverrides(CLI::App* sub, std::vector<std::string>* overrides) {
  sub->add_option("--set", *overrides,
                  "override a scenario key, KEY a dotted path, VALUE YAML (repeatable), e.g. --set "
                  "kinematics.provider=dynamic --set 'kinematics.dynamic={contact: lut, duration_s: 64}'")
      ->allow_extra_args(false);
}
inline constexpr const char* kPythonHelp =
    "python interpreter with matplotlib for the plots (default: $CONFORMA_PYTHON, else python3 on PATH)";

}  // namespace conforma::cli
