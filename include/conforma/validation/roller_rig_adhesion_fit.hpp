#pragma once
// Identification of a slip-velocity-dependent friction law from the three numbers paper 000 Table 6 gives per test
// (maximum and steady adhesion coefficient, initial slope); docs/physics-reference.md §7.5.
//
// Model of a test: FASTSIM creep curve on the rig ellipse (roller_rig_adhesion.hpp) with
//   * slope reduction k = measured slope / (G a b C11): FASTSIM's initial slope is k G a b C11 (paper 002 eq. 9), so
//     k reproduces the measured slope exactly (fitted, not predicted);
//   * the exponential law of the slip velocity w = gamma V (Polach 2005, §7.1): mu(w) = mu_s [A + (1 - A) e^(-B w)],
//     i.e. paper 002's f1a with mu_o = mu_s, alpha = A, beta = B V (V: the reference roller's surface speed);
//   * "maximum" = the peak of the creep curve, "steady" = the curve at steady_creepage (after the peak; the measured
//     curves, Figs. 5-8, are not tabulated, so this creepage is an assumption, an option).
// Two fits:
//   SharedLaw: one law (mu_s, A, B) per condition (dry / wet) for all its tests, k per test from its slope; 2 numbers
//              per test, 3 parameters per condition: the residuals test whether one slip-velocity law explains the
//              speed and load dependence of the measured max and steady values (5 degrees of freedom per condition).
//   PerTest:   mu_s and A per test with B of its condition's shared fit: 2 numbers, 2 parameters, exactly determined
//              (residuals ~ 0 by construction: an identification, not a validation).
// Law variants of the SharedLaw fit (RollerRigLawVariant; docs/physics-reference.md §7.5, table of variants): the
// static level may depend on the rolling speed V (wet adhesion falls with the speed: a water film entrained by
// rolling), and Polach's analytic model with k_A != k_S replaces FASTSIM; the steady creepage may be a fitted
// parameter (counted as one).
#include <string>
#include <vector>

#include "conforma/validation/roller_rig_adhesion.hpp"

namespace conforma {

// The model of a test under a shared law (parameters fitted per condition in brackets):
//   SlipVelocity:    FASTSIM, mu(w) = mu_s [A + (1 - A) e^(-B w)]                         (mu_s, A, B)
//   CurtiusKniffler: as SlipVelocity with mu_s(V) = mu_s g(V) / g(V_ref), g the published Curtius-Kniffler shape
//                    g(V) = 0.161 + 7.5 / (3.6 V + 44) (V in m/s; 3.6 V in km/h)              (mu_s, A, B)
//   SpeedPower:      mu_s(V) = mu_s (V / V_ref)^(-n)                                      (mu_s, n, A, B)
//   SpeedHyperbolic: mu_s(V) = mu_s (V_ref + V_0) / (V + V_0)  (the form C / (V + V_0))   (mu_s, V_0, A, B)
//   PolachAnalytic:  Polach's analytic creep force (roller_rig_polach.hpp) instead of FASTSIM, k_A = k_S = k,
//                    mu = mu(w) at the rigid slip velocity w = xi V (Polach 2005)          (mu_s, A, B)
//   PolachExtended:  as PolachAnalytic with k_S / k_A fitted, (k_A + k_S)/2 = k             (mu_s, A, B, k_S/k_A)
// V_ref = kRollerRigReferenceSpeed: mu_s of the speed-dependent variants is the static level at V_ref.
enum class RollerRigLawVariant {
  SlipVelocity,     // FASTSIM with the slip-velocity law (above)
  CurtiusKniffler,  // static level with the Curtius-Kniffler speed shape
  SpeedPower,       // static level ~ V^(-n)
  SpeedHyperbolic,  // static level ~ 1 / (V + V_0)
  PolachAnalytic,   // Polach's analytic creep force, k_A = k_S
  PolachExtended    // Polach's analytic creep force, k_S / k_A fitted
};
constexpr double kRollerRigReferenceSpeed = 10.0;  // m/s
// "slip_velocity", "curtius_kniffler", "speed_power", "speed_hyperbolic", "polach_analytic", "polach_extended"
const char* to_string(RollerRigLawVariant variant);
RollerRigLawVariant ParseRollerRigLawVariant(const std::string& name);  // InputError for an unknown name
std::vector<RollerRigLawVariant> AllRollerRigLawVariants();
int RollerRigLawParameterCount(RollerRigLawVariant variant);  // fitted law parameters (steady creepage excluded)

struct RollerRigLaw {
  RollerRigLawVariant variant = RollerRigLawVariant::SlipVelocity;
  double mu_static = 0.5;         // mu_s (w = 0; at V_ref for the speed-dependent variants)
  double sliding_ratio = 0.7;     // A = mu_inf / mu_s, in [0, 1]
  double decay_s_per_m = 0.5;     // B, s/m, >= 0
  double speed_exponent = 0.0;    // n (SpeedPower)
  double speed_scale_m_per_s = 1.0;  // V_0 (SpeedHyperbolic), > 0
  double slip_area_ratio = 1.0;   // k_S / k_A (PolachExtended), in (0, 1]
  double StaticLevel(double rolling_speed_m_per_s) const;         // mu_s(V)
  FrictionLaw ToFrictionLaw(double rolling_speed_m_per_s) const;  // f1a(mu_s(V), A, B V)
};

// validate(): InputError for a value out of the ranges given.
struct RollerRigFitOptions {
  double steady_creepage = 0.10;     // creepage at which the "steady" coefficient is taken, > 0
  double peak_search_max = 0.30;     // the peak is searched on (1e-4, peak_search_max], > steady_creepage
  int peak_grid_points = 40;         // log-spaced grid before the golden-section refinement, >= 8
  int max_iterations = 60;           // Levenberg-Marquardt iterations
  RollerRigLawVariant variant = RollerRigLawVariant::SlipVelocity;  // SharedLaw fit: the law
  bool fit_steady_creepage = false;  // SharedLaw fit: steady_creepage a fitted parameter in [0.02, 0.5]
  // The model maximum is the largest value of the curve up to the steady creepage (the measured maximum precedes the
  // steady value); false: the peak on (1e-4, peak_search_max] (the definition of the fits of §2.1-2.3 of the report,
  // kept for their figures; their peaks lie below the steady creepage, where both definitions agree).
  bool peak_before_steady = false;
  // SharedLaw fit: further starting laws for Levenberg-Marquardt (e.g. the optimum of a variant nested in this one,
  // so that the fit can only improve on it); their mu_s, A, B are taken, the variant's own parameter from a law of
  // the same variant, else its neutral value (n = 0, V_0 = 1000 m/s, k_S/k_A = 0.9); the steady creepage starts at
  // steady_creepage. LM runs from each of them and, if lm_from_grid, from the best point of its own start grid; the
  // lowest cost wins.
  std::vector<RollerRigLaw> extra_starts;
  bool lm_from_grid = true;
  void validate() const;
};

// One test under a law: the model curve's peak and steady value, and the errors against Table 6.
struct RollerRigTestModel {
  RollerRigAdhesionTest measured;
  RollerRigLinearContact linear;        // Kalker's linear theory at the test load
  double rolling_speed_m_per_s = 0.0;   // V of the reference roller
  double slope_reduction = 1.0;         // k = measured slope / G a b C11
  RollerRigLaw law;
  double peak_creepage = 0.0;           // creepage of the model peak
  double model_max = 0.0;               // peak of -F_x/N
  double model_steady = 0.0;            // -F_x/N at steady_creepage
  double max_error_percent = 0.0;       // (model - measured) / measured * 100
  double steady_error_percent = 0.0;
};

// The model of one test (k from its slope) under `law`; curvatures = RollerRigCentredCurvatures(rig).
RollerRigTestModel EvaluateRollerRigTest(const RollerRigAdhesionTest& test, const RollerRigAdhesionOptions& rig,
                                         const RollerRigCurvatures& curvatures, const RollerRigLaw& law,
                                         const RollerRigFitOptions& fit);

struct RollerRigFit {
  std::string label;                     // condition ("dry", "wet") or "test N"
  RollerRigLaw law;                      // identified (per-test fits: B is the condition's)
  std::vector<RollerRigTestModel> tests; // the tests of the fit under the law
  double steady_creepage = 0.0;          // creepage of the steady values (fitted or the option)
  int parameters = 0;                    // fitted parameters of the fit (per-test k from the slopes not counted)
  int data_points = 0;                   // 2 x tests (max and steady)
  int within_5_percent = 0;              // numbers reproduced within 5 %
  double rms_error_percent = 0.0;        // rms of all max and steady errors
  double max_abs_error_percent = 0.0;
  int iterations = 0;
  bool converged = false;                // the step or the cost change fell below tolerance
};

// SharedLaw fit of the tests (all of one condition) with the law fit.variant. InputError for an empty list.
RollerRigFit FitRollerRigSharedLaw(const std::vector<RollerRigAdhesionTest>& tests, const RollerRigAdhesionOptions& rig,
                                   const RollerRigFitOptions& fit);
// PerTest fit: mu_s and A of one test at the given B.
RollerRigFit FitRollerRigTestLaw(const RollerRigAdhesionTest& test, double decay_s_per_m,
                                 const RollerRigAdhesionOptions& rig, const RollerRigFitOptions& fit);

}  // namespace conforma
