// conforma campaign run FILE --out DIR [--scheduler ADDR] [--workers N] [--retry-failed]
// conforma campaign report DIR
// conforma campaign check SCENARIO...
// Campaigns (many wear / compare / validate runs of generated scenarios, issue 19) are driven by the Python module
// conforma.campaign (python/conforma/campaign.py): `run` and `report` exec the Python interpreter on
// python/conforma/_campaign_main.py of the share dir, which needs neither the compiled extension conforma._core nor an
// installed package, and hand it this executable (--cli) to run the cases with. `check` is what that runner calls
// before any case runs: every generated scenario through this build's scenario reader (unknown keys, bad values).
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "conforma/data_paths.hpp"
#include "conforma/error.hpp"
#include "conforma/scenario.hpp"
#include "exit_status.hpp"

namespace conforma::cli {

namespace {

std::string CampaignScript() {
  const std::string script = ShareDir(CONFORMA_SOURCE_DIR) + "/python/conforma/_campaign_main.py";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(script, ec))
    throw InputError("conforma campaign: the campaign module is missing (" + script +
                     "; set $CONFORMA_SHARE_DIR to the folder that holds python/conforma/)");
  return script;
}

std::string SelfExecutable() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("conforma") : exe.string();
}

// Replaces this process by `python _campaign_main.py args... --cli <this executable>` (returns only on failure).
[[noreturn]] void ExecCampaignModule(const std::string& python, std::vector<std::string> args) {
  // the interpreter is checked first: after the exec its failure is the command's (--python /bin/false exited 1
  // without a word: fuzzing, session 25)
  const std::string probe = "'" + python + "' -c 'import yaml' >/dev/null 2>&1";
  if (std::system(probe.c_str()) != 0)
    throw InputError("conforma campaign: '" + python + "' cannot import yaml (is it a Python interpreter with PyYAML? "
                     "--python or $CONFORMA_PYTHON names one)");
  args.insert(args.begin(), {python, CampaignScript()});
  args.insert(args.end(), {"--cli", SelfExecutable()});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  std::cerr.flush();
  ::execvp(argv[0], argv.data());
  throw InputError("conforma campaign: cannot run the Python interpreter '" + python + "' (" + std::strerror(errno) +
                   "; --python or $CONFORMA_PYTHON names one with PyYAML, matplotlib and, for Dask, python3-distributed)");
}

}  // namespace

void RegisterCampaignCommand(CLI::App& app) {
  CLI::App* campaign = app.add_subcommand("campaign", "many wear / compare / validate runs of generated scenarios");
  campaign->require_subcommand(1);

  struct RunArgs {
    std::string file, out, scheduler, python;
    int workers = 0;
    bool retry_failed = false;
  };
  auto r = std::make_shared<RunArgs>();
  CLI::App* run = campaign->add_subcommand("run", "run every case of a campaign file (skips the complete ones)");
  run->add_option("file", r->file, "campaign file (YAML; README.md \"Campaigns\")")->required();
  run->add_option("--out", r->out, "campaign folder: results.csv and cases/<case id>/")->required();
  run->add_option("--scheduler", r->scheduler,
                  "where the cases run: 'local' (process pool, the default), 'serial' (one after the other), "
                  "'dask-local' (a Dask LocalCluster on 127.0.0.1) or the address of a Dask scheduler "
                  "(tcp://host:8786)");
  run->add_option("--workers", r->workers, "parallel cases (local pool, dask-local); 0: the number of CPUs");
  run->add_flag("--retry-failed", r->retry_failed, "run the cases that failed before again");
  run->add_option("--python", r->python, "python interpreter with PyYAML (default: $CONFORMA_PYTHON, else python3 on PATH)");
  run->callback([r]() {
    if (r->workers < 0) throw InputError("option --workers must be >= 0 (0: the number of CPUs)");
    std::vector<std::string> args{"run", r->file, "--out", r->out};
    if (!r->scheduler.empty()) args.insert(args.end(), {"--scheduler", r->scheduler});
    if (r->workers > 0) args.insert(args.end(), {"--workers", std::to_string(r->workers)});
    if (r->retry_failed) args.push_back("--retry-failed");
    ExecCampaignModule(PythonOr(r->python), args);
  });

  struct ReportArgs {
    std::string dir, python;
  };
  auto p = std::make_shared<ReportArgs>();
  CLI::App* report = campaign->add_subcommand("report", "summary (report.md) and plots of a campaign folder");
  report->add_option("dir", p->dir, "campaign folder (conforma campaign run --out)")->required();
  report->add_option("--python", p->python, kPythonHelp);
  report->callback([p]() { ExecCampaignModule(PythonOr(p->python), {"report", p->dir}); });

  auto files = std::make_shared<std::vector<std::string>>();
  auto models = std::make_shared<std::string>();
  CLI::App* check = campaign->add_subcommand("check", "validate scenario files with the scenario reader (what the "
                                                      "campaign runner does before any case runs)");
  check->add_option("scenarios", *files, "scenario YAML files")->required();
  check->add_option("--models", *models, "the campaign's models, comma-separated: checked as the wear command's");
  check->callback([files, models]() {
    int bad = 0;
    if (!models->empty()) {
      try {
        ParseWearModelList(*models, "--models");
      } catch (const InputError& e) {
        std::cout << "--models\t" << e.what() << "\n";
        ++bad;
      }
    }
    for (const std::string& f : *files) {
      try {
        LoadScenario(f);
      } catch (const InputError& e) {
        std::cout << f << "\t" << e.what() << "\n";
        ++bad;
      }
    }
    if (bad > 0)
      throw InputError(std::to_string(bad) + " of " + std::to_string(files->size()) + " scenarios" +
                       (models->empty() ? "" : " and the model list") + " rejected");
  });
}

}  // namespace conforma::cli
