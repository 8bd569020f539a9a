// Published track irregularity PSDs and their exact band integrals (track_irregularity_psd.hpp;
// docs/physics-reference.md §15.1).
#include "conforma/track_irregularity_psd.hpp"

#include <cmath>
#include <string>

#include "conforma/error.hpp"

namespace conforma {

namespace {

struct NamedSpectrum {
  IrregularitySpectrum spectrum;
  const char* name;
};
constexpr NamedSpectrum kNames[] = {
    {IrregularitySpectrum::OreB176Low, "ore_b176_low"}, {IrregularitySpectrum::OreB176High, "ore_b176_high"},
    {IrregularitySpectrum::FraClass1, "fra_class_1"},   {IrregularitySpectrum::FraClass2, "fra_class_2"},
    {IrregularitySpectrum::FraClass3, "fra_class_3"},   {IrregularitySpectrum::FraClass4, "fra_class_4"},
    {IrregularitySpectrum::FraClass5, "fra_class_5"},   {IrregularitySpectrum::FraClass6, "fra_class_6"},
};

// ORE B176 (§15.1 eqs. 15.1-15.2)
constexpr double kOreOmegaC = 0.8246, kOreOmegaR = 0.0206, kOreOmegaS = 0.4380;  // rad/m
constexpr double kOreHalfRailDistance = 0.75;                                   // b, m
// FRA (§15.1 eq. 15.3); A in cm^2 rad/m, converted with 1e-4 m^2/cm^2
constexpr double kFraK = 0.25, kFraOmegaC = 0.8245;
constexpr double kFraAlignment[6] = {3.3634, 1.2107, 0.4128, 0.3027, 0.0762, 0.0339};
constexpr double kFraLevel[6] = {1.2107, 1.0181, 0.6816, 0.5376, 0.2095, 0.0339};

bool IsOre(IrregularitySpectrum s) {
  return s == IrregularitySpectrum::OreB176Low || s == IrregularitySpectrum::OreB176High;
}

// Roughness coefficient A (m rad for ORE, m^2 rad/m for FRA, k included) of a component.
double Roughness(IrregularitySpectrum s, IrregularityComponent c) {
  const bool level = c != IrregularityComponent::Alignment;  // cross-level scales with the level coefficient
  if (s == IrregularitySpectrum::OreB176Low) return level ? 4.032e-7 : 2.119e-7;
  if (s == IrregularitySpectrum::OreB176High) return level ? 1.080e-6 : 6.125e-7;
  if (c == IrregularityComponent::CrossLevel)
    throw InputError(std::string("irregularity spectrum ") + to_string(s) + ": no cross-level PSD (FRA classes "
                     "give alignment and vertical level only)");
  const int i = static_cast<int>(s) - static_cast<int>(IrregularitySpectrum::FraClass1);
  return kFraK * 1e-4 * (level ? kFraLevel[i] : kFraAlignment[i]);
}

void CheckOmega(double omega, const char* what) {
  if (!(omega > 0.0) || !std::isfinite(omega))
    throw InputError(std::string("irregularity PSD: ") + what + " must be a finite wavenumber > 0 rad/m, got " +
                     MessageNumber(omega));
}

// Antiderivative of 1 / (Omega^2 + a^2) (a > 0).
double AtanTerm(double omega, double a) { return std::atan(omega / a) / a; }

// Antiderivative of the PSD (the band integral is its difference).
double PsdAntiderivative(IrregularitySpectrum s, IrregularityComponent c, double omega) {
  const double A = Roughness(s, c);
  if (!IsOre(s)) {  // k A Omega_c^2 / (Omega^2 (Omega^2 + Omega_c^2)) = k A (1/Omega^2 - 1/(Omega^2 + Omega_c^2))
    return A * (-1.0 / omega - AtanTerm(omega, kFraOmegaC));
  }
  const double rc = kOreOmegaC * kOreOmegaC, rr = kOreOmegaR * kOreOmegaR;
  if (c != IrregularityComponent::CrossLevel) {
    // A Omega_c^2 / ((u + r)(u + c)) = A Omega_c^2 / (c - r) (1/(u + r) - 1/(u + c)), u = Omega^2
    return A * rc / (rc - rr) * (AtanTerm(omega, kOreOmegaR) - AtanTerm(omega, kOreOmegaC));
  }
  // (A / b^2) Omega_c^2 u / ((u + r)(u + c)(u + s)) = (A / b^2) Omega_c^2 sum_k alpha_k / (u + k),
  // alpha_k = -k / prod_{j != k} (j - k)
  const double rs = kOreOmegaS * kOreOmegaS;
  const double ar = -rr / ((rc - rr) * (rs - rr));
  const double ac = -rc / ((rr - rc) * (rs - rc));
  const double as = -rs / ((rr - rs) * (rc - rs));
  const double scale = A / (kOreHalfRailDistance * kOreHalfRailDistance) * rc;
  return scale * (ar * AtanTerm(omega, kOreOmegaR) + ac * AtanTerm(omega, kOreOmegaC) + as * AtanTerm(omega, kOreOmegaS));
}

}  // namespace

bool HasCrossLevelSpectrum(IrregularitySpectrum spectrum) { return IsOre(spectrum); }

const char* to_string(IrregularitySpectrum spectrum) {
  for (const NamedSpectrum& n : kNames)
    if (n.spectrum == spectrum) return n.name;
  return "unknown";
}

IrregularitySpectrum ParseIrregularitySpectrum(const std::string& name) {
  std::string names;
  for (const NamedSpectrum& n : kNames) {
    if (name == n.name) return n.spectrum;
    names += names.empty() ? "" : ", ";
    names += n.name;
  }
  throw InputError("unknown irregularity spectrum '" + name + "' (one of: " + names + ")");
}

double IrregularityPsd(IrregularitySpectrum s, IrregularityComponent c, double omega) {
  CheckOmega(omega, "Omega");
  const double A = Roughness(s, c);
  const double u = omega * omega;
  if (!IsOre(s)) return A * kFraOmegaC * kFraOmegaC / (u * (u + kFraOmegaC * kFraOmegaC));  // eq. 15.3
  const double rc = kOreOmegaC * kOreOmegaC, rr = kOreOmegaR * kOreOmegaR;
  const double base = A * rc / ((u + rr) * (u + rc));                                     // eq. 15.1
  if (c != IrregularityComponent::CrossLevel) return base;
  return base / (kOreHalfRailDistance * kOreHalfRailDistance) * u / (u + kOreOmegaS * kOreOmegaS);  // eq. 15.2
}

double IrregularityBandVariance(IrregularitySpectrum s, IrregularityComponent c, double omega_min, double omega_max) {
  CheckOmega(omega_min, "omega_min");
  CheckOmega(omega_max, "omega_max");
  if (omega_max < omega_min)
    throw InputError("irregularity band: omega_max " + MessageNumber(omega_max) + " < omega_min " +
                     MessageNumber(omega_min));
  return PsdAntiderivative(s, c, omega_max) - PsdAntiderivative(s, c, omega_min);
}

}  // namespace conforma
