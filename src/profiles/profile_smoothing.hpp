#pragma once
// Private: smoothing of noisy profile points (used by Profile::FromPoints when smoothing_rms_m > 0).
#include <string>
#include <vector>

#include <Eigen/Core>

namespace conforma::profile_smoothing {

// Parametric cubic smoothing spline (Reinsch 1967; Green & Silverman 1994 §2.3) through the ordered points:
// y(t) and z(t) minimise sum |p_i - f(t_i)|^2 + lambda * integral (|y''|^2 + |z''|^2) dt, t = chord length of the
// smoothed curve (two passes), lambda chosen so that the RMS distance |p_i - f(t_i)| equals rms_m. The sparse SPD
// pentadiagonal system (R + lambda Q^T Q) gamma = Q^T y is solved with CHOLMOD. Returns the smoothed curve
// sampled every spacing_m in t. Throws InputError (naming source) if the system cannot be solved.
std::vector<Eigen::Vector2d> smooth(const std::vector<Eigen::Vector2d>& points, double rms_m, double spacing_m,
                                    const std::string& source);

}  // namespace conforma::profile_smoothing
