// Step-function and power-law fits of the conformity threshold (threshold.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

#include "conforma/error.hpp"
#include "conforma/validation/threshold.hpp"

namespace conforma {

ThresholdFit FitConformityThreshold(const std::vector<ThresholdPoint>& points, double tolerance,
                                    double (*d_of)(const ThresholdPoint&)) {
  require_positive(tolerance, "tolerance");
  std::vector<std::pair<double, bool>> data;  // (alpha_c, exceeds)
  std::vector<std::pair<double, double>> log_data;
  for (const ThresholdPoint& p : points) {
    if (!p.valid) continue;
    const double d = d_of ? d_of(p) : p.d_max;
    if (!std::isfinite(d) || !std::isfinite(p.alpha_c_deg)) continue;
    data.push_back({p.alpha_c_deg, d > tolerance});
    if (p.alpha_c_deg >= 0.5 && d > 1e-4) log_data.push_back({std::log(p.alpha_c_deg), std::log(d)});
  }
  ThresholdFit fit;
  fit.points = static_cast<int>(data.size());
  std::sort(data.begin(), data.end());
  for (const auto& d : data) fit.exceeding += d.second;
  // Step fit: candidate alpha* = each data alpha (points at or above it are "conformal"), or +inf (none).
  // errors(alpha*_i) = exceeding points before i + non-exceeding points from i on.
  // Scanning upwards with a strict '<' keeps the FIRST (smallest) alpha* with the minimal count; alpha* = +inf
  // (no point is conformal) is taken only when it is strictly better than every finite candidate.
  int best = fit.points + 1;
  double best_alpha = std::numeric_limits<double>::infinity();
  int exceeding_before = 0, quiet_before = 0;
  const int quiet_total = fit.points - fit.exceeding;
  for (size_t i = 0; i < data.size(); ++i) {
    if (i == 0 || data[i].first != data[i - 1].first) {
      const int errors = exceeding_before + (quiet_total - quiet_before);
      if (errors < best) best = errors, best_alpha = data[i].first;
    }
    (data[i].second ? exceeding_before : quiet_before) += 1;
  }
  if (fit.exceeding < best) best = fit.exceeding, best_alpha = std::numeric_limits<double>::infinity();
  fit.misclassified = best;
  fit.threshold_deg = best_alpha;
  for (const auto& d : data)
    if (d.first < best_alpha) fit.bracket_low_deg = d.first;
  // Power law d = c alpha^k in log-log least squares.
  if (log_data.size() >= 3) {
    Eigen::MatrixXd A(log_data.size(), 2);
    Eigen::VectorXd b(log_data.size());
    for (size_t i = 0; i < log_data.size(); ++i) A(i, 0) = 1.0, A(i, 1) = log_data[i].first, b(i) = log_data[i].second;
    const Eigen::Vector2d x = A.colPivHouseholderQr().solve(b);
    fit.power_c = std::exp(x(0));
    fit.power_k = x(1);
    const Eigen::VectorXd r = b - A * x;
    const double mean = b.mean();
    const double ss_tot = (b.array() - mean).square().sum();
    fit.power_r2 = ss_tot > 0.0 ? 1.0 - r.squaredNorm() / ss_tot : 0.0;
    if (fit.power_k > 0.0) fit.power_threshold_deg = std::pow(tolerance / fit.power_c, 1.0 / fit.power_k);
  }
  return fit;
}

}  // namespace conforma
