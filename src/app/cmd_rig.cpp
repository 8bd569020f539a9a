// conforma rig run    --scenario FILE --out DIR [--step-s X] [--distance-fraction F] [--max-tests N] [--wear-law L]
// conforma rig replay --scenario FILE --input CSV --out DIR [--wear-law L]
// Roller-rig mode (issue 18, paper 000; roller_rig*.hpp, docs/physics-reference.md §18):
//   run:    the scenario's wear test plan (Table 5), each test from the previous profiles; DIR/rig_plan.csv (per test:
//           wheel and roller wear depth and area, distance, run time, status), DIR/report.md, DIR/profiles/.
//   replay: a measured time series (t, y, yaw, omega1, omega2, loads [, omega3]) sample by sample; DIR/rig_replay.csv
//           (forces, creepages, wear increments per sample) and the final profiles in DIR/profiles/.
// Exit 5 (partial result) when samples failed; the outputs say which.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "conforma/contact_model.hpp"
#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/roller_rig_plan.hpp"
#include "conforma/roller_rig_replay.hpp"
#include "exit_status.hpp"
#include "text_format.hpp"
#include "progress.hpp"

namespace conforma::cli {

namespace {

struct RigArgs {
  std::string scenario, out, input, wear_law;
  double step_s = 0.0, distance_fraction = 1.0, max_depth_per_approach = 0.0, strip_mean_elements = 0.0;
  int max_tests = 0;
  bool adaptive_substeps = false;
  std::string model;
};

RollerRigScenario Scenario(const RigArgs& a) {
  // 0 = the scenario's; a negative or NaN value was silently the scenario's too (fuzzing, session 25)
  const std::pair<double, const char*> given[] = {{a.step_s, "--step-s"},
                                                  {a.max_depth_per_approach, "--max-depth-per-approach"},
                                                  {a.strip_mean_elements, "--strip-mean-elements"}};
  for (const auto& [value, option] : given)
    if (!(std::isfinite(value) && value >= 0.0))
      throw InputError(std::string("option ") + option + " must be finite and > 0 (omit it for the scenario's)");
  if (a.max_tests < 0) throw InputError("option --max-tests must be >= 1 (omit it for all tests)");
  RollerRigScenario sc = LoadRollerRigScenario(a.scenario);
  if (!a.wear_law.empty()) sc.options.wear_law = RollerRigWearLawFromName(a.wear_law);
  if (!a.model.empty()) sc.options.kinematics.contact.model = ParseContactModel(a.model);
  if (a.max_depth_per_approach > 0.0) sc.options.max_depth_per_approach = a.max_depth_per_approach;
  if (a.strip_mean_elements > 0.0) sc.options.strip_mean_elements = a.strip_mean_elements;
  sc.options.validate();
  return sc;
}

void SaveProfiles(const std::string& dir, const std::string& prefix, const std::array<Profile, 2>& wheel,
                  const std::array<Profile, 2>& roller, double spacing) {
  std::filesystem::create_directories(dir);
  SaveProfileCsv(wheel[0], dir + "/" + prefix + "wheel_left.csv", spacing);
  SaveProfileCsv(wheel[1], dir + "/" + prefix + "wheel_right.csv", spacing);
  SaveProfileCsv(roller[0], dir + "/" + prefix + "roller_1.csv", spacing);
  SaveProfileCsv(roller[1], dir + "/" + prefix + "roller_2.csv", spacing);
}

void RunPlan(const RigArgs& a, ProgressMode mode) {
  const RollerRigScenario sc = Scenario(a);
  RollerRigPlanOptions po;
  po.step_s = a.step_s;
  po.distance_fraction = a.distance_fraction;
  po.max_tests = a.max_tests;
  po.adaptive_substeps = a.adaptive_substeps;
  // the project's progress display (bar on a terminal, lines otherwise, nothing with --quiet), one per test
  std::unique_ptr<ProgressReporter> progress;
  int progress_test = -1;
  po.progress = [&](int test, long k, long n) {
    if (test != progress_test) {
      progress.reset();  // ends the previous test's bar
      progress = std::make_unique<ProgressReporter>("rig run test " + std::to_string(test + 1),
                                                    static_cast<double>(n), "sample", mode, std::cerr);
      progress_test = test;
    }
    progress->Update(static_cast<double>(k + 1));
  };
  EnsureOutputFolder(a.out, "--out");
  const double step = a.step_s > 0.0 ? a.step_s : sc.step_s;
  const auto results = RunRollerRigPlan(sc, po);
  progress.reset();
  std::ofstream csv(a.out + "/rig_plan.csv");
  csv << "test,creep,reference_speed_rpm,wheel_load_kg,distance_km_plan,time_min_plan,distance_m,simulated_time_s,"
         "samples,failed_samples,mean_omega3_rad_s,mean_xi_1,mean_xi_2,mean_fx_left_N,mean_fx_right_N,"
         "wheel_left_max_depth_mm,wheel_left_area_mm2,wheel_right_max_depth_mm,wheel_right_area_mm2,"
         "roller_1_max_depth_mm,roller_1_area_mm2,roller_2_max_depth_mm,roller_2_area_mm2,"
         "wheel_left_total_max_depth_mm,roller_1_total_max_depth_mm,substeps,rejected_substeps,stability_violations,"
         "min_substep_s,max_depth_per_approach,run_time_s,status\n";
  std::ofstream md(a.out + "/report.md");
  md << "# Roller-rig wear test plan (paper 000 Table 5)\n\nScenario: `" << a.scenario << "`; time step " << step
     << " s, sliding-mean filter every " << std::max(1, static_cast<int>(std::lround(sc.filter_interval_s / step)))
     << " step(s) (" << sc.filter_interval_s << " s), window " << sc.options.filter_window_m * 1e3 << " mm; wear law "
     << to_string(sc.options.wear_law) << " (strip depth / C = " << sc.options.strip_mean_elements
     << ", paper 000 eq. 16); contact model " << to_string(sc.options.kinematics.contact.model)
     << ", mu = " << sc.options.kinematics.contact.friction_coefficient << "; distance fraction " << a.distance_fraction
     << "; " << (a.adaptive_substeps ? "adaptive sub-steps" : "fixed steps")
     << ", depth per step <= " << sc.options.max_depth_per_approach << " x elastic approach.\n\n"
     << "Wear per test = vertical (wheel: radial) difference between the profiles at the start and the end of the "
        "test.\n\n"
     << "| test | creep | rpm | load [kg] | distance [km] | sim. time [min] (plan) | mean xi_1 / xi_2 | "
        "wheel L max [um] | wheel L area [mm^2] | wheel R max [um] | roller 1 max [um] | roller 1 area [mm^2] | "
        "roller 2 max [um] | sub-steps (rejected) | run time [s] | status |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  long failed = 0;
  double run_time = 0.0;
  for (const RollerRigTestResult& r : results) {
    const auto& t = r.test;
    failed += r.failed_samples;
    run_time += r.run_time_s;
    csv << t.test << "," << t.creep << "," << t.reference_speed_rpm << "," << t.wheel_load_kg << "," << t.distance_km
        << "," << t.time_min << "," << Fmt("%.6g", r.distance_m) << "," << Fmt("%.6g", r.simulated_time_s) << ","
        << r.samples << "," << r.failed_samples << "," << Fmt("%.8g", r.mean_wheelset_speed_rad_s) << ","
        << Fmt("%.6g", r.mean_creepage[0]) << "," << Fmt("%.6g", r.mean_creepage[1]) << ","
        << Fmt("%.6g", r.mean_fx_N[0]) << "," << Fmt("%.6g", r.mean_fx_N[1]);
    for (const auto* w : {&r.wheel_wear[0], &r.wheel_wear[1], &r.roller_wear[0], &r.roller_wear[1]})
      csv << "," << Fmt("%.6g", w->max_depth_m * 1e3) << "," << Fmt("%.6g", w->area_m2 * 1e6);
    csv << "," << Fmt("%.6g", r.wheel_wear_total[0].max_depth_m * 1e3) << ","
        << Fmt("%.6g", r.roller_wear_total[0].max_depth_m * 1e3) << "," << r.substeps << "," << r.rejected_substeps
        << "," << r.stability_violations << "," << Fmt("%.4g", r.min_substep_s) << ","
        << Fmt("%.4g", r.max_depth_per_approach) << "," << Fmt("%.4g", r.run_time_s) << "," << to_string(r.status)
        << "\n";
    md << "| " << t.test << " | " << t.creep << " | " << t.reference_speed_rpm << " | " << t.wheel_load_kg << " | "
       << Fmt("%.3f", r.distance_m * 1e-3) << " | " << Fmt("%.1f", r.simulated_time_s / 60.0) << " (" << t.time_min
       << ") | " << Fmt("%.4f", r.mean_creepage[0]) << " / " << Fmt("%.4f", r.mean_creepage[1]) << " | "
       << Fmt("%.2f", r.wheel_wear[0].max_depth_m * 1e6) << " | " << Fmt("%.5f", r.wheel_wear[0].area_m2 * 1e6) << " | "
       << Fmt("%.2f", r.wheel_wear[1].max_depth_m * 1e6) << " | " << Fmt("%.2f", r.roller_wear[0].max_depth_m * 1e6)
       << " | " << Fmt("%.5f", r.roller_wear[0].area_m2 * 1e6) << " | "
       << Fmt("%.2f", r.roller_wear[1].max_depth_m * 1e6) << " | " << r.substeps << " (" << r.rejected_substeps
       << ") | " << Fmt("%.1f", r.run_time_s) << " | " << to_string(r.status)
       << (r.first_failure.empty() ? "" : " (" + r.first_failure + ")") << " |\n";
    SaveProfiles(a.out + "/profiles", "test" + std::to_string(t.test) + "_", r.wheel, r.roller,
                 0.1e-3 * sc.options.setup.length_factor);
  }
  md << "\nTotal run time " << Fmt("%.1f", run_time) << " s; failed samples " << failed << ".\n";
  std::printf("rig run: %zu tests, %.1f s -> %s/rig_plan.csv, report.md, profiles/\n", results.size(), run_time,
              a.out.c_str());
  if (failed > 0)
    throw IncompleteResult(ExitCode::PartialResult, std::to_string(failed) + " rig samples failed (see rig_plan.csv)");
}

// Largest pressure over a wheel's patches, Pa (0 without contact).
double MaxPressure(const WheelContactReport& r) {
  double p = 0.0;
  for (const PatchReport& q : r.patches) p = std::max(p, q.pmax_Pa);
  return p;
}

void RunReplay(const RigArgs& a) {
  const RollerRigScenario sc = Scenario(a);
  const std::vector<RollerRigSample> samples = ReadRollerRigSamples(a.input);
  RollerRigState state = MakeRollerRigState(sc.options);
  EnsureOutputFolder(a.out, "--out");
  std::ofstream csv(a.out + "/rig_replay.csv");
  csv << "t_s,dt_s,status,kinematics_status,omega3_rad_s,omega3_eq2_rad_s";
  for (const char* s : {"left", "right"})
    csv << ",fn_" << s << "_N,fx_" << s << "_N,fy_" << s << "_N,xi_" << s << ",eta_" << s << ",phi_" << s << "_per_m,"
        << "wheel_wear_max_depth_" << s << "_m,wheel_wear_area_" << s << "_m2,roller_wear_max_depth_" << s
        << "_m,roller_wear_area_" << s << "_m2,spring_force_" << s << "_N,patches_" << s << ",pmax_" << s << "_Pa";
  csv << ",yaw_deflection_rad,message\n";
  const long failed = ReplayRollerRigSamples(sc.options, &state, samples, [&](const RollerRigReplayRow& row) {
    const RollerRigSampleResult& r = row.result;
    const RollerRigKinematicsResult& k = r.kinematics;
    csv << Fmt("%.12g", row.sample.time_s) << "," << Fmt("%.12g", row.sample.duration_s) << "," << to_string(r.status)
        << "," << to_string(k.status) << "," << Fmt("%.10g", k.wheelset_speed_rad_s) << ","
        << Fmt("%.10g", k.eq2_wheelset_speed_rad_s);
    for (int j = 0; j < 2; ++j) {
      const RollerRigContactResult& c = k.contact[j];
      csv << "," << Fmt("%.8g", c.fn_N) << "," << Fmt("%.8g", c.fx_N) << "," << Fmt("%.8g", c.fy_N) << ","
          << Fmt("%.8g", c.xi) << "," << Fmt("%.8g", c.eta) << "," << Fmt("%.8g", c.phi_per_m) << ","
          << Fmt("%.6g", r.wheel_wear_max_depth_m[j]) << "," << Fmt("%.6g", r.wheel_wear_area_m2[j]) << ","
          << Fmt("%.6g", r.roller_wear_max_depth_m[j]) << "," << Fmt("%.6g", r.roller_wear_area_m2[j]) << ","
          << Fmt("%.8g", k.spring_force_N[j]) << "," << c.report.patches.size() << ","
          << Fmt("%.6g", MaxPressure(c.report));
    }
    std::string msg = r.message;
    for (char& ch : msg)
      if (ch == ',' || ch == '\n') ch = ';';
    csv << "," << Fmt("%.6g", k.yaw_deflection_rad) << "," << msg << "\n";
  });
  SaveProfiles(a.out + "/profiles", "final_", state.wheel, state.roller, 0.1e-3 * sc.options.setup.length_factor);
  std::printf("rig replay: %zu samples (%ld failed) -> %s/rig_replay.csv, profiles/\n", samples.size(), failed,
              a.out.c_str());
  if (failed > 0)
    throw IncompleteResult(ExitCode::PartialResult, std::to_string(failed) + " rig samples failed (see rig_replay.csv)");
}

// The scenario values that `rig run` and `rig replay` can override (applied by Scenario()).
void AddScenarioOverrides(CLI::App* sub, RigArgs* a) {
  sub->add_option("--wear-law", a->wear_law, "archard (paper 000 Table 3) or wear_index (USFD T-gamma)");
  sub->add_option("--model", a->model, "contact model (default: the scenario's)");
  sub->add_option("--strip-mean-elements", a->strip_mean_elements,
                  "paper 000 eq. 16: depth per strip = integral / C (default: the scenario's wear.strip_mean_elements)")
      ->check(CLI::PositiveNumber);
}

}  // namespace

void RegisterRigCommand(CLI::App& app) {
  CLI::App* rig = app.add_subcommand("rig", "roller-rig mode (paper 000): wear test plan, replay of a measured run");
  rig->require_subcommand(1);
  {
    auto a = std::make_shared<RigArgs>();
    CLI::App* sub = rig->add_subcommand("run", "run the scenario's wear test plan (Table 5), test after test");
    sub->add_option("--scenario", a->scenario, "roller-rig scenario (e.g. scenarios/roller_rig_1to5.yaml)")->required();
    sub->add_option("--out", a->out, "output folder (rig_plan.csv, report.md, profiles/)")->required();
    sub->add_option("--step-s", a->step_s, "time step, s (default: the scenario's wear.step_s)");
    sub->add_option("--distance-fraction", a->distance_fraction, "run this fraction of each test's distance (0, 1]");
    sub->add_option("--max-tests", a->max_tests, "run only the first N tests");
    AddScenarioOverrides(sub, a.get());
    sub->add_option("--max-depth-per-approach", a->max_depth_per_approach,
                    "stability rule: depth per step / elastic approach (default: 0.1)");
    sub->add_flag("--adaptive-substeps", a->adaptive_substeps,
                  "repeat a step that breaks the stability rule in halved sub-steps (default: counted only)");
    sub->callback([a, sub]() { RunPlan(*a, ProgressModeOf(sub)); });
  }
  {
    auto a = std::make_shared<RigArgs>();
    CLI::App* sub = rig->add_subcommand("replay", "process a measured time series sample by sample");
    sub->add_option("--scenario", a->scenario, "roller-rig scenario (rig, contact and wear options)")->required();
    sub->add_option("--input", a->input, "CSV: t_s,y_m,yaw_rad,omega1_rad_s,omega2_rad_s,load_left_N,load_right_N"
                                         "[,omega3_rad_s][,dt_s]")->required();
    sub->add_option("--out", a->out, "output folder (rig_replay.csv, profiles/)")->required();
    AddScenarioOverrides(sub, a.get());
    sub->callback([a]() { RunReplay(*a); });
  }
}

}  // namespace conforma::cli
