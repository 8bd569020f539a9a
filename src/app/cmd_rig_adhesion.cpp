// conforma rig-adhesion --out DIR [--table FILE] [--steady-creepage X] [--max-iterations N]
//                       [--roller-profile scaled_uic60|track_ellipse_ratio] [--no-sensitivity]
// The adhesion tests of the 1:5 roller rig of paper 000 (Table 6; roller_rig_adhesion.hpp, _fit.hpp): Kalker's linear
// slope of each test beside the measured slope, the friction-law fits (one law per condition, and per test) against
// the measured maximum and steady adhesion coefficients, and the similitude factors of the 1:5 scale
// (similitude.hpp). Writes DIR/report.md, DIR/rig_adhesion_slopes.csv and DIR/rig_adhesion_fit.csv.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "conforma/data_paths.hpp"
#include "conforma/error.hpp"
#include "conforma/similitude.hpp"
#include "conforma/validation/roller_rig_adhesion.hpp"
#include "conforma/validation/roller_rig_adhesion_fit.hpp"

namespace conforma::cli {

namespace {

struct RigAdhesionArgs {
  std::string out, table, roller_profile = "scaled_uic60";
  double steady_creepage = 0.10;
  int max_iterations = 200;
  bool sensitivity = true;
};

std::string Fmt(const char* format, double v) {
  char b[64];
  std::snprintf(b, sizeof b, format, v);
  return b;
}

std::vector<RollerRigAdhesionTest> OfCondition(const std::vector<RollerRigAdhesionTest>& all, const std::string& c) {
  std::vector<RollerRigAdhesionTest> out;
  for (const auto& t : all)
    if (t.condition == c) out.push_back(t);
  return out;
}

void WriteSlopes(std::ostream& md, std::ostream& csv, const std::vector<RollerRigAdhesionTest>& tests,
                 const RollerRigAdhesionOptions& rig, const RollerRigCurvatures& c, const RollerRigCurvatures& alt) {
  md << "| test | cond. | rpm | V [m/s] | load [kg] | N [N] | a [mm] | b [mm] | a/b | p0 [MPa] | C11 | G a b C11 [N] | "
        "G a b C11, track a/b [N] | measured slope [N] | measured / G a b C11 (= k) |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  csv << "test,condition,reference_speed_rpm,rolling_speed_m_per_s,wheel_load_kg,normal_force_N,a_mm,b_mm,a_over_b,"
         "p0_MPa,c11,linear_slope_N,linear_slope_track_ratio_N,measured_slope_N,slope_ratio\n";
  for (const auto& t : tests) {
    const double N = t.wheel_load_kg * rig.gravity_m_per_s2;
    const RollerRigLinearContact l = RollerRigLinearTheory(c, N, rig.material);
    const RollerRigLinearContact la = RollerRigLinearTheory(alt, N, rig.material);
    const double V = RollerRigRollingSpeed(t.reference_speed_rpm, rig.roller_radius_m);
    const double ratio = t.initial_slope_N / l.linear_slope_N;
    md << "| " << t.test << " | " << t.condition << " | " << t.reference_speed_rpm << " | " << Fmt("%.2f", V) << " | "
       << t.wheel_load_kg << " | " << Fmt("%.1f", N) << " | " << Fmt("%.4f", l.hertz.a_m * 1e3) << " | "
       << Fmt("%.4f", l.hertz.b_m * 1e3) << " | " << Fmt("%.3f", l.hertz.a_over_b) << " | "
       << Fmt("%.0f", l.hertz.p0_Pa * 1e-6) << " | " << Fmt("%.3f", l.c11) << " | " << Fmt("%.0f", l.linear_slope_N)
       << " | " << Fmt("%.0f", la.linear_slope_N) << " | " << t.initial_slope_N << " | " << Fmt("%.4f", ratio)
       << " |\n";
    char row[512];
    std::snprintf(row, sizeof row, "%d,%s,%.0f,%.4f,%.1f,%.3f,%.6f,%.6f,%.5f,%.2f,%.5f,%.2f,%.2f,%.1f,%.6f\n", t.test,
                  t.condition.c_str(), t.reference_speed_rpm, V, t.wheel_load_kg, N, l.hertz.a_m * 1e3,
                  l.hertz.b_m * 1e3, l.hertz.a_over_b, l.hertz.p0_Pa * 1e-6, l.c11, l.linear_slope_N,
                  la.linear_slope_N, t.initial_slope_N, ratio);
    csv << row;
  }
}

void WriteFitTable(std::ostream& md, const std::vector<RollerRigTestModel>& models) {
  md << "| test | cond. | V [m/s] | k | peak creepage | max meas. | max model | err [%] | steady meas. | "
        "steady model | err [%] |\n|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& m : models)
    md << "| " << m.measured.test << " | " << m.measured.condition << " | " << Fmt("%.2f", m.rolling_speed_m_per_s)
       << " | " << Fmt("%.4f", m.slope_reduction) << " | " << Fmt("%.4f", m.peak_creepage) << " | "
       << m.measured.max_adhesion << " | " << Fmt("%.4f", m.model_max) << " | " << Fmt("%+.2f", m.max_error_percent)
       << " | " << m.measured.steady_adhesion << " | " << Fmt("%.4f", m.model_steady) << " | "
       << Fmt("%+.2f", m.steady_error_percent) << " |\n";
}

void CsvFitRows(std::ostream& csv, const std::string& fit, const RollerRigFit& f) {
  for (const auto& m : f.tests) {
    char row[512];
    std::snprintf(row, sizeof row, "%s,%d,%s,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f,%.4f,%d\n",
                  fit.c_str(), m.measured.test, m.measured.condition.c_str(), f.law.mu_static, f.law.sliding_ratio,
                  f.law.decay_s_per_m, m.slope_reduction, m.peak_creepage, m.measured.max_adhesion, m.model_max,
                  m.measured.steady_adhesion, m.model_steady, m.max_error_percent,
                  m.steady_error_percent, f.converged ? 1 : 0);
    csv << row;
  }
}

std::string LawText(const RollerRigLaw& l) {
  return "mu_s = " + Fmt("%.4f", l.mu_static) + ", A = mu_inf/mu_s = " + Fmt("%.4f", l.sliding_ratio) +
         " (mu_inf = " + Fmt("%.4f", l.mu_static * l.sliding_ratio) + "), B = " + Fmt("%.4f", l.decay_s_per_m) +
         " s/m";
}

void WriteSimilitude(std::ostream& md, const RollerRigAdhesionOptions& rig, const RollerRigCurvatures& c) {
  const SimilitudeQuantity q[] = {SimilitudeQuantity::Length,          SimilitudeQuantity::Time,
                                  SimilitudeQuantity::Speed,           SimilitudeQuantity::AngularSpeed,
                                  SimilitudeQuantity::Acceleration,    SimilitudeQuantity::Mass,
                                  SimilitudeQuantity::Force,           SimilitudeQuantity::Stiffness,
                                  SimilitudeQuantity::Damping,         SimilitudeQuantity::ContactSemiAxis,
                                  SimilitudeQuantity::ContactPressure, SimilitudeQuantity::CreepCoefficient,
                                  SimilitudeQuantity::Creepage};
  SimilitudeOptions s{rig.length_factor, SimilitudeRule::ContactStress};
  SimilitudeOptions w{rig.length_factor, SimilitudeRule::Weight};
  md << "| quantity | contact_stress (model / full) | weight (model / full) |\n|---|---|---|\n";
  for (SimilitudeQuantity x : q)
    md << "| " << to_string(x) << " | " << Fmt("%.5g", SimilitudeFactor(x, s)) << " | "
       << Fmt("%.5g", SimilitudeFactor(x, w)) << " |\n";
  md << "\nFull-scale axle load (2 wheels) of the rig loads, and the Hertz p0 of the rig contact against the full-scale "
        "one (curvatures x phi, same steel):\n\n| load per wheel [kg] | axle load, contact_stress [t] | axle load, weight [t] | "
        "p0 rig [MPa] | p0 full scale, contact_stress [MPa] | p0 full scale, weight [MPa] |\n|---|---|---|---|---|---|\n";
  for (double kg : {37.0, 42.0, 47.0}) {
    const double N = kg * rig.gravity_m_per_s2;
    const double p_rig = SolveHertzForLoad(c.A_per_m, c.B_per_m, N, rig.material).p0_Pa;
    auto full = [&](const SimilitudeOptions& o) {
      const double Nf = ScaleToFull(N, SimilitudeQuantity::Force, o);
      return SolveHertzForLoad(c.A_per_m * rig.length_factor, c.B_per_m * rig.length_factor, Nf, rig.material).p0_Pa;
    };
    md << "| " << kg << " | " << Fmt("%.2f", 2.0 * ScaleToFull(kg, SimilitudeQuantity::Force, s) * 1e-3) << " | "
       << Fmt("%.2f", 2.0 * ScaleToFull(kg, SimilitudeQuantity::Force, w) * 1e-3) << " | "
       << Fmt("%.0f", p_rig * 1e-6) << " | " << Fmt("%.0f", full(s) * 1e-6) << " | " << Fmt("%.0f", full(w) * 1e-6)
       << " |\n";
  }
}

void Run(const RigAdhesionArgs& a) {
  const std::string table =
      a.table.empty() ? ShareDir(CONFORMA_SOURCE_DIR) + "/validation/data/roller_rig_000_table6.csv" : a.table;
  const auto tests = ReadRollerRigAdhesionTable(table);
  RollerRigAdhesionOptions rig;
  rig.roller_profile = a.roller_profile == "scaled_uic60"          ? RollerProfileChoice::ScaledUic60
                       : a.roller_profile == "track_ellipse_ratio" ? RollerProfileChoice::TrackEllipseRatio
                                                                   : throw InputError("--roller-profile '" +
                                                                                      a.roller_profile +
                                                                                      "': expected scaled_uic60 or "
                                                                                      "track_ellipse_ratio");
  RollerRigAdhesionOptions alt_rig = rig;
  alt_rig.roller_profile = rig.roller_profile == RollerProfileChoice::ScaledUic60
                               ? RollerProfileChoice::TrackEllipseRatio
                               : RollerProfileChoice::ScaledUic60;
  RollerRigFitOptions fit;
  fit.steady_creepage = a.steady_creepage;
  fit.max_iterations = a.max_iterations;
  fit.validate();
  const RollerRigCurvatures c = RollerRigCentredCurvatures(rig);
  const RollerRigCurvatures alt = RollerRigCentredCurvatures(alt_rig);
  std::filesystem::create_directories(a.out);
  std::ofstream md(a.out + "/report.md"), slopes(a.out + "/rig_adhesion_slopes.csv"),
      fits(a.out + "/rig_adhesion_fit.csv");
  if (!md || !slopes || !fits) throw InputError(a.out + ": cannot write the report files");

  md << "# Roller-rig adhesion tests (paper 000, Table 6)\n\nTable: `" << std::filesystem::path(table).filename().string()
     << "`. Rig contact at the centred position (docs/physics-reference.md §7.5): wheel S1002, roller UIC60 1:20, "
        "both scaled by phi = "
     << rig.length_factor << "; r_w = " << rig.wheel_radius_m << " m, R_r = " << rig.roller_radius_m
     << " m; G = " << rig.material.shear_modulus_Pa * 1e-9 << " GPa, nu = " << rig.material.poisson_ratio
     << "; load = kg x " << rig.gravity_m_per_s2 << " m/s^2.\n\n"
     << "- A = 1/(2 r_w) + 1/(2 R_r) = " << Fmt("%.4f", c.A_per_m) << " 1/m\n"
     << "- full-scale centred contact: wheel-profile y = " << Fmt("%.2f", c.wheel_profile_y_m * 1e3)
     << " mm, contact angle " << Fmt("%.4f", c.contact_angle_rad) << " rad, kappa_wheel = "
     << Fmt("%.4f", c.full_scale_wheel_curvature_per_m) << " 1/m, kappa_rail = "
     << Fmt("%.4f", c.full_scale_rail_curvature_per_m) << " 1/m, A = " << Fmt("%.4f", c.full_scale_A_per_m)
     << " 1/m, B = " << Fmt("%.4f", c.full_scale_B_per_m) << " 1/m\n"
     << "- B used (" << to_string(rig.roller_profile) << ") = " << Fmt("%.4f", c.B_per_m) << " 1/m; the other choice ("
     << to_string(alt_rig.roller_profile) << ") B = " << Fmt("%.4f", alt.B_per_m) << " 1/m\n\n"
     << "## 1. Initial slope: Kalker's linear theory (paper 000 eq. 22) against the measured slope\n\n";
  WriteSlopes(md, slopes, tests, rig, c, alt);
  // load exponent of the measured slope at one speed (tests 5 -> 7 dry, 6 -> 8 wet, 358 rpm)
  auto find = [&](int id) -> const RollerRigAdhesionTest* {
    for (const auto& t : tests)
      if (t.test == id) return &t;
    return nullptr;
  };
  md << "\nThe slope is read as N per unit creepage (the only reading below the linear-theory bound, §7.5). "
        "Linear theory: slope ~ N^(2/3).";
  for (auto pr : {std::pair<int, int>{5, 7}, std::pair<int, int>{6, 8}}) {
    const auto *t1 = find(pr.first), *t2 = find(pr.second);
    if (t1 && t2 && t1->wheel_load_kg != t2->wheel_load_kg)
      md << " Measured exponent, tests " << pr.first << " -> " << pr.second << ": "
         << Fmt("%.2f", std::log(t2->initial_slope_N / t1->initial_slope_N) /
                            std::log(t2->wheel_load_kg / t1->wheel_load_kg))
         << ".";
  }
  md << "\n\n## 2. Friction-law fit\n\nModel: FASTSIM on the rig ellipse, flexibilities / k with k = measured slope / "
        "G a b C11 (fitted: reproduces the slope exactly), law mu(w) = mu_s [A + (1 - A) exp(-B w)] of the slip "
        "velocity w = gamma V; model max = peak of the creep curve, model steady = curve at creepage "
     << fit.steady_creepage << " (assumed; the curves are not tabulated).\n\n"
     << "### 2.1 One law per condition (3 parameters for 4 tests x 2 numbers: a test of the law)\n\n";
  fits << "fit,test,condition,mu_static,sliding_ratio_A,decay_B_s_per_m,slope_reduction_k,peak_creepage,max_measured,"
          "max_model,steady_measured,steady_model,max_error_percent,steady_error_percent,converged\n";
  std::vector<RollerRigFit> shared;
  for (const std::string cond : {"dry", "wet"}) {
    const auto sub = OfCondition(tests, cond);
    if (sub.empty()) continue;
    std::fprintf(stderr, "rig-adhesion: fitting the %s law ...\n", cond.c_str());
    shared.push_back(FitRollerRigSharedLaw(sub, rig, fit));
    const RollerRigFit& f = shared.back();
    md << "**" << cond << "**: " << LawText(f.law) << "; rms error " << Fmt("%.2f", f.rms_error_percent)
       << " %, largest " << Fmt("%.2f", f.max_abs_error_percent) << " % (" << f.iterations << " iterations, "
       << (f.converged ? "converged" : "NOT converged") << ")\n\n";
    WriteFitTable(md, f.tests);
    md << "\n";
    CsvFitRows(fits, "shared_" + cond, f);
  }
  md << "### 2.2 One law per test (mu_s and A per test, B of its condition: 2 parameters for 2 numbers, an "
        "identification)\n\n| test | cond. | mu_s | A | mu_inf | B [s/m] | k | max err [%] | steady err [%] | converged |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& t : tests) {
    double B = 0.0;
    for (const auto& f : shared)
      if (f.label == t.condition) B = f.law.decay_s_per_m;
    const RollerRigFit f = FitRollerRigTestLaw(t, B, rig, fit);
    const RollerRigTestModel& m = f.tests.front();
    md << "| " << t.test << " | " << t.condition << " | " << Fmt("%.4f", f.law.mu_static) << " | "
       << Fmt("%.4f", f.law.sliding_ratio) << " | " << Fmt("%.4f", f.law.mu_static * f.law.sliding_ratio) << " | "
       << Fmt("%.4f", B) << " | " << Fmt("%.4f", m.slope_reduction) << " | " << Fmt("%+.3f", m.max_error_percent)
       << " | " << Fmt("%+.3f", m.steady_error_percent) << " | " << (f.converged ? "yes" : "no") << " |\n";
    CsvFitRows(fits, "test_" + std::to_string(t.test), f);
  }
  if (a.sensitivity) {
    md << "\n### 2.3 Sensitivity of the per-condition fit to the assumed steady creepage\n\n"
          "| steady creepage | cond. | mu_s | A | B [s/m] | rms err [%] | largest err [%] |\n|---|---|---|---|---|---|---|\n";
    for (double xs : {0.05, 0.2}) {
      RollerRigFitOptions f2 = fit;
      f2.steady_creepage = xs;
      f2.peak_search_max = std::max(fit.peak_search_max, 1.5 * xs);
      for (const std::string cond : {"dry", "wet"}) {
        const auto sub = OfCondition(tests, cond);
        if (sub.empty()) continue;
        std::fprintf(stderr, "rig-adhesion: sensitivity, steady creepage %.2f, %s ...\n", xs, cond.c_str());
        const RollerRigFit f = FitRollerRigSharedLaw(sub, rig, f2);
        md << "| " << xs << " | " << cond << " | " << Fmt("%.4f", f.law.mu_static) << " | "
           << Fmt("%.4f", f.law.sliding_ratio) << " | " << Fmt("%.4f", f.law.decay_s_per_m) << " | "
           << Fmt("%.2f", f.rms_error_percent) << " | " << Fmt("%.2f", f.max_abs_error_percent) << " |\n";
      }
    }
  }
  md << "\n## 3. Similitude of the 1:5 rig (docs/physics-reference.md §7.6)\n\n";
  WriteSimilitude(md, rig, c);
  std::printf("rig-adhesion: %zu tests -> %s/report.md, rig_adhesion_slopes.csv, rig_adhesion_fit.csv\n", tests.size(),
              a.out.c_str());
}

}  // namespace

void RegisterRigAdhesionCommand(CLI::App& app) {
  auto a = std::make_shared<RigAdhesionArgs>();
  CLI::App* sub = app.add_subcommand(
      "rig-adhesion", "roller-rig adhesion tests of paper 000 (Table 6): linear slope, friction-law fit, similitude");
  sub->add_option("--out", a->out, "output folder (report.md and CSV files)")->required();
  sub->add_option("--table", a->table, "Table 6 CSV (default: validation/data/roller_rig_000_table6.csv)");
  sub->add_option("--steady-creepage", a->steady_creepage, "creepage at which the steady coefficient is taken");
  sub->add_option("--max-iterations", a->max_iterations, "Levenberg-Marquardt iterations per fit");
  sub->add_option("--roller-profile", a->roller_profile, "scaled_uic60 or track_ellipse_ratio (B of the rig ellipse)");
  sub->add_flag("--sensitivity,!--no-sensitivity", a->sensitivity, "run the steady-creepage sensitivity fits (default on)");
  sub->callback([a]() { Run(*a); });
}

}  // namespace conforma::cli
