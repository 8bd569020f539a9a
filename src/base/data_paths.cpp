#include "conforma/data_paths.hpp"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <system_error>

// Set for this file only by the top-level CMakeLists (never in a header): the CONFORMA_SHARED_DATA option and the
// install share folder relative to the install bin folder.
#ifndef CONFORMA_DEFAULT_SHARED_DATA
#define CONFORMA_DEFAULT_SHARED_DATA ""
#endif
#ifndef CONFORMA_SHARE_DIR_FROM_BIN
#define CONFORMA_SHARE_DIR_FROM_BIN "../share/conforma"
#endif

namespace conforma {

namespace fs = std::filesystem;

namespace {
std::string Env(const char* name) {
  const char* v = std::getenv(name);
  return v ? std::string(v) : std::string();
}

std::string NoTrailingSlash(std::string s) {
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  return s;
}
}  // namespace

std::string ExecutableDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.parent_path().string();
}

std::string ShareDir(const std::string& build_tree_fallback) {
  const std::string env = Env("CONFORMA_SHARE_DIR");
  if (!env.empty()) return NoTrailingSlash(env);
  const std::string exe_dir = ExecutableDir();
  if (!exe_dir.empty()) {
    const fs::path installed = (fs::path(exe_dir) / CONFORMA_SHARE_DIR_FROM_BIN).lexically_normal();
    std::error_code ec;
    if (fs::is_directory(installed, ec)) return NoTrailingSlash(installed.string());
  }
  return NoTrailingSlash(build_tree_fallback);
}

std::string DefaultSharedDataDir() { return CONFORMA_DEFAULT_SHARED_DATA; }

std::string SharedDataDir() {
  const std::string env = Env("CONFORMA_DATA_DIR");
  return env.empty() ? DefaultSharedDataDir() : NoTrailingSlash(env);
}

std::string PythonInterpreter() {
  const std::string env = Env("CONFORMA_PYTHON");
  if (!env.empty()) return env;
  // the plot scripts need matplotlib and NumPy (Debian's python3-matplotlib): an interpreter earlier on PATH (e.g.
  // a pyenv shim) may lack them, so the first python3 on PATH that imports them wins, else the first one at all
  std::string first;
  std::stringstream path(Env("PATH"));
  for (std::string dir; std::getline(path, dir, ':');) {
    const std::string candidate = (dir.empty() ? std::string(".") : dir) + "/python3";
    if (::access(candidate.c_str(), X_OK) != 0) continue;
    if (first.empty()) first = candidate;
    const std::string probe = "'" + candidate + "' -c 'import matplotlib, numpy' >/dev/null 2>&1";
    if (std::system(probe.c_str()) == 0) return candidate;
  }
  return first.empty() ? "python3" : first;
}

}  // namespace conforma
