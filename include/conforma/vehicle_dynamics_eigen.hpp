#pragma once
// Linear stability of the time-domain vehicle model on tangent track (docs/physics-reference.md §16.4): the state
// matrix A of the model with linear contact (vehicle_dynamics_linear_contact.hpp) at the centred state,
// dx/dt = A x, its eigenvalues s = sigma +/- i omega, the modes' frequencies omega / (2 pi) and damping ratios
// -sigma / |s|, and the critical speed: the lowest speed at which a mode's real part becomes positive (hunting),
// bracketed on a speed grid and refined by bisection.
#include <complex>
#include <vector>

#include <Eigen/Core>

#include "conforma/vehicle.hpp"
#include "conforma/vehicle_dynamics_model.hpp"

namespace conforma {

struct DynamicsMode {
  std::complex<double> eigenvalue;  // 1/s
  double frequency_Hz = 0.0;        // |Im| / (2 pi)
  double damping_ratio = 0.0;       // -Re / |s| (1: critically damped or a real decaying root; < 0 unstable)
};

struct LinearStabilityResult {
  double speed_m_s = 0.0;          // V of the analysis, m/s
  Eigen::MatrixXd state_matrix;     // A in the model's scaled state (vehicle_dynamics_model.hpp); same eigenvalues as in SI
  std::vector<DynamicsMode> modes;  // all eigenvalues, one of each conjugate pair (Im >= 0), by increasing frequency
  double max_real_part = 0.0;       // largest Re(s), 1/s
};

// model_options.contact_kind must be Linear (InputError otherwise); the speed is model_options.speed_m_s.
// A by central differences of the (linear) right-hand side, step 1e-3 of the scaled state: exact up to rounding.
LinearStabilityResult AnalyseLinearStability(const VehicleParameters& vehicle, const DynamicsModelOptions& model_options);

// validate() throws InputError naming the option.
struct CriticalSpeedOptions {
  double min_speed_m_s = 1.0;        // > 0
  double max_speed_m_s = 150.0;      // > min_speed_m_s
  double speed_step_m_s = 1.0;       // grid of the bracketing scan, > 0
  double tolerance_m_s = 1e-3;       // bisection width, > 0
  double real_part_threshold = 1e-9; // a mode is unstable when Re(s) > this, 1/s, >= 0
  void validate() const;
};

struct CriticalSpeedResult {
  bool found = false;                // an unstable mode appeared below max_speed_m_s (and min_speed_m_s was stable)
  bool unstable_at_min_speed = false;  // already unstable at min_speed_m_s (no critical speed searched)
  double critical_speed_m_s = 0.0;   // the upper end of the final bisection bracket
  double frequency_Hz = 0.0;         // of the least stable mode at the critical speed
  int evaluations = 0;               // eigenvalue analyses
};

CriticalSpeedResult FindCriticalSpeed(const VehicleParameters& vehicle, const DynamicsModelOptions& model_options,
                                      const CriticalSpeedOptions& options);

}  // namespace conforma
