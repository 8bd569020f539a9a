// Linear stability and critical speed of the time-domain vehicle model (vehicle_dynamics_eigen.hpp).
#include "conforma/vehicle_dynamics_eigen.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>

#include "conforma/error.hpp"

namespace conforma {

void CriticalSpeedOptions::validate() const {
  require_positive(min_speed_m_s, "min_speed_m_s");
  require_positive(speed_step_m_s, "speed_step_m_s");
  require_positive(tolerance_m_s, "tolerance_m_s");
  require_non_negative(real_part_threshold, "real_part_threshold");
  if (!(max_speed_m_s > min_speed_m_s)) throw InputError("option 'max_speed_m_s' must be > min_speed_m_s");
}

LinearStabilityResult AnalyseLinearStability(const VehicleParameters& vehicle, const DynamicsModelOptions& model_options) {
  if (model_options.contact_kind != DynamicsContactKind::Linear)
    throw InputError("linear stability: the model options' contact_kind must be linear");
  const VehicleDynamicsModel model(vehicle, nullptr, TrackInput{}, model_options);
  const int n = model.state_size();
  LinearStabilityResult r;
  r.speed_m_s = model_options.speed_m_s;
  r.state_matrix.resize(n, n);
  std::vector<WheelsetDynamicsForces> f;
  Eigen::VectorXd fp, fm;
  const double h = 1e-3;
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    x[k] = h;
    model.Derivative(x, 0.0, &fp, &f, nullptr, nullptr);
    x[k] = -h;
    model.Derivative(x, 0.0, &fm, &f, nullptr, nullptr);
    r.state_matrix.col(k) = (fp - fm) / (2.0 * h);
  }
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(r.state_matrix, false);
  r.max_real_part = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const std::complex<double> s = solver.eigenvalues()[i];
    r.max_real_part = std::max(r.max_real_part, s.real());
    if (s.imag() < 0.0) continue;
    DynamicsMode m;
    m.eigenvalue = s;
    m.frequency_Hz = s.imag() / (2.0 * M_PI);
    m.damping_ratio = std::abs(s) > 0.0 ? -s.real() / std::abs(s) : 0.0;
    r.modes.push_back(m);
  }
  std::sort(r.modes.begin(), r.modes.end(), [](const DynamicsMode& a, const DynamicsMode& b) {
    return a.frequency_Hz != b.frequency_Hz ? a.frequency_Hz < b.frequency_Hz : a.eigenvalue.real() < b.eigenvalue.real();
  });
  return r;
}

CriticalSpeedResult FindCriticalSpeed(const VehicleParameters& vehicle, const DynamicsModelOptions& model_options,
                                      const CriticalSpeedOptions& options) {
  options.validate();
  CriticalSpeedResult out;
  DynamicsModelOptions o = model_options;
  auto unstable = [&](double V, double* frequency) {
    o.speed_m_s = V;
    const LinearStabilityResult r = AnalyseLinearStability(vehicle, o);
    ++out.evaluations;
    if (frequency) {
      double best = -std::numeric_limits<double>::infinity();
      for (const DynamicsMode& m : r.modes)
        if (m.eigenvalue.real() > best) best = m.eigenvalue.real(), *frequency = m.frequency_Hz;
    }
    return r.max_real_part > options.real_part_threshold;
  };
  if (unstable(options.min_speed_m_s, nullptr)) {
    out.unstable_at_min_speed = true;
    return out;
  }
  double lo = options.min_speed_m_s, hi = lo;
  bool bracketed = false;
  while (hi < options.max_speed_m_s) {
    hi = std::min(options.max_speed_m_s, lo + options.speed_step_m_s);
    if (unstable(hi, nullptr)) {
      bracketed = true;
      break;
    }
    lo = hi;
  }
  if (!bracketed) return out;
  while (hi - lo > options.tolerance_m_s) {
    const double mid = 0.5 * (lo + hi);
    (unstable(mid, nullptr) ? hi : lo) = mid;
  }
  out.found = true;
  out.critical_speed_m_s = hi;
  unstable(hi, &out.frequency_Hz);
  return out;
}

}  // namespace conforma
