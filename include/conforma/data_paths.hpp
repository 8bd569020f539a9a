#pragma once
// Where Conforma finds its run-time files. Everything is resolved when called (environment first), nothing is
// baked into this header, so an installed package and an uninstalled build tree both work:
//   share dir (scripts/plot_*.py, scenarios/, profiles/): $CONFORMA_SHARE_DIR, else <executable dir>/../share/conforma
//       (the install layout) when that folder exists, else the caller's fallback (an uninstalled build tree passes
//       its source folder);
//   shared reference data dir (measured wheels, CONTACT references, profile banks; docs/data.md):
//       $CONFORMA_DATA_DIR, else the CMake option CONFORMA_SHARED_DATA the library was built with;
//   python interpreter (plot scripts): $CONFORMA_PYTHON, else the first python3 on PATH that imports matplotlib and
//       NumPy, else the first python3 on PATH.
#include <string>

namespace conforma {

// Folder of the running executable (/proc/self/exe); "" when it cannot be read.
std::string ExecutableDir();

// The share dir as described above; `build_tree_fallback` is returned when neither the environment variable nor the
// installed folder is there (it may be ""). The result has no trailing '/'.
std::string ShareDir(const std::string& build_tree_fallback = std::string());

// $CONFORMA_DATA_DIR when set and not empty, else DefaultSharedDataDir().
std::string SharedDataDir();
// The built-in default: the CMake option CONFORMA_SHARED_DATA at build time.
std::string DefaultSharedDataDir();

// $CONFORMA_PYTHON when set and not empty, else the full path of the first python3 on PATH that imports matplotlib
// and NumPy (one probe per candidate), else the first python3 on PATH, else "python3" (which then fails to run, and
// callers report that plots were not produced).
std::string PythonInterpreter();

}  // namespace conforma
