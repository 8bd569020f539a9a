// conforma bench: run time against error for every model and grid over the fixed case set against the exact model
// (benchmark_cases.hpp); writes DIR/bench.csv (one row per model x grid x case), DIR/bench_reference.csv (the exact
// reference of every case: status, iterations, time), DIR/bench_creep_errors.{csv,md} (worst creep-force errors per
// model and case family), DIR/bench_summary.json and the Pareto plot DIR/bench_pareto.png (scripts/plot_bench.py).
// A reference that did not converge is marked in every output and makes the command exit 4 (exit_status.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "progress.hpp"
#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/error.hpp"

namespace conforma::cli {

namespace {

double Median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// The case families of the creep-force summary, with the name it reports them by.
const std::vector<std::pair<std::string, std::string>> kCreepFamilies = {
    {"mbench", "tread"},  {"flange_root", "flange_root"},   {"groove", "groove"},
    {"worn", "worn"},     {"flange", "flange"}, {"gauge_corner", "gauge_corner"}};
// The fast models of the creep-force summary.
const std::vector<std::string> kCreepModels = {"hertz", "kpec", "conformal"};

struct WorstCreep {
  double fx = 0.0, fy = 0.0;  // max |err_fx|, max |err_fy|
  std::string fx_case, fy_case;
  int rows = 0;
};

// Worst |err_fx|, |err_fy| of `model` over the rows of `family` (all grids when grid is empty) whose reference
// converged.
WorstCreep WorstCreepError(const std::vector<BenchRow>& rows, const std::string& model, const std::string& family,
                           const std::string& grid) {
  WorstCreep w;
  for (const BenchRow& r : rows) {
    if (r.model != model || r.family != family || (!grid.empty() && r.grid != grid)) continue;
    if (r.reference_status != "converged") continue;
    ++w.rows;
    if (std::fabs(r.err_fx) >= w.fx) w.fx = std::fabs(r.err_fx), w.fx_case = r.case_name + "@" + r.grid;
    if (std::fabs(r.err_fy) >= w.fy) w.fy = std::fabs(r.err_fy), w.fy_case = r.case_name + "@" + r.grid;
  }
  return w;
}

// bench_creep_errors.csv / .md and the same table on stdout.
void WriteCreepSummary(const std::vector<BenchRow>& rows, const std::string& out_dir, const std::string& default_grid,
                       nlohmann::json& summary) {
  std::ofstream csv(out_dir + "/bench_creep_errors.csv");
  std::ofstream md(out_dir + "/bench_creep_errors.md");
  if (!csv || !md) throw InputError("bench: cannot write " + out_dir + "/bench_creep_errors.{csv,md}");
  csv << "model,family,grids,rows,max_abs_err_fx,worst_fx_case,max_abs_err_fy,worst_fy_case\n";
  md << "Worst creep-force errors against the exact reference (|F - F_exact| / |F_t,exact|), rows with a converged "
        "reference\n\n"
     << "| model | family | max \\|err_fx\\| at " << default_grid << " | max \\|err_fy\\| at " << default_grid
     << " | max \\|err_fx\\| all grids | max \\|err_fy\\| all grids | worst fx / fy (all grids) |\n"
     << "|---|---|---|---|---|---|---|\n";
  std::printf("\nworst creep-force errors vs exact (|dF| / |F_t,exact|; case@grid of the worst)\n");
  std::printf("%-10s %-7s %8s %8s %8s %8s  %s\n", "model", "family", "fx@def", "fy@def", "fx@all", "fy@all",
              "worst fx (all) / worst fy (all)");
  for (const std::string& model : kCreepModels) {
    for (const auto& [family, label] : kCreepFamilies) {
      const WorstCreep d = WorstCreepError(rows, model, family, default_grid);
      const WorstCreep a = WorstCreepError(rows, model, family, "");
      if (a.rows == 0) continue;  // model or family not run
      char line[512];
      std::snprintf(line, sizeof line, "%s,%s,%s,%d,%.6f,%s,%.6f,%s\n", model.c_str(), label.c_str(),
                    default_grid.c_str(), d.rows, d.fx, d.fx_case.c_str(), d.fy, d.fy_case.c_str());
      csv << line;
      std::snprintf(line, sizeof line, "%s,%s,all,%d,%.6f,%s,%.6f,%s\n", model.c_str(), label.c_str(), a.rows, a.fx,
                    a.fx_case.c_str(), a.fy, a.fy_case.c_str());
      csv << line;
      std::snprintf(line, sizeof line, "| %s | %s | %.1f %% | %.1f %% | %.1f %% | %.1f %% | %s / %s |\n", model.c_str(),
                    label.c_str(), 100 * d.fx, 100 * d.fy, 100 * a.fx, 100 * a.fy, a.fx_case.c_str(),
                    a.fy_case.c_str());
      md << line;
      std::printf("%-10s %-7s %7.1f%% %7.1f%% %7.1f%% %7.1f%%  %s / %s\n", model.c_str(), label.c_str(), 100 * d.fx,
                  100 * d.fy, 100 * a.fx, 100 * a.fy, a.fx_case.c_str(), a.fy_case.c_str());
      summary["creep_errors"][model][label] = {{"max_abs_err_fx_default_grid", d.fx},
                                               {"max_abs_err_fy_default_grid", d.fy},
                                               {"max_abs_err_fx_all_grids", a.fx},
                                               {"max_abs_err_fy_all_grids", a.fy}};
    }
  }
}

// bench_reference.csv, a per-family summary on stdout and in the JSON; returns the cases whose reference did not
// converge ("case: status; ...").
std::string WriteReferences(const std::vector<BenchCase>& cases, const std::vector<BenchReference>& refs,
                            const std::string& out_dir, nlohmann::json& summary) {
  const std::string path = out_dir + "/bench_reference.csv";
  std::ofstream f(path);
  if (!f) throw InputError("bench: cannot write " + path);
  f << "case,family,status,normal_status,tangential_status,fn_N,approach_m,pmax_Pa,area_m2,alpha_c_deg,bem_nx,bem_ns,"
       "bem_edge,load_iterations,fx_N,fy_N,wear_index_N,tangential_iterations,tangential_residual,time_s\n";
  std::string failed;
  std::map<std::string, std::vector<double>> times;
  std::map<std::string, int> converged;
  std::vector<std::string> families;
  for (size_t k = 0; k < cases.size(); ++k) {
    const BenchCase& c = cases[k];
    const BenchReference& r = refs[k];
    char line[768];
    std::snprintf(line, sizeof line,
                  "%s,%s,%s,%s,%s,%.6g,%.6e,%.6e,%.6e,%.3f,%d,%d,%d,%d,%.6g,%.6g,%.6g,%d,%.3e,%.3f\n", c.name.c_str(),
                  c.family.c_str(), r.status().c_str(), r.normal_status.c_str(), r.tangential_status.c_str(), r.fn_N,
                  r.approach_m, r.pmax_Pa, r.area_m2, r.alpha_c_deg, r.bem_nx, r.bem_ns, r.contact_at_grid_edge ? 1 : 0,
                  r.load_iterations, r.fx_N, r.fy_N, r.wear_index_N, r.tangential_iterations, r.tangential_residual,
                  r.time_s);
    f << line;
    if (!r.converged) failed += (failed.empty() ? "" : "; ") + c.name + ": " + r.status();
    if (!times.count(c.family)) families.push_back(c.family);
    times[c.family].push_back(r.time_s);
    converged[c.family] += r.converged;
  }
  std::printf("\nexact reference per family (one solve per case, load given; %s)\n", path.c_str());
  std::printf("%-12s %5s %9s %9s %9s %9s\n", "family", "cases", "converged", "total_s", "median_s", "max_s");
  for (const std::string& fam : families) {
    const std::vector<double>& t = times[fam];
    double total = 0.0;
    for (double x : t) total += x;
    const double tmax = *std::max_element(t.begin(), t.end());
    std::printf("%-12s %5zu %9d %9.2f %9.2f %9.2f\n", fam.c_str(), t.size(), converged[fam], total, Median(t), tmax);
    summary["reference"][fam] = {{"cases", t.size()}, {"converged", converged[fam]}, {"total_time_s", total},
                                 {"median_time_s", Median(t)}, {"max_time_s", tmax}};
  }
  if (!failed.empty()) std::printf("WARNING: exact reference not converged: %s\n", failed.c_str());
  return failed;
}

}  // namespace

void RegisterBenchCommand(CLI::App& app) {
  auto out_dir = std::make_shared<std::string>("bench_out");
  auto data = std::make_shared<std::string>();
  auto models = std::make_shared<std::string>("hertz,kp,kpec,conformal,auto");
  auto families = std::make_shared<std::string>("mbench,groove,worn,flange_root,flange,gauge_corner");
  auto plot = std::make_shared<bool>(true);
  auto default_grid = std::make_shared<std::string>("s31e30");
  auto spin_centre = std::make_shared<bool>(false);
  auto local_flex = std::make_shared<bool>(false);
  auto creepage_scale = std::make_shared<double>(1.0);
  CLI::App* sub = app.add_subcommand("bench", "run time against error per model and grid (bench.csv, Pareto plot)");
  sub->add_option("--out", *out_dir, "output folder");
  sub->add_option("--data", *data, kDataHelp);
  sub->add_option("--models", *models, "comma-separated models");
  sub->add_option("--families", *families, "comma-separated case families");
  sub->add_option("--default-grid", *default_grid, "grid label of the models' default resolution (summary)");
  sub->add_flag("!--no-plot", *plot, "do not run scripts/plot_bench.py");
  AddKpFastsimFlags(sub, spin_centre.get(), local_flex.get());
  sub->add_option("--creepage-scale", *creepage_scale,
                  "every case's creepages (xi, eta, phi) times this factor, for the models and the exact reference; "
                  "e.g. 0.01 probes the linear range (docs/physics-reference.md §5.4)");
  sub->callback([=]() {
    BenchOptions options;
    options.kp_spin_about_patch_centre = *spin_centre;
    options.kp_local_flexibilities = *local_flex;
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
    require_positive(*creepage_scale, "--creepage-scale");
    if (*creepage_scale > 1e3)  // (1e300 wrote 168 NaN rows while the summary said 0.0 %: fuzzing, session 25)
      throw InputError("option --creepage-scale must be at most 1000 (the cases' creepages x 1000 are in full slip)");
    std::vector<BenchCase> cases;
    for (const BenchCase& c : all_cases)
      if (std::find(wanted.begin(), wanted.end(), c.family) != wanted.end()) cases.push_back(c);
    for (BenchCase& c : cases) {  // the same rigid slip field scaled: creepages and spin alike
      c.creepages.xi *= *creepage_scale;
      c.creepages.eta *= *creepage_scale;
      c.creepages.phi_per_m *= *creepage_scale;
    }
    std::printf("bench: %zu patches, %zu models x %zu grids\n", cases.size(), options.models.size(), options.grids.size());
    std::fflush(stdout);  // before the progress lines on stderr
    std::vector<BenchReference> refs;
    // two units per case: the exact references (in parallel), then the timed models case by case
    ProgressReporter progress("bench", 2.0 * cases.size(), "", ProgressModeOf(sub), std::cerr);
    options.on_progress = progress.Function();
    const std::vector<BenchRow> rows = RunBench(cases, options, &refs);
    progress.Finish();

    const std::string csv = *out_dir + "/bench.csv";
    std::ofstream f(csv);
    if (!f) throw InputError("bench: cannot write " + csv);
    f << "model,grid,case,time_us,err_pmax,err_area,err_fx,err_fy,err_wear,err_fn,family,alpha_c_deg,time_approach_us,"
         "time_normal_us,status,reference_status\n";
    for (const BenchRow& r : rows) {
      char line[512];
      std::snprintf(line, sizeof line, "%s,%s,%s,%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%s,%.3f,%.3f,%.3f,%s,%s\n",
                    r.model.c_str(), r.grid.c_str(), r.case_name.c_str(), r.time_us, r.err_pmax, r.err_area, r.err_fx,
                    r.err_fy, r.err_wear, r.err_fn, r.family.c_str(), r.alpha_c_deg, r.time_approach_us,
                    r.time_normal_us, r.status.c_str(), r.reference_status.c_str());
      f << line;
    }
    f.close();
    nlohmann::json summary;
    const std::string failed_references = WriteReferences(cases, refs, *out_dir, summary);

    // Summary per model and grid: median time, max |error| over the cases whose reference converged.
    std::printf("\nerrors vs exact (max over the cases whose reference converged)\n");
    std::printf("%-16s %-7s %9s %9s %9s %9s %9s %9s %9s %9s %9s %9s\n", "model", "grid", "t_med_us", "t_max_us",
                "t_appr_us", "t_norm_us", "|pmax|max", "|area|max", "|fn|max", "|fx|max", "|fy|max", "|wear|max");
    std::map<std::string, double> median_time_default;
    std::vector<std::string> names;
    for (ContactModel m : options.models) names.push_back(to_string(m));
    if (options.conformal_eps055) names.push_back("conformal_eps055");
    for (const std::string& name : names) {
      for (const BenchGrid& g : options.grids) {
        std::vector<double> t, ta, tn;
        double ep = 0, ea = 0, en = 0, efx = 0, efy = 0, ew = 0;
        std::string worst_case;
        for (const BenchRow& r : rows) {
          if (r.model != name || r.grid != g.label()) continue;
          t.push_back(r.time_us);
          ta.push_back(r.time_approach_us);
          tn.push_back(r.time_normal_us);
          if (r.reference_status != "converged") continue;
          if (std::fabs(r.err_pmax) > ep) ep = std::fabs(r.err_pmax), worst_case = r.case_name;
          ea = std::max(ea, std::fabs(r.err_area));
          en = std::max(en, std::fabs(r.err_fn));
          efx = std::max(efx, std::fabs(r.err_fx));
          efy = std::max(efy, std::fabs(r.err_fy));
          ew = std::max(ew, std::fabs(r.err_wear));
        }
        const double tmax = t.empty() ? 0.0 : *std::max_element(t.begin(), t.end());
        std::printf("%-16s %-7s %9.1f %9.1f %9.1f %9.1f %8.1f%% %8.1f%% %8.1f%% %8.1f%% %8.1f%% %8.1f%%  (worst pmax: %s)\n",
                    name.c_str(), g.label().c_str(), Median(t), tmax, Median(ta), Median(tn), 100 * ep, 100 * ea,
                    100 * en, 100 * efx, 100 * efy, 100 * ew, worst_case.c_str());
        summary["models"][name][g.label()] = {{"median_time_us", Median(t)}, {"max_time_us", tmax},
                                               {"median_time_approach_given_us", Median(ta)},
                                               {"median_time_normal_approach_given_us", Median(tn)},
                                                       {"max_abs_err_pmax", ep}, {"worst_pmax_case", worst_case},
                                                       {"max_abs_err_area", ea}, {"max_abs_err_fn", en},
                                                       {"max_abs_err_fx", efx}, {"max_abs_err_fy", efy},
                                                       {"max_abs_err_wear", ew}};
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
    WriteCreepSummary(rows, *out_dir, *default_grid, summary);
    summary["references_not_converged"] = failed_references;
    std::ofstream(*out_dir + "/bench_summary.json") << summary.dump(2) << "\n";
    std::printf("wrote %s, bench_reference.csv, bench_creep_errors.{csv,md} and bench_summary.json in %s\n",
                csv.c_str(), out_dir->c_str());
    std::fflush(stdout);  // before the plot script's own output
    if (*plot) {
      const std::string cmd = PythonOr("") + " '" + PlotScript("plot_bench.py") + "' '" + csv + "' '" + *out_dir +
                              "/bench_pareto.png'";
      if (std::system(cmd.c_str()) != 0) {
        if (!failed_references.empty())
          throw IncompleteResult(ExitCode::NotConverged, "bench: exact reference not converged (" +
                                                             failed_references + "); the Pareto plot was not produced");
        throw IncompleteResult(ExitCode::PartialResult, "bench: the Pareto plot was not produced (" + cmd + ")");
      }
    }
    if (!failed_references.empty())
      throw IncompleteResult(ExitCode::NotConverged, "bench: exact reference not converged: " + failed_references +
                                                         " (their rows carry reference_status)");
  });
}

}  // namespace conforma::cli
