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
#include <string>
#include <vector>

#include "conforma/validation/roller_rig_adhesion.hpp"

namespace conforma {

struct RollerRigLaw {
  double mu_static = 0.5;         // mu_s (w = 0)
  double sliding_ratio = 0.7;     // A = mu_inf / mu_s, in [0, 1]
  double decay_s_per_m = 0.5;     // B, s/m, >= 0
  FrictionLaw ToFrictionLaw(double rolling_speed_m_per_s) const;  // f1a(mu_s, A, B V)
};

// validate(): InputError for a value out of the ranges given.
struct RollerRigFitOptions {
  double steady_creepage = 0.10;     // creepage at which the "steady" coefficient is taken, > 0
  double peak_search_max = 0.30;     // the peak is searched on (1e-4, peak_search_max], > steady_creepage
  int peak_grid_points = 40;         // log-spaced grid before the golden-section refinement, >= 8
  int max_iterations = 60;           // Levenberg-Marquardt iterations
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
  double rms_error_percent = 0.0;        // rms of all max and steady errors
  double max_abs_error_percent = 0.0;
  int iterations = 0;
  bool converged = false;                // the step or the cost change fell below tolerance
};

// SharedLaw fit of the tests (all of one condition). InputError for an empty list.
RollerRigFit FitRollerRigSharedLaw(const std::vector<RollerRigAdhesionTest>& tests, const RollerRigAdhesionOptions& rig,
                                   const RollerRigFitOptions& fit);
// PerTest fit: mu_s and A of one test at the given B.
RollerRigFit FitRollerRigTestLaw(const RollerRigAdhesionTest& test, double decay_s_per_m,
                                 const RollerRigAdhesionOptions& rig, const RollerRigFitOptions& fit);

}  // namespace conforma
