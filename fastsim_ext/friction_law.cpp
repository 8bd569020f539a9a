// Friction laws of paper 002 §2.2 (eqs. 6-8) and the slope reduction of §2.3 (eq. 9).
#include <cmath>
#include <sstream>
#include <string>

#include "conforma/error.hpp"
#include "conforma/friction_law.hpp"

namespace conforma {

const char* to_string(FrictionLawKind kind) {
  switch (kind) {
    case FrictionLawKind::Constant: return "constant";
    case FrictionLawKind::F1aExponential: return "f1a";
    case FrictionLawKind::F1bPiecewise: return "f1b";
    case FrictionLawKind::F2: return "f2";
  }
  return "unknown";
}

FrictionLaw FrictionLaw::Constant(double mu) { return {FrictionLawKind::Constant, {mu, 0.0, 0.0, 0.0}}; }
FrictionLaw FrictionLaw::F1a(double mu_o, double alpha, double beta) {
  return {FrictionLawKind::F1aExponential, {mu_o, alpha, beta, 0.0}};
}
FrictionLaw FrictionLaw::F1b(double mu_s, double mu_d, double gamma_c) {
  return {FrictionLawKind::F1bPiecewise, {mu_s, mu_d, gamma_c, 0.0}};
}
FrictionLaw FrictionLaw::F2(double mu_s, double alpha, double mu_d, double beta) {
  return {FrictionLawKind::F2, {mu_s, alpha, mu_d, beta}};
}

int FrictionLaw::parameter_count() const {
  switch (kind) {
    case FrictionLawKind::Constant: return 1;
    case FrictionLawKind::F1aExponential: return 3;
    case FrictionLawKind::F1bPiecewise: return 3;
    case FrictionLawKind::F2: return 4;
  }
  return 0;
}

double FrictionLaw::operator()(double gamma) const {
  const auto& q = parameters;
  switch (kind) {
    case FrictionLawKind::Constant: return q[0];
    case FrictionLawKind::F1aExponential: return q[0] * (q[1] + (1.0 - q[1]) * std::exp(-q[2] * gamma));  // eq. 6
    case FrictionLawKind::F1bPiecewise:                                                                  // eq. 7
      return gamma <= q[2] ? q[0] - (q[0] - q[1]) * gamma / q[2] : q[1];
    case FrictionLawKind::F2: return q[0] * std::exp(-q[1] * gamma) + q[2] * (1.0 - std::exp(-q[3] * gamma));  // eq. 8
  }
  return 0.0;
}

double FrictionLaw::derivative(double gamma) const {
  const auto& q = parameters;
  switch (kind) {
    case FrictionLawKind::Constant: return 0.0;
    case FrictionLawKind::F1aExponential: return -q[0] * (1.0 - q[1]) * q[2] * std::exp(-q[2] * gamma);
    case FrictionLawKind::F1bPiecewise: return gamma < q[2] ? -(q[0] - q[1]) / q[2] : 0.0;
    case FrictionLawKind::F2: return -q[0] * q[1] * std::exp(-q[1] * gamma) + q[2] * q[3] * std::exp(-q[3] * gamma);
  }
  return 0.0;
}

void FrictionLaw::validate() const {
  const int n = parameter_count();
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(parameters[i]) || parameters[i] < 0.0)
      throw InputError(std::string("FrictionLaw ") + to_string(kind) + ": parameter " + std::to_string(i) +
                       " must be finite and >= 0 (got " + MessageNumber(parameters[i]) + ")");
  if (kind == FrictionLawKind::F1aExponential && parameters[1] > 1.0)
    throw InputError("FrictionLaw f1a: alpha must be in [0, 1]");
  if (kind == FrictionLawKind::F1bPiecewise && !(parameters[2] > 0.0))
    throw InputError("FrictionLaw f1b: gamma_c must be > 0");
}

std::string FrictionLaw::describe() const {
  std::ostringstream out;
  out << to_string(kind) << "(";
  for (int i = 0; i < parameter_count(); ++i) out << (i ? ", " : "") << parameters[i];
  out << ")";
  return out.str();
}

FastsimFlexibilities ReducedFlexibilities(const FastsimFlexibilities& flexibilities, double slope_reduction) {
  require_positive(slope_reduction, "slope_reduction");
  return {flexibilities.L1 / slope_reduction, flexibilities.L2 / slope_reduction,
          flexibilities.L3 / slope_reduction};  // paper 002 eq. 9: L* = L / k
}

}  // namespace conforma
