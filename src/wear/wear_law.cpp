#include "conforma/wear_law.hpp"

#include <algorithm>
#include <cmath>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(WearRegime regime) {
  switch (regime) {
    case WearRegime::Mild: return "mild";
    case WearRegime::Severe: return "severe";
    case WearRegime::Catastrophic: return "catastrophic";
  }
  return "?";
}

const char* to_string(WearLawKind kind) { return kind == WearLawKind::WearIndex ? "wear_index" : "archard"; }

WearRegime usfd_regime(double wear_index, const UsfdCoefficients& c) {
  if (wear_index < c.mild_limit_N_mm2) return WearRegime::Mild;
  if (wear_index <= c.severe_limit_N_mm2) return WearRegime::Severe;
  return WearRegime::Catastrophic;
}

// docs/physics-reference.md §8.1 / paper 003 eq. 15
double usfd_wear_rate(double wear_index, const UsfdCoefficients& c) {
  require_non_negative(wear_index, "wear index I_w");
  switch (usfd_regime(wear_index, c)) {
    case WearRegime::Mild: return c.mild_slope * wear_index;
    case WearRegime::Severe: return c.severe_rate;
    case WearRegime::Catastrophic: return std::max(0.0, c.catastrophic_slope * wear_index + c.catastrophic_intercept);
  }
  return 0.0;
}

// paper 003 eq. 14: I_w = p_t . s (Pa -> N/mm^2)
double wear_index_N_mm2(const Eigen::Vector2d& traction_Pa, const Eigen::Vector2d& slip) {
  if (!traction_Pa.allFinite()) throw InputError("wear index: tangential traction is not finite");
  if (!slip.allFinite()) throw InputError("wear index: slip is not finite");
  return std::abs(traction_Pa.dot(slip)) * 1e-6;
}

// paper 003 eqs. 16-17: depth = K_w / rho. K_w [ug/(mm^2 m)], rho [ug/mm^3] = rho [kg/m^3] numerically,
// so K_w / rho is in mm per metre rolled; * 1e-3 gives m per metre rolled.
double depth_per_rolled_metre_from_rate(double rate, double density_kg_m3) {
  require_non_negative(rate, "wear rate K_w");
  require_positive(density_kg_m3, "density_kg_m3");
  return rate / density_kg_m3 * 1e-3;
}

void WearIndexLaw::validate() const {
  const std::string who = "wear law '" + name + "'";
  if (points.size() < 2) throw InputError(who + ": needs at least 2 points");
  if (points.front().wear_index_N_mm2 != 0.0) throw InputError(who + ": the first point must be at I_w = 0");
  for (size_t k = 0; k < points.size(); ++k) {
    const auto& p = points[k];
    if (!std::isfinite(p.wear_index_N_mm2) || !std::isfinite(p.rate_ug_m_mm2))
      throw InputError(who + ": point " + std::to_string(k + 1) + " is not finite");
    if (k > 0 && p.wear_index_N_mm2 < points[k - 1].wear_index_N_mm2)
      throw InputError(who + ": wear index decreases at point " + std::to_string(k + 1));
    if (k > 1 && p.wear_index_N_mm2 == points[k - 2].wear_index_N_mm2)
      throw InputError(who + ": more than two points at one wear index (point " + std::to_string(k + 1) + ")");
  }
  if (points.back().wear_index_N_mm2 == points[points.size() - 2].wear_index_N_mm2)
    throw InputError(who + ": the table must not end with a jump (the last segment is extrapolated)");
}

double WearIndexLaw::rate(double wear_index) const {
  require_non_negative(wear_index, "wear index I_w");
  const size_t n = points.size();
  // first segment [k, k+1] with I_k < I_{k+1} and I <= I_{k+1}: at a jump I_j the left value applies.
  size_t k = 0;
  while (k + 2 < n && (wear_index > points[k + 1].wear_index_N_mm2 ||
                       points[k + 1].wear_index_N_mm2 == points[k].wear_index_N_mm2))
    ++k;
  const auto& a = points[k];
  const auto& b = points[k + 1];
  const double t = (wear_index - a.wear_index_N_mm2) / (b.wear_index_N_mm2 - a.wear_index_N_mm2);
  return std::max(0.0, a.rate_ug_m_mm2 + t * (b.rate_ug_m_mm2 - a.rate_ug_m_mm2));
}

WearIndexLaw WearIndexLaw::Usfd(const UsfdCoefficients& c) {
  WearIndexLaw law;
  law.name = "USFD (Lewis & Dwyer-Joyce 2004; Braghin et al. 2006)";
  const double i1 = c.mild_limit_N_mm2, i2 = c.severe_limit_N_mm2, i3 = 200.0;
  law.points = {{0.0, 0.0},
                {i1, c.mild_slope * i1},
                {i1, c.severe_rate},
                {i2, c.severe_rate},
                {i2, c.catastrophic_slope * i2 + c.catastrophic_intercept},
                {i3, c.catastrophic_slope * i3 + c.catastrophic_intercept}};
  return law;
}

void ArchardMap::validate() const {
  const std::string who = "Archard map '" + name + "'";
  require_positive(hardness_Pa, (who + ": hardness_Pa").c_str());
  require_positive(severe_pressure_ratio, (who + ": severe_pressure_ratio").c_str());
  if (bins.empty()) throw InputError(who + ": needs at least one velocity bin");
  for (size_t k = 0; k < bins.size(); ++k) {
    const auto& b = bins[k];
    const std::string at = who + ": bin " + std::to_string(k + 1);
    if (!(b.velocity_upper_m_s > 0.0)) throw InputError(at + ": velocity limit must be > 0");
    if (k > 0 && !(b.velocity_upper_m_s > bins[k - 1].velocity_upper_m_s))
      throw InputError(at + ": velocity limits must increase");
    if (!std::isfinite(b.k_mild) || b.k_mild < 0 || !std::isfinite(b.k_severe) || b.k_severe < 0)
      throw InputError(at + ": coefficients must be finite and >= 0");
  }
  if (!std::isinf(bins.back().velocity_upper_m_s)) throw InputError(who + ": the last bin must end at inf");
}

double ArchardMap::coefficient(double pressure_Pa, double sliding_velocity) const {
  require_non_negative(pressure_Pa, "pressure_Pa");
  require_non_negative(sliding_velocity, "sliding velocity");
  size_t k = 0;
  while (k + 1 < bins.size() && sliding_velocity > bins[k].velocity_upper_m_s) ++k;
  return pressure_Pa > severe_pressure_ratio * hardness_Pa ? bins[k].k_severe : bins[k].k_mild;
}

ArchardMap ArchardMap::Jendel() {
  ArchardMap m;
  m.name = "Jendel 2002 (paper 000 Table 2, mid-points of the ranges)";
  m.hardness_Pa = 2.75e9;
  const double inf = std::numeric_limits<double>::infinity();
  m.bins = {{0.2, 5.5e-4, 350e-4}, {0.7, 35e-4, 350e-4}, {inf, 5.5e-4, 350e-4}};
  return m;
}

ArchardMap ArchardMap::Paper000Wheel() {
  ArchardMap m;
  m.name = "paper 000 Table 3, wheel (scaled roller rig)";
  m.hardness_Pa = 100 * 9.80665e6;  // paper 000 Table 4: HB 100 (kgf/mm^2)
  const double inf = std::numeric_limits<double>::infinity(), s = 370e-4;
  m.bins = {{0.1, 1e-4, s},   {0.2, 3.6e-4, s}, {0.3, 8.5e-4, s}, {0.4, 29e-4, s},
            {0.5, 31.8e-4, s}, {0.7, 18e-4, s}, {inf, 1e-4, s}};
  return m;
}

ArchardMap ArchardMap::Paper000Roller() {
  ArchardMap m;
  m.name = "paper 000 Table 3, roller (scaled roller rig)";
  m.hardness_Pa = 160 * 9.80665e6;  // paper 000 Table 4: HB 160 (kgf/mm^2)
  const double inf = std::numeric_limits<double>::infinity(), s = 520e-4;
  m.bins = {{0.1, 2e-4, s},  {0.2, 7.8e-4, s}, {0.3, 13.3e-4, s}, {0.4, 48.2e-4, s},
            {0.5, 53e-4, s}, {0.7, 21.7e-4, s}, {inf, 2e-4, s}};
  return m;
}

WearLaw::WearLaw() : wear_index(WearIndexLaw::Usfd()), archard(ArchardMap::Jendel()) {}

void WearLaw::validate() const {
  if (kind == WearLawKind::WearIndex) wear_index.validate();
  else archard.validate();
}

double WearLaw::depth_per_rolled_metre(const Eigen::Vector2d& traction_Pa, const Eigen::Vector2d& slip,
                                       double pressure_Pa, double rolling_speed, const Material& material) const {
  require_non_negative(pressure_Pa, "pressure_Pa");
  if (kind == WearLawKind::WearIndex) {
    const double rate = wear_index.rate(wear_index_N_mm2(traction_Pa, slip));  // eqs. 14-15
    return depth_per_rolled_metre_from_rate(rate, material.density_kg_m3);       // eqs. 16-17
  }
  // paper 000 eqs. 8-10: U = k S p / H, sliding distance per metre rolled = |s|, v_slip = |s| V
  if (!slip.allFinite()) throw InputError("Archard wear: slip is not finite");
  require_non_negative(rolling_speed, "rolling_speed_m_s");
  const double slip_norm = slip.norm();
  const double k = archard.coefficient(pressure_Pa, slip_norm * rolling_speed);
  return k * pressure_Pa * slip_norm / archard.hardness_Pa;
}

}  // namespace conforma
