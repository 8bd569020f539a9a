// conforma rig-adhesion --out DIR [--table FILE] [--steady-creepage X] [--max-iterations N]
//                       [--roller-profile scaled_uic60|track_ellipse_ratio] [--no-sensitivity]
//                       [--variants all|none|VARIANT[,VARIANT...]] [--law VARIANT]
// The adhesion tests of the 1:5 roller rig of paper 000 (Table 6; roller_rig_adhesion.hpp, _fit.hpp): Kalker's linear
// slope of each test beside the measured slope, the friction-law fits (one law per condition, and per test) against
// the measured maximum and steady adhesion coefficients, and the similitude factors of the 1:5 scale
// (similitude.hpp), and the law variants of the per-condition fit (RollerRigLawVariant: each at the steady creepage of
// the option and with the steady creepage fitted). Writes DIR/report.md, DIR/rig_adhesion_slopes.csv,
// DIR/rig_adhesion_fit.csv and DIR/rig_adhesion_variants.csv.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <atomic>
#include <exception>
#include <functional>
#include <thread>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "commands.hpp"
#include "exit_status.hpp"
#include "text_format.hpp"
#include "conforma/data_paths.hpp"
#include "conforma/error.hpp"
#include "conforma/similitude.hpp"
#include "conforma/validation/roller_rig_adhesion.hpp"
#include "conforma/validation/roller_rig_adhesion_fit.hpp"

namespace conforma::cli {

namespace {

struct RigAdhesionArgs {
  std::string out, table, roller_profile = "scaled_uic60", variants = "all", law = "speed_power";
  double steady_creepage = 0.10;
  int max_iterations = 200;
  bool sensitivity = true;
};

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

std::vector<RollerRigLawVariant> SelectedVariants(const std::string& spec) {
  if (spec == "all") return AllRollerRigLawVariants();
  std::vector<RollerRigLawVariant> out;
  if (spec == "none") return out;
  std::stringstream ss(spec);
  std::string item;
  while (std::getline(ss, item, ','))
    if (!item.empty()) out.push_back(ParseRollerRigLawVariant(item));
  if (out.empty()) throw InputError("--law: no law named in '" + spec + "'");
  return out;
}

std::string VariantLawText(const RollerRigLaw& l) {
  std::string t = "mu_s = " + Fmt("%.4f", l.mu_static) + ", A = " + Fmt("%.4f", l.sliding_ratio) + ", B = " +
                  Fmt("%.4f", l.decay_s_per_m) + " s/m";
  if (l.variant == RollerRigLawVariant::SpeedPower) t += ", n = " + Fmt("%.4f", l.speed_exponent);
  if (l.variant == RollerRigLawVariant::SpeedHyperbolic) t += ", V_0 = " + Fmt("%.3f", l.speed_scale_m_per_s) + " m/s";
  if (l.variant == RollerRigLawVariant::PolachExtended) t += ", k_S/k_A = " + Fmt("%.4f", l.slip_area_ratio);
  return t;
}

// One law variant, both conditions: the summary row of the variant table, the per-test tables, the CSV rows.
struct VariantRun {
  RollerRigLawVariant variant;
  bool steady_fitted;
  std::vector<RollerRigFit> fits;  // dry, wet (those present)
};

// The laws fitted again with the steady creepage a parameter: slip_velocity, the chosen law and Polach's (analytic,
// cheap); the other FASTSIM laws only at the fixed creepage (run time).
bool FitSteadyCreepageOf(RollerRigLawVariant v, RollerRigLawVariant chosen) {
  return v == RollerRigLawVariant::SlipVelocity || v == chosen || v == RollerRigLawVariant::PolachAnalytic ||
         v == RollerRigLawVariant::PolachExtended;
}

// The variants of one condition: each at the steady creepage of the options, then those of FitSteadyCreepageOf with
// the steady creepage fitted (LM from their optimum at the fixed creepage; also from their start grid for Polach's
// cheap analytic laws). The laws with a rolling-speed parameter start from the slip_velocity optimum (their n = 0 /
// V_0 -> infinity limit), and from their grid only for the chosen law (run time); Polach's extended model from the
// analytic one and its grid. Result: the fixed fits in the order of `variants`, then the fitted ones in the same
// order.
std::vector<RollerRigFit> FitVariantsOfCondition(const std::vector<RollerRigAdhesionTest>& sub,
                                                 const RollerRigAdhesionOptions& rig, const RollerRigFitOptions& fit,
                                                 const std::vector<RollerRigLawVariant>& variants,
                                                 RollerRigLawVariant chosen) {
  std::vector<RollerRigFit> out;
  auto fixed_of = [&](RollerRigLawVariant v) -> const RollerRigFit* {
    for (size_t i = 0; i < out.size() && i < variants.size(); ++i)
      if (variants[i] == v) return &out[i];
    return nullptr;
  };
  for (bool steady_fitted : {false, true})
    for (RollerRigLawVariant v : variants) {
      if (steady_fitted && !FitSteadyCreepageOf(v, chosen)) continue;
      std::fprintf(stderr, "rig-adhesion: law %s%s, %s ...\n", to_string(v),
                   steady_fitted ? " (steady creepage fitted)" : "", sub.front().condition.c_str());
      RollerRigFitOptions fv = fit;
      fv.variant = v;
      fv.peak_before_steady = true;
      fv.fit_steady_creepage = steady_fitted;
      const bool polach = v == RollerRigLawVariant::PolachAnalytic || v == RollerRigLawVariant::PolachExtended;
      if (steady_fitted) {
        if (const RollerRigFit* f = fixed_of(v)) fv.extra_starts.push_back(f->law), fv.lm_from_grid = polach;
      } else {
        const RollerRigLawVariant nested = v == RollerRigLawVariant::PolachExtended ? RollerRigLawVariant::PolachAnalytic
                                                                                   : RollerRigLawVariant::SlipVelocity;
        const bool has_nested = v == RollerRigLawVariant::SpeedPower || v == RollerRigLawVariant::SpeedHyperbolic ||
                                v == RollerRigLawVariant::PolachExtended;
        if (has_nested)
          if (const RollerRigFit* f = fixed_of(nested)) fv.extra_starts.push_back(f->law), fv.lm_from_grid = polach || v == chosen;
      }
      RollerRigFit f = FitRollerRigSharedLaw(sub, rig, fv);
      out.push_back(std::move(f));
    }
  return out;
}

// Everything fitted for one condition (run in its own thread; results as if run sequentially).
struct ConditionFits {
  std::string condition;
  RollerRigFit shared;                        // §2.1
  std::vector<RollerRigFit> per_test;         // §2.2, in table order
  std::vector<RollerRigFit> sensitivity;      // §2.3: steady creepage 0.05, 0.2
  std::vector<RollerRigFit> variants;         // §2.4: fixed, then steady creepage fitted
  std::vector<RollerRigFit> chosen_sensitivity;  // §2.5: the chosen law at steady creepage 0.05, 0.2
};

const double kSensitivityCreepages[] = {0.05, 0.2};

// The fits that did not converge, or have more parameters than measured numbers (an underdetermined fit
// "converges" on any of its optima: nothing is identified), named; a non-empty list makes the command exit 4.
std::vector<std::string> FitProblems(const std::vector<ConditionFits>& conds) {
  std::vector<std::string> out;
  auto check = [&](const std::string& what, const RollerRigFit& f) {
    if (!f.converged) out.push_back(what + ": not converged (" + std::to_string(f.iterations) + " iterations)");
    if (f.parameters > f.data_points)
      out.push_back(what + ": " + std::to_string(f.parameters) + " parameters for " + std::to_string(f.data_points) +
                    " measured numbers (underdetermined: more tests of the condition needed)");
  };
  for (const ConditionFits& cf : conds) {
    check("section 2.1, " + cf.condition + " law", cf.shared);
    for (const RollerRigFit& f : cf.per_test) check("section 2.2, " + f.label, f);
    for (size_t i = 0; i < cf.sensitivity.size(); ++i)
      check("section 2.3, " + cf.condition + " law at steady creepage " + Fmt("%.2f", kSensitivityCreepages[i]),
            cf.sensitivity[i]);
    for (const RollerRigFit& f : cf.variants)
      check("section 2.4, " + cf.condition + " law " + to_string(f.law.variant) +
                (f.parameters > RollerRigLawParameterCount(f.law.variant) ? " (steady creepage fitted)" : ""),
            f);
    for (size_t i = 0; i < cf.chosen_sensitivity.size(); ++i)
      check("section 2.5, " + cf.condition + " law " + to_string(cf.chosen_sensitivity[i].law.variant) +
                " at steady creepage " + Fmt("%.2f", kSensitivityCreepages[i]),
            cf.chosen_sensitivity[i]);
  }
  return out;
}

// §2.1-2.3 of one condition into *out.
void FitConditionLaws(const std::vector<RollerRigAdhesionTest>& sub, const RollerRigAdhesionOptions& rig,
                      const RollerRigFitOptions& fit, const RigAdhesionArgs& a, ConditionFits* result) {
  ConditionFits& out = *result;
  std::fprintf(stderr, "rig-adhesion: fitting the %s law ...\n", out.condition.c_str());
  out.shared = FitRollerRigSharedLaw(sub, rig, fit);
  for (const auto& t : sub) out.per_test.push_back(FitRollerRigTestLaw(t, out.shared.law.decay_s_per_m, rig, fit));
  if (a.sensitivity)
    for (double xs : kSensitivityCreepages) {
      RollerRigFitOptions f2 = fit;
      f2.steady_creepage = xs;
      f2.peak_search_max = std::max(fit.peak_search_max, 1.5 * xs);
      std::fprintf(stderr, "rig-adhesion: sensitivity, steady creepage %.2f, %s ...\n", xs, out.condition.c_str());
      out.sensitivity.push_back(FitRollerRigSharedLaw(sub, rig, f2));
    }
}

// §2.4-2.5 of one condition into *out.
void FitConditionVariants(const std::vector<RollerRigAdhesionTest>& sub, const RollerRigAdhesionOptions& rig,
                          const RollerRigFitOptions& fit, const RigAdhesionArgs& a,
                          const std::vector<RollerRigLawVariant>& variants, RollerRigLawVariant chosen,
                          ConditionFits* result) {
  ConditionFits& out = *result;
  const RollerRigFitOptions& fv = fit;
  out.variants = FitVariantsOfCondition(sub, rig, fv, variants, chosen);
  if (a.sensitivity) {
    const RollerRigFit* at_option = nullptr;
    for (size_t i = 0; i < variants.size(); ++i)
      if (variants[i] == chosen) at_option = &out.variants[i];
    for (double xs : kSensitivityCreepages) {
      RollerRigFitOptions f2 = fv;
      f2.variant = chosen;
      f2.peak_before_steady = true;
      f2.steady_creepage = xs;
      f2.peak_search_max = std::max(fit.peak_search_max, 1.5 * xs);
      if (at_option) f2.extra_starts.push_back(at_option->law), f2.lm_from_grid = false;
      std::fprintf(stderr, "rig-adhesion: law %s at steady creepage %.2f, %s ...\n", to_string(chosen), xs,
                   out.condition.c_str());
      out.chosen_sensitivity.push_back(FitRollerRigSharedLaw(sub, rig, f2));
    }
  }
}

void WriteVariants(std::ostream& md, std::ostream& csv, const std::vector<VariantRun>& runs) {
  md << "| law | steady creepage | cond. | parameters / numbers | rms err [%] | largest err [%] | within 5 % | "
        "converged |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& r : runs)
    for (const auto& f : r.fits)
      md << "| " << to_string(r.variant) << " | " << (r.steady_fitted ? "fitted " : "") << Fmt("%.4f", f.steady_creepage)
         << " | " << f.label << " | " << f.parameters << " / " << f.data_points << " | "
         << Fmt("%.2f", f.rms_error_percent) << " | " << Fmt("%.2f", f.max_abs_error_percent) << " | "
         << f.within_5_percent << " of " << f.data_points << " | " << (f.converged ? "yes" : "NO") << " |\n";
  for (const auto& r : runs) {
    md << "\n#### " << to_string(r.variant) << (r.steady_fitted ? ", steady creepage fitted" : "") << "\n\n";
    for (const auto& f : r.fits) {
      md << "**" << f.label << "**: " << VariantLawText(f.law) << "; steady creepage " << Fmt("%.4f", f.steady_creepage)
         << "; rms error " << Fmt("%.2f", f.rms_error_percent) << " %, largest " << Fmt("%.2f", f.max_abs_error_percent)
         << " % (" << f.parameters << " parameters for " << f.data_points << " numbers; " << f.iterations
         << " iterations, " << (f.converged ? "converged" : "NOT converged") << ")\n\n";
      WriteFitTable(md, f.tests);
      md << "\n";
      for (const auto& m : f.tests) {
        char row[640];
        std::snprintf(row, sizeof row,
                      "%s,%d,%d,%s,%d,%d,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f,%.4f,%d\n",
                      to_string(r.variant), r.steady_fitted ? 1 : 0, m.measured.test, m.measured.condition.c_str(),
                      f.parameters, f.data_points, f.law.mu_static, f.law.sliding_ratio, f.law.decay_s_per_m,
                      f.law.speed_exponent, f.law.speed_scale_m_per_s, f.law.slip_area_ratio, f.steady_creepage,
                      m.slope_reduction, m.peak_creepage, m.measured.max_adhesion, m.model_max,
                      m.measured.steady_adhesion, m.model_steady, m.max_error_percent, m.steady_error_percent,
                      f.converged ? 1 : 0);
        csv << row;
      }
    }
  }
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
  // bad names fail before any fit
  const std::vector<RollerRigLawVariant> variants = SelectedVariants(a.variants);
  const RollerRigLawVariant chosen = ParseRollerRigLawVariant(a.law);
  const RollerRigCurvatures c = RollerRigCentredCurvatures(rig);
  const RollerRigCurvatures alt = RollerRigCentredCurvatures(alt_rig);
  EnsureOutputFolder(a.out, "--out");
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
  // dry and wet in parallel (independent fits; the same results as one after the other)
  // Four independent jobs (per condition: §2.1-2.3, §2.4-2.5), the longest first, on two worker threads; each job
  // writes its own fields, so the results do not depend on the scheduling.
  std::vector<std::vector<RollerRigAdhesionTest>> subs;
  std::vector<ConditionFits> conds;
  for (const std::string cond : {"dry", "wet"}) {
    auto sub = OfCondition(tests, cond);
    if (sub.empty()) continue;
    conds.emplace_back().condition = cond;
    subs.push_back(std::move(sub));
  }
  std::vector<std::function<void()>> jobs;
  for (size_t i = conds.size(); i-- > 0;)  // wet before dry (the wet fits take more iterations)
    jobs.push_back([&, i]() { FitConditionVariants(subs[i], rig, fit, a, variants, chosen, &conds[i]); });
  for (size_t i = conds.size(); i-- > 0;)
    jobs.push_back([&, i]() { FitConditionLaws(subs[i], rig, fit, a, &conds[i]); });
  std::atomic<size_t> next{0};
  std::vector<std::exception_ptr> errors(jobs.size());
  auto worker = [&]() {
    for (size_t j; (j = next++) < jobs.size();) try {
        jobs[j]();
      } catch (...) {
        errors[j] = std::current_exception();
      }
  };
  {
    std::thread helper(worker);
    worker();
    helper.join();
  }
  for (const auto& e : errors)
    if (e) std::rethrow_exception(e);
  for (const ConditionFits& cf : conds) {
    const RollerRigFit& f = cf.shared;
    md << "**" << cf.condition << "**: " << LawText(f.law) << "; rms error " << Fmt("%.2f", f.rms_error_percent)
       << " %, largest " << Fmt("%.2f", f.max_abs_error_percent) << " % (" << f.iterations << " iterations, "
       << (f.converged ? "converged" : "NOT converged") << ")\n\n";
    WriteFitTable(md, f.tests);
    md << "\n";
    CsvFitRows(fits, "shared_" + cf.condition, f);
  }
  md << "### 2.2 One law per test (mu_s and A per test, B of its condition: 2 parameters for 2 numbers, an "
        "identification)\n\n| test | cond. | mu_s | A | mu_inf | B [s/m] | k | max err [%] | steady err [%] | converged |\n"
        "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& t : tests) {
    for (const ConditionFits& cf : conds)
      for (const RollerRigFit& f : cf.per_test) {
        const RollerRigTestModel& m = f.tests.front();
        if (m.measured.test != t.test) continue;
        const double B = cf.shared.law.decay_s_per_m;
        md << "| " << t.test << " | " << t.condition << " | " << Fmt("%.4f", f.law.mu_static) << " | "
           << Fmt("%.4f", f.law.sliding_ratio) << " | " << Fmt("%.4f", f.law.mu_static * f.law.sliding_ratio)
           << " | " << Fmt("%.4f", B) << " | " << Fmt("%.4f", m.slope_reduction) << " | "
           << Fmt("%+.3f", m.max_error_percent) << " | " << Fmt("%+.3f", m.steady_error_percent) << " | "
           << (f.converged ? "yes" : "no") << " |\n";
        CsvFitRows(fits, "test_" + std::to_string(t.test), f);
      }
  }
  if (a.sensitivity) {
    md << "\n### 2.3 Sensitivity of the per-condition fit to the assumed steady creepage\n\n"
          "| steady creepage | cond. | mu_s | A | B [s/m] | rms err [%] | largest err [%] |\n|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < std::size(kSensitivityCreepages); ++i)
      for (const ConditionFits& cf : conds) {
        const RollerRigFit& f = cf.sensitivity[i];
        md << "| " << kSensitivityCreepages[i] << " | " << cf.condition << " | " << Fmt("%.4f", f.law.mu_static)
           << " | " << Fmt("%.4f", f.law.sliding_ratio) << " | " << Fmt("%.4f", f.law.decay_s_per_m) << " | "
           << Fmt("%.2f", f.rms_error_percent) << " | " << Fmt("%.2f", f.max_abs_error_percent) << " |\n";
      }
  }
  if (!variants.empty()) {
    std::ofstream vcsv(a.out + "/rig_adhesion_variants.csv");
    if (!vcsv) throw InputError(a.out + "/rig_adhesion_variants.csv: cannot be written");
    vcsv << "law,steady_fitted,test,condition,parameters,data_points,mu_static,sliding_ratio_A,decay_B_s_per_m,"
            "speed_exponent_n,speed_scale_V0_m_per_s,slip_area_ratio_kS_over_kA,steady_creepage,slope_reduction_k,"
            "peak_creepage,max_measured,max_model,steady_measured,steady_model,max_error_percent,steady_error_percent,"
            "converged\n";
    std::vector<VariantRun> runs;
    size_t index = 0;  // position in ConditionFits::variants (the order of FitVariantsOfCondition)
    for (bool steady_fitted : {false, true})
      for (RollerRigLawVariant v : variants) {
        if (steady_fitted && !FitSteadyCreepageOf(v, chosen)) continue;
        VariantRun run{v, steady_fitted, {}};
        for (const ConditionFits& cf : conds) run.fits.push_back(cf.variants[index]);
        runs.push_back(run);
        ++index;
      }
    md << "\n### 2.4 Law variants of the per-condition fit (docs/physics-reference.md §7.5)\n\n"
          "One law per condition, k per test from its slope (not counted), V_ref = "
       << kRollerRigReferenceSpeed
       << " m/s. slip_velocity: FASTSIM, mu(w) = mu_s [A + (1 - A) exp(-B w)] (the law of §2.1); curtius_kniffler: "
          "mu_s(V) = mu_s g(V)/g(V_ref), g(V) = 0.161 + 7.5/(3.6 V + 44) (published shape, no parameter added); "
          "speed_power: mu_s(V) = mu_s (V/V_ref)^(-n); speed_hyperbolic: mu_s(V) = mu_s (V_ref + V_0)/(V + V_0); "
          "polach_analytic: Polach's analytic creep force, k_A = k_S = k, mu at w = xi V; polach_extended: the same "
          "with k_S/k_A fitted, (k_A + k_S)/2 = k. Model max = the largest value of the curve up to the steady creepage. "
          "\"steady creepage fitted\" (slip_velocity, the chosen law --law, Polach's): one more parameter per "
          "condition, bounded to [0.02, 0.5], Levenberg-Marquardt from the law's optimum at the fixed creepage (a "
          "local refinement; Polach's laws also from their start grid, the better kept). Laws with a rolling-speed parameter start from the slip_velocity "
          "optimum (and their grid: the chosen law only), polach_extended from polach_analytic (and its grid), so "
          "they cannot end above them.\n\n";
    WriteVariants(md, vcsv, runs);
  }
  if (a.sensitivity && !conds.empty() && !conds.front().chosen_sensitivity.empty()) {
    md << "\n### 2.5 The chosen law (" << to_string(chosen) << ", option --law) at other steady creepages\n\n"
          "| steady creepage | cond. | law | parameters / numbers | rms err [%] | largest err [%] | within 5 % |\n"
          "|---|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < std::size(kSensitivityCreepages); ++i)
      for (const ConditionFits& cf : conds) {
        const RollerRigFit& f = cf.chosen_sensitivity[i];
        md << "| " << kSensitivityCreepages[i] << " | " << cf.condition << " | " << VariantLawText(f.law) << " | "
           << f.parameters << " / " << f.data_points << " | " << Fmt("%.2f", f.rms_error_percent) << " | "
           << Fmt("%.2f", f.max_abs_error_percent) << " | " << f.within_5_percent << " of " << f.data_points
           << " |\n";
      }
  }
  md << "\n## 3. Similitude of the 1:5 rig (docs/physics-reference.md §7.6)\n\n";
  WriteSimilitude(md, rig, c);
  const std::vector<std::string> problems = FitProblems(conds);
  if (!problems.empty()) {
    md << "\n## Fits without a result\n\n";
    for (const std::string& p : problems) md << "- " << p << "\n";
  }
  std::printf("rig-adhesion: %zu tests -> %s/report.md, rig_adhesion_slopes.csv, rig_adhesion_fit.csv\n", tests.size(),
              a.out.c_str());
  if (!problems.empty()) {
    std::string what = std::to_string(problems.size()) + " fit(s) without a result (report.md, 'Fits without a "
                       "result'); the first: " + problems.front();
    throw IncompleteResult(ExitCode::NotConverged, what);
  }
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
  sub->add_option("--variants", a->variants,
                  "law variants of the per-condition fit (section 2.4): all (default), none, or a comma list of "
                  "slip_velocity, curtius_kniffler, speed_power, speed_hyperbolic, polach_analytic, polach_extended");
  sub->add_option("--law", a->law, "the chosen law (section 2.5: other steady creepages; default speed_power)");
  sub->add_flag("--sensitivity,!--no-sensitivity", a->sensitivity, "run the steady-creepage sensitivity fits (default on)");
  sub->callback([a]() { Run(*a); });
}

}  // namespace conforma::cli
