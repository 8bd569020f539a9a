#include "conforma/wear_distribution.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "conforma/error.hpp"

namespace conforma {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

WearDistribution WearDistribution::Zero(double length_m, double spacing_m) {
  require_positive(length_m, "wear grid length_m");
  require_positive(spacing_m, "wear grid spacing_m");
  const size_t n = std::max<size_t>(2, static_cast<size_t>(std::ceil(length_m / spacing_m - 1e-9)) + 1);
  WearDistribution d;
  d.spacing_m = length_m / static_cast<double>(n - 1);
  d.depth_m.assign(n, 0.0);
  return d;
}

WearDistribution WearDistribution::ForProfile(const Profile& profile, double spacing_m) {
  if (profile.empty()) throw InputError("wear grid: the profile is empty");
  return Zero(profile.length(), spacing_m);
}

double WearDistribution::max_depth_m() const {
  return depth_m.empty() ? 0.0 : *std::max_element(depth_m.begin(), depth_m.end());
}

double WearDistribution::area_m2() const {
  if (depth_m.size() < 2) return 0.0;
  double sum = 0.5 * (depth_m.front() + depth_m.back());
  for (size_t i = 1; i + 1 < depth_m.size(); ++i) sum += depth_m[i];
  return sum * spacing_m;
}

double WearDistribution::at(double s) const {
  if (depth_m.size() < 2 || s < 0.0 || s > length_m()) return 0.0;
  const double u = s / spacing_m;
  const size_t i = std::min(static_cast<size_t>(u), depth_m.size() - 2);
  const double t = u - static_cast<double>(i);
  return (1.0 - t) * depth_m[i] + t * depth_m[i + 1];
}

bool WearDistribution::same_grid(const WearDistribution& o) const {
  return o.depth_m.size() == depth_m.size() && std::abs(o.spacing_m - spacing_m) <= 1e-12 * spacing_m;
}

void WearDistribution::add(const WearDistribution& other, double weight) {
  require_finite(weight, "wear distribution weight");
  if (!same_grid(other)) throw InputError("wear distributions on different grids cannot be added");
  for (size_t i = 0; i < depth_m.size(); ++i) depth_m[i] += weight * other.depth_m[i];
}

namespace {

// Deposits a strip of depth `depth` over [s - width/2, s + width/2] onto the node cells of the grid,
// conserving depth * width (trapezoid area). Returns the area that falls outside the grid.
double deposit(WearDistribution& grid, double s, double width, double depth) {
  const double h = grid.spacing_m, length = grid.length_m();
  const double a = s - 0.5 * width, b = s + 0.5 * width;
  double outside = depth * (std::max(0.0, std::min(b, 0.0) - a) + std::max(0.0, b - std::max(a, length)));
  const double lo = std::max(a, 0.0), hi = std::min(b, length);
  if (hi <= lo) return depth * width;
  const size_t n = grid.depth_m.size();
  const size_t first = static_cast<size_t>(std::max(0.0, std::floor(lo / h + 0.5)));
  const size_t last = std::min(n - 1, static_cast<size_t>(std::floor(hi / h + 0.5)));
  for (size_t i = first; i <= last; ++i) {
    const double cell_lo = std::max(0.0, (i - 0.5) * h), cell_hi = std::min(length, (i + 0.5) * h);
    const double overlap = std::min(hi, cell_hi) - std::max(lo, cell_lo);
    if (overlap > 0.0) grid.depth_m[i] += depth * overlap / (cell_hi - cell_lo);
  }
  return outside;
}

void check_cell(const WearCell& c, size_t index) {
  const bool ok = c.traction_Pa.allFinite() && c.slip.allFinite() && std::isfinite(c.pressure_Pa) &&
                  c.pressure_Pa >= 0.0 && std::isfinite(c.area_m2) && c.area_m2 >= 0.0 &&
                  std::isfinite(c.length_x_m) && c.length_x_m > 0.0 && std::isfinite(c.wheel_s_m) &&
                  std::isfinite(c.rail_s_m);
  if (ok) return;  // the messages below are built only for a bad cell (once per cell was ~1 % of a rig sample)
  const std::string at = "wear cell " + std::to_string(index) + ": ";
  if (!c.traction_Pa.allFinite()) throw InputError(at + "traction is not finite");
  if (!c.slip.allFinite()) throw InputError(at + "slip is not finite");
  require_non_negative(c.pressure_Pa, (at + "pressure_Pa").c_str());
  require_non_negative(c.area_m2, (at + "area_m2").c_str());
  require_positive(c.length_x_m, (at + "length_x_m").c_str());
  require_finite(c.wheel_s_m, (at + "wheel_s_m").c_str());
  require_finite(c.rail_s_m, (at + "rail_s_m").c_str());
}

}  // namespace

PatchWear ComputePatchWear(const WearPatch& patch, const WearModel& model, const WearDistribution& wheel_grid,
                           const WearDistribution& rail_grid) {
  require_non_negative(patch.rolling_speed_m_s, "rolling_speed_m_s");
  PatchWear out;
  out.wheel_depth_per_passage = wheel_grid;
  out.rail_depth_per_passage = rail_grid;
  std::fill(out.wheel_depth_per_passage.depth_m.begin(), out.wheel_depth_per_passage.depth_m.end(), 0.0);
  std::fill(out.rail_depth_per_passage.depth_m.begin(), out.rail_depth_per_passage.depth_m.end(), 0.0);
  for (size_t k = 0; k < patch.cells.size(); ++k) {
    const WearCell& c = patch.cells[k];
    check_cell(c, k);
    if (c.area_m2 == 0.0) continue;
    const double width = c.area_m2 / c.length_x_m;  // lateral extent along the profile
    // paper 001 eq. 24 / paper 000 eq. 16: the cell contributes rate * dx to its strip's depth per passage
    const double wheel_depth = model.wheel_law.depth_per_rolled_metre(c.traction_Pa, c.slip, c.pressure_Pa,
                                                                      patch.rolling_speed_m_s, model.wheel_material) *
                               c.length_x_m;
    const double rail_depth = model.rail_law.depth_per_rolled_metre(c.traction_Pa, c.slip, c.pressure_Pa,
                                                                    patch.rolling_speed_m_s, model.rail_material) *
                              c.length_x_m;
    if (wheel_depth > 0.0) out.wheel_area_outside_m2 += deposit(out.wheel_depth_per_passage, c.wheel_s_m, width, wheel_depth);
    if (rail_depth > 0.0) out.rail_area_outside_m2 += deposit(out.rail_depth_per_passage, c.rail_s_m, width, rail_depth);
  }
  return out;
}

WearAccumulator::WearAccumulator(const WearDistribution& wheel_grid, const WearDistribution& rail_grid, WearModel model)
    : model_(std::move(model)), wheel_sum_(wheel_grid), rail_sum_(rail_grid) {
  model_.wheel_law.validate();
  model_.rail_law.validate();
  model_.wheel_material.validate();
  model_.rail_material.validate();
  std::fill(wheel_sum_.depth_m.begin(), wheel_sum_.depth_m.end(), 0.0);
  std::fill(rail_sum_.depth_m.begin(), rail_sum_.depth_m.end(), 0.0);
}

void WearAccumulator::add(const WearSample& sample) {
  require_non_negative(sample.distance_m, "wear sample distance_m");
  for (const WearPatch& patch : sample.patches) {
    require_positive(patch.wheel_radius_m, "wheel_radius_m");
    const PatchWear w = ComputePatchWear(patch, model_, wheel_sum_, rail_sum_);
    // paper 001 eqs. 23, 25-26: wheel depth spread over the circumference, times the distance
    wheel_sum_.add(w.wheel_depth_per_passage, sample.distance_m / (2.0 * kPi * patch.wheel_radius_m));
    // rail: depth per passage weighted by the distance (divided by the class length in result())
    rail_sum_.add(w.rail_depth_per_passage, sample.distance_m);
    outside_m2_ += (w.wheel_area_outside_m2 + w.rail_area_outside_m2) * sample.distance_m;
  }
  distance_m_ += sample.distance_m;
}

void WearAccumulator::merge(const WearAccumulator& o) {
  wheel_sum_.add(o.wheel_sum_, 1.0);
  rail_sum_.add(o.rail_sum_, 1.0);
  distance_m_ += o.distance_m_;
  outside_m2_ += o.outside_m2_;
}

TrackClassWear WearAccumulator::result() const {
  TrackClassWear r;
  r.wheel_depth_per_metre = wheel_sum_;
  r.rail_depth_per_passage = rail_sum_;
  r.distance_m = distance_m_;
  if (distance_m_ > 0.0) {
    for (double& v : r.wheel_depth_per_metre.depth_m) v /= distance_m_;
    for (double& v : r.rail_depth_per_passage.depth_m) v /= distance_m_;
    r.area_outside_m2 = outside_m2_ / distance_m_;
  }
  return r;
}

TrackClassWear IntegrateTrackClass(const std::vector<WearSample>& samples, const WearModel& model,
                                   const WearDistribution& wheel_grid, const WearDistribution& rail_grid) {
  WearAccumulator acc(wheel_grid, rail_grid, model);
  for (const WearSample& s : samples) acc.add(s);
  return acc.result();
}

TrackClassWear CombineTrackClasses(const std::vector<TrackClassWear>& classes, const std::vector<double>& weights) {
  if (classes.empty()) throw InputError("track classes: none given");
  if (weights.size() != classes.size())
    throw InputError("track classes: " + std::to_string(classes.size()) + " classes but " +
                     std::to_string(weights.size()) + " weights");
  double sum = 0.0;
  for (size_t k = 0; k < weights.size(); ++k) {
    require_non_negative(weights[k], ("track class weight " + std::to_string(k)).c_str());
    sum += weights[k];
  }
  if (std::abs(sum - 1.0) > 1e-9) throw InputError("track class weights must sum to 1, got " + MessageNumber(sum, 12));
  TrackClassWear out = classes.front();
  std::fill(out.wheel_depth_per_metre.depth_m.begin(), out.wheel_depth_per_metre.depth_m.end(), 0.0);
  std::fill(out.rail_depth_per_passage.depth_m.begin(), out.rail_depth_per_passage.depth_m.end(), 0.0);
  out.distance_m = 0.0;
  out.area_outside_m2 = 0.0;
  for (size_t k = 0; k < classes.size(); ++k) {  // paper 001 eq. 27
    out.wheel_depth_per_metre.add(classes[k].wheel_depth_per_metre, weights[k]);
    out.rail_depth_per_passage.add(classes[k].rail_depth_per_passage, weights[k]);
    out.distance_m += classes[k].distance_m;
    out.area_outside_m2 += weights[k] * classes[k].area_outside_m2;
  }
  return out;
}

}  // namespace conforma
