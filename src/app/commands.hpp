#pragma once
// Subcommands of the conforma executable; each file src/app/cmd_<name>.cpp registers one.
#include <CLI/CLI.hpp>

namespace conforma::cli {

void RegisterContactCommand(CLI::App& app);  // conforma contact: one wheelset pose, any model
void RegisterSweepCommand(CLI::App& app);    // conforma sweep: lateral sweep table (the default main job)
void RegisterProfileCommand(CLI::App& app);  // conforma profile: info / write standard profiles
void RegisterMbenchCommand(CLI::App& app);   // conforma mbench: Manchester against CONTACT

}  // namespace conforma::cli
