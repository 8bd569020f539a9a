// conforma threshold: conformal against planar over situation sweeps, the fitted conformity-index threshold
// (threshold.hpp); writes DIR/threshold.csv, DIR/threshold.json (threshold_deg) and DIR/threshold.png.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "cli_setup.hpp"
#include "commands.hpp"
#include "conforma/wheel_contact.hpp"
#include "conforma/error.hpp"
#include "exit_status.hpp"
#include "progress.hpp"
#include "conforma/validation/threshold.hpp"

namespace conforma::cli {

namespace {

// a free-text field of threshold.csv (an error message) without the separator
std::string CsvField(std::string text) {
  for (char& ch : text)
    if (ch == ',' || ch == '\n') ch = ';';
  return text;
}

nlohmann::json FitJson(const std::vector<ThresholdPoint>& points, double tolerance) {
  const ThresholdFit f = FitConformityThreshold(points, tolerance);
  auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json j = {{"threshold_deg", finite(f.threshold_deg)}, {"bracket_low_deg", f.bracket_low_deg},
                      {"misclassified", f.misclassified}, {"points", f.points}, {"exceeding", f.exceeding},
                      {"power_law_c", f.power_c}, {"power_law_k", f.power_k}, {"power_law_r2", f.power_r2},
                      {"power_law_threshold_deg", f.power_threshold_deg}};
  using Getter = double (*)(const ThresholdPoint&);
  const std::pair<const char*, Getter> metrics[] = {
      {"pmax", [](const ThresholdPoint& p) { return p.d_pmax; }},
      {"area", [](const ThresholdPoint& p) { return p.d_area; }},
      {"creep_force", [](const ThresholdPoint& p) { return p.d_creep; }},
      {"wear_index", [](const ThresholdPoint& p) { return p.d_wear; }}};
  for (const auto& [name, get] : metrics) {
    const ThresholdFit m = FitConformityThreshold(points, tolerance, get);
    j["per_metric"][name] = {{"threshold_deg", finite(m.threshold_deg)}, {"misclassified", m.misclassified},
                             {"exceeding", m.exceeding}};
  }
  double amax = 0.0;
  for (const ThresholdPoint& p : points)
    if (p.valid) amax = std::max(amax, p.alpha_c_deg);
  j["max_alpha_c_deg"] = amax;
  return j;
}

}  // namespace

void RegisterThresholdCommand(CLI::App& app) {
  auto out_dir = std::make_shared<std::string>("threshold_out");
  auto data = std::make_shared<std::string>();
  auto sets = std::make_shared<std::string>("new,worn,groove");
  auto against = std::make_shared<std::string>("flat_kp");
  auto reference = std::make_shared<std::string>("conformal");
  auto tolerance = std::make_shared<double>(0.05);
  auto load = std::make_shared<double>(10e3);
  auto worn_load = std::make_shared<double>(137e3);
  auto strips = std::make_shared<int>(kDefaultKpStrips);
  auto elements = std::make_shared<int>(30);
  auto variable_eps = std::make_shared<bool>(false);
  auto plot = std::make_shared<bool>(true);
  CLI::App* sub = app.add_subcommand("threshold", "conformity-index threshold: conformal vs planar over sweeps");
  sub->add_option("--out", *out_dir, "output folder");
  sub->add_option("--data", *data, kDataHelp);
  sub->add_option("--sets", *sets, "comma-separated situation sets: new (S1002/60E1 1:20), worn, groove");
  sub->add_option("--against", *against, "planar comparison: flat_kp (planar KP on the flattened patch), kp (curvilinear KP), hertz");
  sub->add_option("--reference", *reference,
                  "measured against: conformal (the conformal model, default) or exact (the exact solver: slow)");
  sub->add_option("--tolerance", *tolerance, "relative difference that counts as significant");
  sub->add_option("--load-N", *load, "vertical load per wheel (sets new and groove)");
  sub->add_option("--worn-load-N", *worn_load, "vertical load per wheel of the worn heavy-haul set");
  sub->add_option("--kp-strips", *strips, "KP strips across the contact");
  sub->add_option("--fastsim-elements", *elements, "FASTSIM elements per strip");
  sub->add_flag("!--no-plot", *plot, "do not run scripts/plot_threshold.py");
  sub->add_flag("--variable-penetration", *variable_eps,
                "compare with KPEC's variable eps on both sides (default: eps = 0.55, paper 003's formulation)");
  sub->callback([=]() {
    // the lists and sizes up front (an empty --sets computed nothing with exit 0; --kp-strips 1e8 failed row by row)
    const std::vector<std::string> set_names = SplitCommaList(*sets, "--sets");
    if (set_names.empty()) throw InputError("option --sets: no situation set given (new, worn, groove)");
    for (const std::string& set : set_names)
      if (set != "new" && set != "worn" && set != "groove")
        throw InputError("option --sets: unknown situation set '" + set + "' (new, worn, groove)");
    if (*strips < 3 || *strips > kMaxKpStrips)
      throw InputError("option --kp-strips must lie in [3, " + std::to_string(kMaxKpStrips) + "]");
    if (*elements < 2 || *elements > kMaxFastsimElements)
      throw InputError("option --fastsim-elements must lie in [2, " + std::to_string(kMaxFastsimElements) + "]");
    ThresholdOptions options;
    options.tolerance = *tolerance;
    options.kp_strips = *strips;
    options.variable_epsilon = *variable_eps;
    options.fastsim_elements = *elements;
    options.against = ParsePlanarComparison(*against);
    options.reference = ParseThresholdReference(*reference);
    require_positive(*load, "--load-N");
    require_positive(*worn_load, "--worn-load-N");
    RequireWheelLoad(*load, "option --load-N");  // (1e12 N gave a threshold of 98.6 deg with exit 0)
    RequireWheelLoad(*worn_load, "option --worn-load-N");
    EnsureOutputFolder(*out_dir, "--out");
    std::vector<ThresholdPoint> all;
    nlohmann::json json = {{"tolerance", *tolerance}, {"against", *against}, {"reference", *reference}, {"load_N", *load},
                           {"worn_load_N", *worn_load},
                           {"kp_strips", *strips}, {"fastsim_elements", *elements}};
    int failed_situations = 0;
    for (const std::string& set : set_names) {
      std::fflush(stdout);  // the previous set's lines before this set's progress on stderr
      ProgressReporter progress("threshold " + set, 0.0, "situation", ProgressModeOf(sub), std::cerr);
      ThresholdOptions set_options = options;
      set_options.on_progress = progress.Function();
      const std::vector<ThresholdPoint> points = CompareConformalPlanar(
          MakeThresholdSituations(set, DataDirOr(*data), set == "worn" ? *worn_load : *load), set_options);
      progress.Finish();
      json["sets"][set] = FitJson(points, *tolerance);
      int not_valid = 0, failed = 0;
      for (const ThresholdPoint& p : points) {
        not_valid += !p.valid;
        failed += p.failed;
      }
      json["sets"][set]["not_valid"] = not_valid;  // no contact in one of the models, or an error (status column)
      json["sets"][set]["errors"] = failed;
      failed_situations += failed;
      if (not_valid > 0)
        std::printf("%-7s %d of %zu situations not valid (%d errors): see the status column of threshold.csv\n",
                    set.c_str(), not_valid, points.size(), failed);
      const auto& j = json["sets"][set];
      std::printf("%-7s %4d situations, %3d exceed %.0f%%: threshold %s deg (bracket from %.2f deg, %d misclassified);"
                  " power law d = %.3g alpha^%.2f -> %.2f deg; max alpha_c %.1f deg\n",
                  set.c_str(), j["points"].get<int>(), j["exceeding"].get<int>(), 100 * *tolerance,
                  j["threshold_deg"].dump().c_str(), j["bracket_low_deg"].get<double>(), j["misclassified"].get<int>(),
                  j["power_law_c"].get<double>(), j["power_law_k"].get<double>(),
                  j["power_law_threshold_deg"].get<double>(), j["max_alpha_c_deg"].get<double>());
      all.insert(all.end(), points.begin(), points.end());
    }
    const nlohmann::json combined = FitJson(all, *tolerance);
    json["all"] = combined;
    json["threshold_deg"] = combined["threshold_deg"];
    json["paper_003_threshold_deg"] = kConformityThresholdDeg;

    std::filesystem::create_directories(*out_dir);
    const std::string csv = *out_dir + "/threshold.csv";
    std::ofstream f(csv);
    if (!f) throw InputError("threshold: cannot write " + csv);
    f << "situation,set,alpha_c_deg,contact_angle_deg,d_pmax,d_area,d_creep,d_wear,d_max,valid,status\n";
    for (const ThresholdPoint& p : all) {
      char line[512];
      std::snprintf(line, sizeof line, "%s,%s,%.4f,%.3f,%.6f,%.6f,%.6f,%.6f,%.6f,%d,%s\n", p.name.c_str(),
                    p.family.c_str(), p.alpha_c_deg, p.contact_angle_deg, p.d_pmax, p.d_area, p.d_creep, p.d_wear,
                    p.d_max, p.valid ? 1 : 0, CsvField(p.status).c_str());
      f << line;
    }
    f.close();
    std::ofstream(*out_dir + "/threshold.json") << json.dump(2) << "\n";
    std::printf("all sets: threshold_deg %s (tolerance %.0f%%, against %s); wrote %s, %s/threshold.json\n",
                json["threshold_deg"].dump().c_str(), 100 * *tolerance, against->c_str(), csv.c_str(), out_dir->c_str());
    std::fflush(stdout);  // before the plot script's own output
    if (*plot) {
      const std::string cmd = PythonOr("") + " '" + PlotScript("plot_threshold.py") + "' '" + csv + "' '" + *out_dir +
                              "/threshold.json' '" + *out_dir + "/threshold.png'";
      if (std::system(cmd.c_str()) != 0)
        throw IncompleteResult(ExitCode::PartialResult, "the plot was not produced (" + cmd + " failed)");
    }
    if (failed_situations > 0)
      throw IncompleteResult(ExitCode::PartialResult,
                             std::to_string(failed_situations) + " situation(s) failed with an error (threshold.csv status)");
  });
}

}  // namespace conforma::cli
