// conforma bench: run time against error for every model and grid over the fixed case set (benchmark_cases.hpp);
// writes DIR/bench.csv, DIR/bench_summary.json and the Pareto plot DIR/bench_pareto.png (scripts/plot_bench.py).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/error.hpp"

namespace conforma::cli {

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

void RegisterBenchCommand(CLI::App& app) {
  auto out_dir = std::make_shared<std::string>("bench_out");
  auto data = std::make_shared<std::string>();
  auto models = std::make_shared<std::string>("hertz,kp,kpec,conformal,auto");
  auto families = std::make_shared<std::string>("mbench,groove,worn,flange_root");
  auto plot = std::make_shared<bool>(true);
  auto default_grid = std::make_shared<std::string>("s31e30");
  CLI::App* sub = app.add_subcommand("bench", "run time against error per model and grid (bench.csv, Pareto plot)");
  sub->add_option("--out", *out_dir, "output folder");
  sub->add_option("--data", *data, kDataHelp);
  sub->add_option("--models", *models, "comma-separated models");
  sub->add_option("--families", *families, "comma-separated case families");
  sub->add_option("--default-grid", *default_grid, "grid label of the models' default resolution (summary)");
  sub->add_flag("!--no-plot", *plot, "do not run scripts/plot_bench.py");
  sub->callback([=]() {
    BenchOptions options;
    options.models.clear();
    std::stringstream ms(*models);
    for (std::string name; std::getline(ms, name, ',');)
      if (!name.empty()) options.models.push_back(ParseContactModel(name));
    if (options.models.empty()) throw InputError("option --models: no contact model given");
    EnsureOutputFolder(*out_dir, "--out");
    const std::vector<BenchCase> all_cases = MakeBenchCases(DataDirOr(*data));
    std::vector<std::string> known;  // the families of the case set, in order
    for (const BenchCase& c : all_cases)
      if (std::find(known.begin(), known.end(), c.family) == known.end()) known.push_back(c.family);
    std::vector<std::string> wanted;
    std::stringstream fs(*families);
    for (std::string f; std::getline(fs, f, ',');) {
      if (f.empty()) continue;
      if (std::find(known.begin(), known.end(), f) == known.end()) {
        std::string list;
        for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
        throw InputError("option --families: unknown case family '" + f + "' (known: " + list + ")");
      }
      wanted.push_back(f);
    }
    if (wanted.empty()) throw InputError("option --families: no case family given");
    std::vector<BenchCase> cases;
    for (const BenchCase& c : all_cases)
      if (std::find(wanted.begin(), wanted.end(), c.family) != wanted.end()) cases.push_back(c);
    std::printf("bench: %zu patches, %zu models x %zu grids\n", cases.size(), options.models.size(), options.grids.size());
    const std::vector<BenchRow> rows = RunBench(cases, options);

    const std::string csv = *out_dir + "/bench.csv";
    std::ofstream f(csv);
    if (!f) throw InputError("bench: cannot write " + csv);
    f << "model,grid,case,time_us,err_pmax,err_area,err_fx,err_fy,err_wear,err_fn,family,alpha_c_deg,time_approach_us,time_normal_us,status\n";
    for (const BenchRow& r : rows) {
      char line[512];
      std::snprintf(line, sizeof line, "%s,%s,%s,%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%s,%.3f,%.3f,%.3f,%s\n", r.model.c_str(),
                    r.grid.c_str(), r.case_name.c_str(), r.time_us, r.err_pmax, r.err_area, r.err_fx, r.err_fy,
                    r.err_wear, r.err_fn, r.family.c_str(), r.alpha_c_deg, r.time_approach_us, r.time_normal_us,
                    r.status.c_str());
      f << line;
    }
    f.close();

    // Summary per model and grid: median time, max |error| over the cases.
    nlohmann::json summary;
    std::printf("\n%-14s %-7s %9s %9s %9s %9s %9s %9s %9s %9s %9s\n", "model", "grid", "t_med_us", "t_max_us", "t_appr_us", "t_norm_us", "|pmax|max",
                "|area|max", "|fn|max", "|Ft|max", "|wear|max");
    std::map<std::string, double> median_time_default;
    std::vector<std::string> names;
    for (ContactModel m : options.models) names.push_back(to_string(m));
    if (options.conformal_eps055) names.push_back("conformal_eps055");
    for (const std::string& name : names) {
      for (const BenchGrid& g : options.grids) {
        std::vector<double> t, ta, tn;
        double ep = 0, ea = 0, en = 0, ef = 0, ew = 0;
        std::string worst_case;
        for (const BenchRow& r : rows) {
          if (r.model != name || r.grid != g.label()) continue;
          t.push_back(r.time_us);
          ta.push_back(r.time_approach_us);
          tn.push_back(r.time_normal_us);
          if (std::fabs(r.err_pmax) > ep) ep = std::fabs(r.err_pmax), worst_case = r.case_name;
          ea = std::max(ea, std::fabs(r.err_area));
          en = std::max(en, std::fabs(r.err_fn));
          ef = std::max({ef, std::fabs(r.err_fx), std::fabs(r.err_fy)});
          ew = std::max(ew, std::fabs(r.err_wear));
        }
        const double tmax = t.empty() ? 0.0 : *std::max_element(t.begin(), t.end());
        std::printf("%-14s %-7s %9.1f %9.1f %9.1f %9.1f %8.1f%% %8.1f%% %8.1f%% %8.1f%% %8.1f%%  (worst pmax: %s)\n",
                    name.c_str(), g.label().c_str(), Median(t), tmax, Median(ta), Median(tn), 100 * ep, 100 * ea, 100 * en, 100 * ef, 100 * ew,
                    worst_case.c_str());
        summary["models"][name][g.label()] = {{"median_time_us", Median(t)}, {"max_time_us", tmax},
                                               {"median_time_approach_given_us", Median(ta)},
                                               {"median_time_normal_approach_given_us", Median(tn)},
                                                       {"max_abs_err_pmax", ep}, {"worst_pmax_case", worst_case},
                                                       {"max_abs_err_area", ea}, {"max_abs_err_fn", en},
                                                       {"max_abs_err_ft", ef}, {"max_abs_err_wear", ew}};
        if (g.label() == *default_grid) median_time_default[name] = Median(t);
      }
    }
    summary["cases"] = cases.size();
    summary["default_grid"] = *default_grid;
    if (median_time_default.count("conformal") && median_time_default.count("hertz") && median_time_default["hertz"] > 0) {
      const double ratio = median_time_default["conformal"] / median_time_default["hertz"];
      summary["conformal_over_hertz_time_ratio"] = ratio;
      std::printf("\nconformal / hertz median time at %s: %.2f\n", default_grid->c_str(), ratio);
    }
    std::ofstream(*out_dir + "/bench_summary.json") << summary.dump(2) << "\n";
    std::printf("wrote %s and %s/bench_summary.json\n", csv.c_str(), out_dir->c_str());
    std::fflush(stdout);  // before the plot script's own output
    if (*plot) {
      const std::string cmd = PythonOr("") + " '" + PlotScript("plot_bench.py") + "' '" + csv + "' '" + *out_dir +
                              "/bench_pareto.png'";
      if (std::system(cmd.c_str()) != 0)
        throw IncompleteResult(ExitCode::PartialResult, "bench: the Pareto plot was not produced (" + cmd + ")");
    }
  });
}

}  // namespace conforma::cli
