// Run-time files of the commands (commands.hpp): the data_paths.hpp resolvers, with this build's source folder as
// the last fallback of the share dir (CONFORMA_SOURCE_DIR, a compile definition of the executable only).
#include "commands.hpp"
#include "conforma/data_paths.hpp"

namespace conforma::cli {

std::string PlotScript(const std::string& name) { return ShareDir(CONFORMA_SOURCE_DIR) + "/scripts/" + name; }

std::string DataDirOr(const std::string& given) { return given.empty() ? SharedDataDir() : given; }

std::string PythonOr(const std::string& given) { return given.empty() ? PythonInterpreter() : given; }

}  // namespace conforma::cli
