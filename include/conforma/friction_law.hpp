#pragma once
// Local friction laws mu(gamma) of the dimensionless slip gamma = |s| (slip velocity / rolling speed), the slope
// reduction k, and the variable-friction FASTSIM kernel (paper 002: Gimenez et al., "Application of Fastsim with
// variable coefficient of friction using twin disc experimental measurements"; docs/physics-reference.md §7).
//
// Laws (paper 002 §2.2):
//   Constant      mu(gamma) = mu
//   F1aExponential mu(gamma) = mu_o [alpha + (1 - alpha) exp(-beta gamma)]                       (eq. 6)
//   F1bPiecewise  mu(gamma) = mu_s - (mu_s - mu_d) gamma / gamma_c  (gamma <= gamma_c), mu_d beyond (eq. 7)
//   F2            mu(gamma) = mu_s exp(-alpha gamma) + mu_d (1 - exp(-beta gamma))               (eq. 8)
// Slope reduction (paper 002 §2.3, eq. 9): every flexibility is divided by k, 0 < k <= 1 (values slightly above 1
// are accepted, as the paper identifies k = 1.07 on dry curves).
#include <array>
#include <string>

#include "conforma/fastsim.hpp"

namespace conforma {

// The laws above: Constant, F1aExponential (eq. 6), F1bPiecewise (eq. 7), F2 (eq. 8).
enum class FrictionLawKind { Constant, F1aExponential, F1bPiecewise, F2 };
const char* to_string(FrictionLawKind kind);  // "constant", "f1a", "f1b", "f2"

struct FrictionLaw {
  FrictionLawKind kind = FrictionLawKind::Constant;  // default: constant mu = 0.3
  // Parameters, in the order of the paper's equations:
  //   Constant: {mu}
  //   F1aExponential: {mu_o, alpha, beta}
  //   F1bPiecewise: {mu_s, mu_d, gamma_c}
  //   F2: {mu_s, alpha, mu_d, beta}
  // mu values dimensionless, rates alpha / beta per unit gamma (dimensionless), gamma_c dimensionless; unused
  // entries are ignored.
  std::array<double, 4> parameters{0.3, 0.0, 0.0, 0.0};

  static FrictionLaw Constant(double mu);
  static FrictionLaw F1a(double mu_o, double alpha, double beta);
  static FrictionLaw F1b(double mu_s, double mu_d, double gamma_c);
  static FrictionLaw F2(double mu_s, double alpha, double mu_d, double beta);

  int parameter_count() const;
  double operator()(double gamma) const;  // mu(gamma), gamma >= 0
  double derivative(double gamma) const;  // d mu / d gamma (right derivative at the kink of F1b)
  double static_value() const { return (*this)(0.0); }
  bool is_constant() const { return kind == FrictionLawKind::Constant; }
  // Throws InputError unless the parameters are finite and physical (mu >= 0, rates >= 0, gamma_c > 0,
  // 0 <= alpha <= 1 for F1a, mu(gamma) >= 0 everywhere).
  void validate() const;
  std::string describe() const;
};

// L_i / k for the three flexibilities (paper 002 eq. 9). Throws InputError unless k > 0.
FastsimFlexibilities ReducedFlexibilities(const FastsimFlexibilities& flexibilities, double slope_reduction);

// Variable-friction FASTSIM on a strip patch (paper 002 §2.1, docs/physics-reference.md §7.2). Same marching, patch,
// creepage and sign conventions as SolveFastsimStrips; only the traction bound differs:
//  * without recuperation of static friction (Piotrowski): along a strip the friction level does not come back,
//    mu_eff(gamma) = mu(max(gamma, gamma_memory)), gamma_memory = the largest slip reached so far on the strip
//    (0 at the leading edge); adhesion test |p_trial| <= mu_eff(0) p_n. Every adhesion/slip switch is then
//    continuous in the creepages and the law's parameters;
//  * slip elements: the slip modulus gamma solves gamma = |s(gamma)| with the slip of paper 002 eq. 5 (Gimenez et
//    al.): the previous traction is taken at the friction level of this element (p_prev mu(gamma)/mu_prev), so the
//    elastic part of the slip is mu(gamma) L dp_n/dx and falling laws do not run into the stick-slip branch;
//    p = mu(gamma) p_n p_trial / |p_trial|, s = L (p - p_trial) / h; regula falsi on a doubling bracket.
// A constant law gives the core's answer (to rounding). patch.friction_coefficient must be empty.
void SolveFastsimStripsVariableFriction(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                                        const FastsimCreepages& creepages, const FrictionLaw& law,
                                        double rolling_speed_m_per_s, const FastsimOptions& options,
                                        FastsimResult* result);

// Dispatch: constant law -> SolveFastsimStrips (the core), otherwise the variable-friction kernel.
void SolveFastsimStripsWithLaw(const FastsimPatch& patch, const FastsimFlexibilities& flexibilities,
                               const FastsimCreepages& creepages, const FrictionLaw& law,
                               double rolling_speed_m_per_s, const FastsimOptions& options, FastsimResult* result);

}  // namespace conforma
