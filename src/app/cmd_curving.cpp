// conforma curving --scenario F [--class I] [--model M] [--provider P]: the curving kinematics of a scenario's track
// classes on its initial profiles, with the contact forces of every wheel at the solution (what the wear loop
// uses as its samples; kinematics_quasistatic.hpp, wear_simulation.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "progress.hpp"
#include "conforma/dynamic_kinematics.hpp"
#include "conforma/error.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/scenario.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma::cli {

namespace {

// Returns how many loaded wheels' contacts are not ok (no contact or not converged).
int PrintSamples(const Scenario& sc, const WheelsetTrackGeometry& g, const KinematicsSeries& s, ContactModel model) {
  int failed = 0;
  WheelContactOptions o;
  o.model = model;
  ApplyScenarioContact(sc, &o);
  for (const KinematicsSample& k : s.samples) {
    std::printf("    ws %d w %.3f: y %+7.3f mm  psi %+7.3f mrad  Omega r0/V-1 %+.2e\n", k.wheelset, k.weight,
                k.pose.lateral_m * 1e3, k.pose.yaw_rad * 1e3,
                k.velocity.axle_angular_velocity_rad_s * sc.vehicle.nominal_wheel_radius_m / k.velocity.forward_speed_m_s -
                    1.0);
    for (Side side : {Side::Left, Side::Right}) {
      o.vertical_load_N = k.vertical_load_N[side_index(side)];
      const WheelContactReport r = SolveWheelContact(g, side, k.pose, k.velocity, o);
      if (o.vertical_load_N > 0.0 && r.status != WheelContactStatus::Ok) ++failed;
      std::printf("      %s Q %7.0f N  %s  %zu patches  Y %+8.0f N\n", side == Side::Left ? "L" : "R", o.vertical_load_N,
                  to_string(r.status), r.patches.size(), r.lateral_force_N);
      for (const PatchReport& p : r.patches)
        std::printf("        angle %+6.1f deg  y_w %+7.2f mm  Fn %8.0f N  Fx %+7.0f  Fy %+7.0f  pmax %5.0f MPa  "
                    "xi %+.4f eta %+.4f phi %+6.2f/m  P %.0f W\n",
                    p.contact_angle_rad * 180.0 / M_PI, p.y_contact_wheel_m * 1e3, p.fn_N, p.fx_N, p.fy_N,
                    p.pmax_Pa * 1e-6, p.xi, p.eta, p.phi_per_m, p.frictional_power_W);
    }
  }
  return failed;
}

// The quasi-static solve with the options the wear loop uses (MakeScenarioKinematics), before any fallback; true
// when it converged.
bool PrintEquilibrium(const Scenario& sc, const WheelsetTrackGeometry& g, const TrackClass& tc, ContactModel model) {
  const QuasiStaticResult r = SolveQuasiStaticCurving(sc.vehicle, g, tc, ScenarioQuasiStaticOptions(sc, model));
  const double c = TrackClassCurvature(tc);
  std::printf("  equilibrium %s, a_nc %.3f m/s^2, flange-contact shift %+.3f mm\n", to_string(r.status),
              r.unbalanced_acceleration_m_s2, FlangeContactShift(g, c >= 0.0 ? 1.0 : -1.0) * 1e3);
  for (const BogieQuasiStaticReport& b : r.bogies)
    std::printf("    bogie %d %s: max residual %.2e, %d iterations, continuation %s, %d of %d wheel contact solves "
                "failed%s%s\n",
                b.bogie, to_string(b.status), b.max_residual, b.iterations, b.continuation_used ? "yes" : "no",
                b.failed_contact_evaluations, b.contact_evaluations, b.derailed ? ", DERAILED" : "",
                b.climbing ? ", CLIMBING its flange" : "");
  for (const BogieQuasiStaticReport& b : r.bogies)
    std::printf("    bogie %d residuals: ws0 %+.1e %+.1e %+.1e  ws1 %+.1e %+.1e %+.1e  frame %+.1e %+.1e\n", b.bogie,
                b.residuals[0], b.residuals[1], b.residuals[2], b.residuals[3], b.residuals[4], b.residuals[5],
                b.residuals[6], b.residuals[7]);
  for (const WheelsetQuasiStaticReport& w : r.wheelsets)
    std::printf("    ws %d: y %+7.3f mm psi %+7.3f mrad  Y/Q L %+.2f R %+.2f  max angle L %.0f R %.0f deg\n", w.wheelset,
                w.pose.lateral_m * 1e3, w.pose.yaw_rad * 1e3, w.wheel[0].y_over_q, w.wheel[1].y_over_q,
                w.wheel[0].max_contact_angle_rad * 180.0 / M_PI, w.wheel[1].max_contact_angle_rad * 180.0 / M_PI);
  return r.status == QuasiStaticStatus::Converged;
}

// The dynamic provider's samples per wheelset: count, mean, standard deviation and range of y and psi (relative to
// the actual track), and of the load of the outer (right for a left curve) wheel.
void PrintSampleSummary(const KinematicsSeries& s) {
  std::map<int, std::vector<const KinematicsSample*>> by_ws;
  for (const KinematicsSample& k : s.samples) by_ws[k.wheelset].push_back(&k);
  std::printf("    %s\n", s.source.c_str());
  for (const auto& [ws, v] : by_ws) {
    auto stats = [&v](auto f, double scale, const char* name, const char* unit) {
      double mean = 0.0, lo = 1e300, hi = -1e300;
      for (const KinematicsSample* k : v) {
        const double x = f(*k) * scale;
        mean += x / v.size();
        lo = std::min(lo, x);
        hi = std::max(hi, x);
      }
      double var = 0.0;
      for (const KinematicsSample* k : v) var += std::pow(f(*k) * scale - mean, 2) / v.size();
      std::printf("  %s %+8.3f +/- %6.3f [%+8.3f, %+8.3f] %s", name, mean, std::sqrt(var), lo, hi, unit);
    };
    std::printf("    ws %d: %zu samples, weights %.4f\n     ", ws, v.size(), v.front()->weight);
    stats([](const KinematicsSample& k) { return k.pose.lateral_m; }, 1e3, "y", "mm");
    stats([](const KinematicsSample& k) { return k.pose.yaw_rad; }, 1e3, "psi", "mrad\n     ");
    stats([](const KinematicsSample& k) { return k.vertical_load_N[1]; }, 1e-3, "Q_R", "kN\n");
  }
}

}  // namespace

void RegisterCurvingCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("curving", "curving kinematics of a scenario's track classes, with the wheel forces");
  struct Args {
    std::vector<std::string> scenario_overrides;  // --set
    std::string scenario, model, provider;
    int track_class = -1;
    bool equilibrium = false;
  };
  auto a = std::make_shared<Args>();
  sub->add_option("--scenario", a->scenario, "scenario YAML file")->required();
  sub->add_option("--class", a->track_class, "track class index (default: all)");
  AddScenarioOverrides(sub, &a->scenario_overrides);
  sub->add_option("--model", a->model, WearModelHelp("contact model") + "; default: the scenario's");
  sub->add_flag("--equilibrium", a->equilibrium,
                "also print the quasi-static solve itself: status and residual per bogie, flange-contact shift");
  sub->add_option("--provider", a->provider, "kinematics provider: quasistatic, kinematic, centred, dynamic (default: the scenario's; dynamic prints a summary of "
                                          "the samples per wheelset)");
  sub->callback([a, sub]() {
    Scenario sc = LoadScenario(a->scenario, a->scenario_overrides);
    WarnImplausibleFriction(sc);
    const ContactModel model = a->model.empty() ? sc.model : ParseWearModel(a->model, "--model");
    if (!IsWearContactModel(model))
      throw InputError(std::string("scenario contact_model '") + to_string(model) +
                       "' solves the normal problem only (no creep forces for the curving equilibrium); usable: " +
                       WearContactModelNames());
    if (a->provider == "quasistatic") sc.kinematics.provider = KinematicsProvider::QuasiStatic;
    else if (a->provider == "kinematic") sc.kinematics.provider = KinematicsProvider::Kinematic;
    else if (a->provider == "centred") sc.kinematics.provider = KinematicsProvider::Centred;
    else if (a->provider == "dynamic") sc.kinematics.provider = KinematicsProvider::Dynamic;
    else if (!a->provider.empty()) throw InputError("--provider: unknown provider '" + a->provider + "'");
    const int nc = static_cast<int>(sc.classes.size());
    if (a->track_class >= nc) throw InputError("--class: index " + std::to_string(a->track_class) + " >= " + std::to_string(nc));
    if (a->track_class < -1)  // (-5 meant "all": fuzzing, session 25)
      throw InputError("--class: index " + std::to_string(a->track_class) + " < 0 (omit it for all classes)");
    const WheelsetTrackGeometry g(sc.MakeTrackSetup());
    auto fallbacks = std::make_shared<KinematicsFallbackLog>();
    const ContactModel curving_model = CurvingContactModel(sc, model);
    const KinematicsFunction kin = MakeWearKinematics(sc, curving_model, &SolveWheelContact, fallbacks);
    // progress: before each class "k/n class, <class being solved>"; erased before its lines on stdout
    ProgressReporter progress("curving", a->track_class >= 0 ? 1.0 : nc, "class", ProgressModeOf(sub), std::cerr);
    int done = 0;
    // what makes the result incomplete (exit 5, or 4 for an equilibrium alone): classes that fell back, loaded wheels
    // whose contact at a sample is not ok, and (--equilibrium) quasi-static solves that did not converge
    int fallback_classes = 0, failed_contacts = 0, unconverged_equilibria = 0;
    for (int c = 0; c < nc; ++c) {
      if (a->track_class >= 0 && c != a->track_class) continue;
      const TrackClass& tc = sc.classes[c];
      progress.Update(done, "class " + std::to_string(c) + " " + tc.name);
      const size_t before = fallbacks->size();
      const KinematicsSeries s = kin(g, tc, c);
      progress.Suspend();
      std::string fell_back;
      for (const KinematicsFallbackLog::Entry& e : fallbacks->since(before))
        fell_back += " (fell back to the " + e.replacement + ": " + e.reason + ")";
      std::printf("class %d %s: R %.0f m, cant %.0f mm, V %.1f km/h, share %.4f, provider %s%s\n", c, tc.name.c_str(),
                  tc.curve_radius_m, tc.cant_m * 1e3, tc.speed_m_s * 3.6, tc.share, to_string(sc.kinematics.provider),
                  fell_back.c_str());
      if (!fell_back.empty()) ++fallback_classes;
      if (a->equilibrium && TrackClassCurvature(tc) != 0.0 && !PrintEquilibrium(sc, g, tc, curving_model))
        ++unconverged_equilibria;
      if (sc.kinematics.provider == KinematicsProvider::Dynamic) PrintSampleSummary(s);
      else failed_contacts += PrintSamples(sc, g, s, model);
      std::fflush(stdout);  // the class's lines before the next progress line on stderr
      ++done;
    }
    progress.Update(done, "");
    progress.Finish();
    if (fallback_classes > 0 || failed_contacts > 0) {
      const std::string what = std::to_string(fallback_classes) + " track class(es) fell back to another provider's "
                               "kinematics and " + std::to_string(failed_contacts) +
                               " loaded wheel contact(s) of the samples are not ok (see the lines above)";
      throw IncompleteResult(ExitCode::PartialResult, "curving: " + what);
    }
    if (unconverged_equilibria > 0)
      throw IncompleteResult(ExitCode::NotConverged, "curving: " + std::to_string(unconverged_equilibria) +
                                                         " quasi-static equilibrium solve(s) did not converge");
  });
}

}  // namespace conforma::cli
