#pragma once
// Runs the conforma executable (CONFORMA_CLI, set by CMake for every test) and captures its exit code, stdout and
// stderr, for tests of the command line as a user sees it (exit codes, messages, output files).
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace conforma::test {

// The whole content of a file ("" when it cannot be read).
inline std::string Slurp(const std::filesystem::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

struct CliRun {
  int exit_code = -1;  // the process's exit status; -1 when it did not exit normally (signal)
  std::string out, err;
};

// args: the shell-quoted arguments after the executable, e.g. "contact --wheel S1002 --json".
inline CliRun RunCli(const std::string& args) {
  namespace fs = std::filesystem;
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() /
                       ("conforma_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  fs::create_directories(dir);
  const std::string out_file = (dir / "out").string(), err_file = (dir / "err").string();
  const std::string cmd = std::string("\"") + CONFORMA_CLI + "\" " + args + " >\"" + out_file + "\" 2>\"" +
                          err_file + "\"";
  const int status = std::system(cmd.c_str());
  CliRun run;
  run.exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  run.out = Slurp(out_file);
  run.err = Slurp(err_file);
  fs::remove_all(dir);
  return run;
}

// A fresh, empty temporary folder named after the test file's prefix, the process and the name.
inline std::filesystem::path FreshTempDir(const std::string& prefix, const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path d = fs::temp_directory_path() / (prefix + "_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// The shared reference data folder (CONFORMA_SHARED_DATA), for test-bank profiles.
inline std::string SharedData(const std::string& relative) {
  return std::string(CONFORMA_SHARED_DATA) + "/" + relative;
}

}  // namespace conforma::test
