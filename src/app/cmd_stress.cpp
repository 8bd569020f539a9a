// conforma stress: the numerical stability stress suite (stress.hpp) on N random cases, plus the thread-count
// determinism check (the first M cases with 1 thread and with all threads must hash identically).
#include <omp.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "progress.hpp"
#include "conforma/error.hpp"
#include "conforma/validation/stress.hpp"

namespace conforma::cli {

namespace {

nlohmann::json SummaryJson(const StressSummary& s) {
  char digest[32];
  std::snprintf(digest, sizeof digest, "%016llx", static_cast<unsigned long long>(s.digest));
  return {{"cases", s.cases}, {"wheel_cases", s.wheel_cases}, {"patch_cases", s.patch_cases},
          {"degenerate_cases", s.degenerate_cases}, {"patches", s.patches}, {"non_finite", s.non_finite},
          {"crashes", s.crashes}, {"input_errors", s.input_errors},
          {"unexpected_input_errors", s.unexpected_input_errors}, {"no_contact", s.no_contact},
          {"not_converged", s.not_converged}, {"continuity_pairs", s.continuity_pairs},
          {"continuity_jumps", s.continuity_jumps}, {"continuity_steep_but_continuous", s.continuity_steep},
          {"continuity_violations", s.continuity_violations},
          {"max_continuity_fraction_of_load", s.max_continuity_fraction}, {"digest", digest},
          {"seconds", s.seconds}, {"passed", s.passed()}, {"failures", s.failures}};
}

void Print(const char* label, const StressSummary& s) {
  std::printf("%s: %ld cases (%ld wheel, %ld groove patch, %ld degenerate) in %.1f s; %ld patches; NaN/inf %ld, "
              "crashes %ld, InputError %ld (unexpected %ld), no contact %ld, not converged %ld; continuity pairs %ld "
              "(jumps %ld, steep-but-continuous %ld, violations %ld, max |dF|/load %.2e); digest %016llx -> %s\n",
              label, s.cases, s.wheel_cases, s.patch_cases, s.degenerate_cases, s.seconds, s.patches, s.non_finite,
              s.crashes, s.input_errors, s.unexpected_input_errors, s.no_contact, s.not_converged, s.continuity_pairs,
              s.continuity_jumps, s.continuity_steep, s.continuity_violations, s.max_continuity_fraction,
              static_cast<unsigned long long>(s.digest), s.passed() ? "PASSED" : "FAILED");
  for (const std::string& f : s.failures) std::printf("  %s\n", f.c_str());
}

}  // namespace

void RegisterStressCommand(CLI::App& app) {
  auto options = std::make_shared<StressOptions>();
  auto data = std::make_shared<std::string>();
  auto determinism_cases = std::make_shared<long>(2000);
  auto json_path = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand("stress", "numerical stability stress suite over random contact situations");
  sub->add_option("--cases", options->cases, "number of random cases");
  sub->add_option("--first", options->first_case, "index of the first case");
  sub->add_option("--seed", options->seed, "random seed");
  sub->add_flag("--wheelset", options->wheelset_mode,
                "issue 3's check: both wheels, y +-12 mm, yaw +-25 mrad, 1-150 kN, conformal, new and worn pairs");
  sub->add_option("--threads", options->threads, "OpenMP threads (0 = default)");
  sub->add_option("--continuity-every", options->continuity_every, "every k-th wheel case gets a +1 um twin (0: none)");
  sub->add_option("--determinism-cases", *determinism_cases, "cases rerun with 1 and with all threads (0: skip)");
  sub->add_option("--data", *data, kDataHelp);
  sub->add_option("--json", *json_path, "write the summary as JSON to this file");
  sub->callback([=]() {
    if (options->cases < 1) throw InputError("option --cases: must be >= 1 (got " + std::to_string(options->cases) + ")");
    constexpr long kMaxStressCases = 1000000;  // (2e9 cases: std::bad_alloc)
    if (options->cases > kMaxStressCases || *determinism_cases > kMaxStressCases)
      throw InputError("option --cases / --determinism-cases: at most " + std::to_string(kMaxStressCases) +
                       " cases per run (run batches with --first)");
    RequireThreads(options->threads, "--threads");
    if (!json_path->empty()) EnsureWritableFile(*json_path, "--json");
    if (*determinism_cases < 0) throw InputError("option --determinism-cases: must be >= 0");
    const StressSetup setup = StressSetup::Make(DataDirOr(*data));
    const ProgressMode mode = ProgressModeOf(sub);
    // one reporter per run; its Options copy carries the reporter's function
    auto run = [&](const std::string& label, StressOptions run_options) {
      std::fflush(stdout);
      ProgressReporter progress(label, static_cast<double>(run_options.cases), "", mode, std::cerr);
      run_options.on_progress = progress.Function();
      StressSummary summary = RunStress(setup, run_options);
      progress.Finish();
      return summary;
    };
    const StressSummary s = run("stress", *options);
    Print("stress", s);
    nlohmann::json j = {{"run", SummaryJson(s)}, {"threads", options->threads > 0 ? options->threads : omp_get_max_threads()}};
    bool ok = s.passed();
    if (*determinism_cases > 0) {
      StressOptions d = *options;
      d.cases = std::min(*determinism_cases, options->cases > 0 ? options->cases : *determinism_cases);
      d.threads = 1;
      const StressSummary one = run("stress determinism, 1 thread", d);
      d.threads = std::max(2, omp_get_max_threads());
      const StressSummary many = run("stress determinism, " + std::to_string(d.threads) + " threads", d);
      const bool same = one.digest == many.digest;
      std::printf("determinism: %ld cases with 1 thread (%.1f s) and %d threads (%.1f s): digests %016llx / %016llx -> %s\n",
                  d.cases, one.seconds, d.threads, many.seconds, static_cast<unsigned long long>(one.digest),
                  static_cast<unsigned long long>(many.digest), same ? "identical" : "DIFFERENT");
      j["determinism"] = {{"cases", d.cases}, {"threads", d.threads}, {"identical", same},
                          {"digest_1_thread", SummaryJson(one)["digest"]}, {"digest_n_threads", SummaryJson(many)["digest"]}};
      ok = ok && same;
    }
    if (!json_path->empty()) {
      std::ofstream out(*json_path);
      if (!(out << j.dump(2) << "\n")) throw InputError("option --json: cannot write '" + *json_path + "'");
    }
    if (!ok) throw std::runtime_error("stress suite failed");
  });
}

}  // namespace conforma::cli
