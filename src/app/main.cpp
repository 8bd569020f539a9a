// conforma: command-line entry point. Subcommands are registered in their own files (src/app/cmd_*.cpp).
#include <CLI/CLI.hpp>
#include <iostream>

int main(int argc, char** argv) {
  CLI::App app{"Conforma: conformal wheel-rail contact and wear"};
  app.require_subcommand(0, 1);
  app.set_version_flag("--version", "conforma 0.1.0");
  CLI11_PARSE(app, argc, argv);
  if (app.get_subcommands().empty()) std::cout << app.help();
  return 0;
}
