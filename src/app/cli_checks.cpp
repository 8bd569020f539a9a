// Checks made before computing (cli_checks.hpp).
#include "cli_checks.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "cli_setup.hpp"
#include "conforma/contact_plausibility.hpp"
#include "conforma/error.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma::cli {

void EnsureOutputFolder(const std::string& dir, const std::string& option) {
  if (dir.empty()) throw InputError("option " + option + ": empty output folder");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw InputError("option " + option + ": cannot create the output folder '" + dir + "'" +
                     (ec ? ": " + ec.message() : std::string(": not a folder")));
  const std::filesystem::path probe = std::filesystem::path(dir) / ".conforma_write_check";
  {
    std::ofstream f(probe);
    if (!(f << "x") || !(f.flush()))
      throw InputError("option " + option + ": cannot write in the output folder '" + dir + "'");
  }
  std::filesystem::remove(probe, ec);
}

void RequirePlotPython(const std::string& python, const std::string& option) {
  const std::string cmd = "'" + python + "' -c 'import matplotlib' >/dev/null 2>&1";
  if (std::system(cmd.c_str()) != 0)
    throw InputError("option " + option + ": '" + python +
                     "' cannot import matplotlib (is it a Python interpreter? install python3-matplotlib, set "
                     "CONFORMA_PYTHON, give " + option + ", or skip the plots with --no-plot)");
}

ContactModel ParseWearModel(const std::string& name, const std::string& option) {
  ContactModel m;
  try {
    m = ParseContactModel(name);
  } catch (const InputError&) {
    throw InputError("option " + option + ": unknown contact model '" + name + "' (usable: " +
                     WearContactModelNames() + ")");
  }
  if (!IsWearContactModel(m))
    throw InputError("option " + option + ": contact model '" + name +
                     "' solves the normal problem only (no creep forces, no wear); usable: " + WearContactModelNames());
  return m;
}

std::vector<std::string> ParseWearModelList(const std::string& list, const std::string& option) {
  const std::vector<std::string> names = SplitCommaList(list, option);
  if (names.empty()) throw InputError("option " + option + ": no contact model given (usable: " + WearContactModelNames() + ")");
  for (const std::string& n : names) ParseWearModel(n, option);
  return names;
}

void CheckRunLimits(bool steps_given, int steps, bool km_given, double km) {
  if (steps_given && steps < 0)
    throw InputError("option --steps must be >= 0 (omit it for the scenario's), got " + std::to_string(steps));
  if (km_given && !(std::isfinite(km) && km >= 0.0)) {
    char text[160];
    std::snprintf(text, sizeof text, "option --km must be finite and >= 0 (omit it for the scenario's), got %g", km);
    throw InputError(text);
  }
}

void RequireThreads(long threads, const std::string& option) {
  constexpr long kMaxThreads = 256;
  if (threads >= 0 && threads <= kMaxThreads) return;
  throw InputError("option " + option + " must lie in [0, " + std::to_string(kMaxThreads) + "] (0: the default), got " +
                   std::to_string(threads));
}

void EnsureWritableFile(const std::string& path, const std::string& option) {
  std::ofstream f(path);
  if (!f) throw InputError("option " + option + ": cannot write '" + path + "'");
}

void WarnImplausibleFriction(const Scenario& scenario) {
  for (const TrackClass& c : scenario.classes)
    if (!IsPlausibleFriction(c.friction_coefficient))
      std::fprintf(stderr,
                   "warning: track class %s: friction %g is outside the plausible range %g to %g of wheel-rail "
                   "contact (dry steel ~0.3-0.6, wet or contaminated down to ~0.05)\n",
                   c.name.c_str(), c.friction_coefficient, kMinPlausibleFriction, kMaxPlausibleFriction);
}

std::string WearModelHelp(const std::string& what) { return what + " (" + WearContactModelNames() + ")"; }

}  // namespace conforma::cli
