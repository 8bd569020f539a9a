// Contact model `auto`: the per-patch choice of hertz, kpec or conformal (model_selection.hpp).
#include "conforma/model_selection.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <vector>

#include "conforma/conformity.hpp"
#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/material.hpp"

namespace conforma {

void ModelSelectionOptions::validate() const {
  require_finite(conformity_threshold_deg, "auto: conformity_threshold_deg");
  require_positive(virtual_penetration_factor, "auto: virtual_penetration_factor");
  if (!(virtual_penetration_factor <= 1.0)) throw InputError("auto: virtual_penetration_factor must be <= 1");
  require_non_negative(gap_fit_tolerance, "auto: gap_fit_tolerance");
  require_non_negative(curvature_tolerance, "auto: curvature_tolerance");
  if (min_strips < 3) throw InputError("auto: min_strips must be >= 3 (a parabola has three coefficients)");
  require_non_negative(min_hertz_axis_ratio, "auto: min_hertz_axis_ratio");
}

const char* to_string(ModelSelectionReason reason) {
  switch (reason) {
    case ModelSelectionReason::Elliptic: return "elliptic";
    case ModelSelectionReason::NonElliptic: return "non_elliptic";
    case ModelSelectionReason::ElongatedEllipse: return "elongated_ellipse";
    case ModelSelectionReason::NoHertzPoint: return "no_hertz_point";
    case ModelSelectionReason::TooFewStrips: return "too_few_strips";
    case ModelSelectionReason::Conformal: return "conformal";
  }
  return "?";
}

ModelSelection SelectContactModel(const PatchGeometry& patch, double approach_m, const RigidContactPoint* hertz_point,
                                  const ModelSelectionOptions& options) {
  options.validate();
  require_finite(approach_m, "auto: approach_m");
  const size_t n = patch.strips();
  if (patch.gap_m.size() != n || patch.alpha_rad.size() != n || patch.longitudinal_curvature_per_m.size() != n)
    throw InputError("auto: patch arrays of different lengths");
  ModelSelection out;

  // Estimated contact: virtual interpenetration eps * delta - gap > 0 (docs/physics-reference.md §3.1).
  const double virtual_penetration = options.virtual_penetration_factor * approach_m;
  std::vector<size_t> in_contact;
  std::vector<double> angles;
  for (size_t j = 0; j < n; ++j) {
    require_finite(patch.gap_m[j], "auto: patch gap");
    require_finite(patch.alpha_rad[j], "auto: patch alpha");
    if (patch.gap_m[j] < virtual_penetration) {
      in_contact.push_back(j);
      angles.push_back(patch.alpha_rad[j]);
    }
  }
  out.strips_in_contact = static_cast<int>(in_contact.size());
  if (!in_contact.empty())
    out.width_m = patch.s_m[in_contact.back()] - patch.s_m[in_contact.front()] + patch.ds_m;

  // Conformity index over the estimated contact (paper 003 eq. 13).
  out.alpha_c_deg = ComputeConformityIndex(angles, options.conformity_threshold_deg).alpha_c_deg;
  if (out.alpha_c_deg > options.conformity_threshold_deg) {
    out.model = ContactModel::Conformal;
    out.reason = ModelSelectionReason::Conformal;
    return out;
  }
  out.model = ContactModel::Kpec;
  if (out.strips_in_contact < options.min_strips) {
    out.reason = ModelSelectionReason::TooFewStrips;
    return out;
  }
  if (hertz_point == nullptr || !(hertz_point->hertz_A_per_m > 0.0) || !(hertz_point->hertz_B_per_m > 0.0)) {
    out.reason = ModelSelectionReason::NoHertzPoint;
    return out;
  }

  // (a) parabola fit of the gap over the estimated contact (least squares, s scaled to [-1, 1] for conditioning)
  const double s_mid = 0.5 * (patch.s_m[in_contact.front()] + patch.s_m[in_contact.back()]);
  const double s_half = std::max(0.5 * (patch.s_m[in_contact.back()] - patch.s_m[in_contact.front()]), patch.ds_m);
  const Eigen::Index m = static_cast<Eigen::Index>(in_contact.size());
  Eigen::MatrixXd design(m, 3);
  Eigen::VectorXd gap(m);
  for (Eigen::Index k = 0; k < m; ++k) {
    const double u = (patch.s_m[in_contact[k]] - s_mid) / s_half;
    design(k, 0) = 1.0;
    design(k, 1) = u;
    design(k, 2) = u * u;
    gap(k) = patch.gap_m[in_contact[k]];
  }
  const Eigen::Vector3d c = design.colPivHouseholderQr().solve(gap);
  out.gap_fit_residual = (design * c - gap).cwiseAbs().maxCoeff() / virtual_penetration;
  // (b) lateral curvature of the fit (gap = B s^2 near the minimum, hertz.hpp) against B of the Hertz point
  const double fitted_B = c(2) / (s_half * s_half);
  out.lateral_curvature_error = std::fabs(fitted_B / hertz_point->hertz_B_per_m - 1.0);
  // (c) longitudinal curvature across the contact against A of the Hertz point
  for (size_t j : in_contact)
    out.longitudinal_curvature_error =
        std::max(out.longitudinal_curvature_error,
                 std::fabs(patch.longitudinal_curvature_per_m[j] / hertz_point->hertz_A_per_m - 1.0));

  const bool elliptic = out.gap_fit_residual <= options.gap_fit_tolerance &&
                        out.lateral_curvature_error <= options.curvature_tolerance &&
                        out.longitudinal_curvature_error <= options.curvature_tolerance;
  if (!elliptic) {
    // KP's amplitude rule (peak proportional to the strip half-length, kpec) is exact only on elliptic patches; the
    // conformal model collocates the amplitudes (docs/physics-reference.md §5.3, §9.2)
    out.model = ContactModel::Conformal;
    out.reason = ModelSelectionReason::NonElliptic;
    return out;
  }
  // (e) axis ratio of the Hertz ellipse: a function of A / B alone (any load and material give the same ratio)
  const HertzResult h = SolveHertzForLoad(hertz_point->hertz_A_per_m, hertz_point->hertz_B_per_m, 1e4, Material{});
  if (h.status == HertzStatus::Ok) out.hertz_axis_ratio = std::min(h.a_m, h.b_m) / std::max(h.a_m, h.b_m);
  if (!(out.hertz_axis_ratio >= options.min_hertz_axis_ratio) || h.status != HertzStatus::Ok) {
    out.reason = ModelSelectionReason::ElongatedEllipse;
    return out;
  }
  out.model = ContactModel::Hertz;
  out.reason = ModelSelectionReason::Elliptic;
  return out;
}

}  // namespace conforma
