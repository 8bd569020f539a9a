// The `reference` contact model on one patch (patch_solver.hpp): the BEM normal solver on the curved patch with
// Blanco-Lorenzo influence coefficients (docs/physics-reference.md §10); no tangential part.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "conforma/bem_reference.hpp"
#include "conforma/conformity.hpp"
#include "conforma/error.hpp"
#include "patch_models.hpp"

namespace conforma {

PatchNormalSolution SolveReferencePatchNormal(ContactModel, const PatchInput& input, double approach_m,
                                              const WheelContactOptions& options) {
  PatchNormalSolution out;
  if (input.patch == nullptr) throw InputError("reference model: the patch has no geometry");
  const PatchGeometry& patch = *input.patch;
  if (approach_m <= 0.0) { out.status = "no_contact"; return out; }
  BemOptions b;
  b.influence = BemInfluence::Blanco;
  b.control = BemLoadControl::Approach;
  b.approach_m = approach_m;
  b.element_dx_m = b.element_ds_m = options.exact_element_size_m;
  b.max_elements = options.exact_max_elements;
  b.tolerance = std::min(1e-7, 0.1 * options.load_tolerance);  // force noise well below the load control tolerance
  BemResult r = SolveBemNormal(patch, options.material, b);
  out.status = r.status == BemStatus::Converged ? "ok" : r.status == BemStatus::NoContact ? "no_contact" : "not_converged";
  if (r.status == BemStatus::NoContact) return out;
  out.in_contact = r.normal_force_reference_N > 0.0;
  out.fn_N = r.normal_force_reference_N;
  // lateral component of the curved-surface pressure along t0 (n_j = cos a n0 + sin a t0, patch.hpp), as the KP
  // models report it, so that load control balances the same resultant for every model
  for (int j = 0; j < r.grid.ns; ++j)
    out.fs_N += r.pressure_Pa.col(j).sum() * std::sin(r.grid.alpha(j)) * r.grid.element_area_m2();
  out.pmax_Pa = out.p0_Pa = r.max_pressure_Pa;
  out.area_m2 = r.contact_area_m2;
  out.width_m = r.contact_width_s_m;
  out.length_m = r.contact_length_x_m;
  // conformity index (paper 003 eq. 13) over the strips whose centres lie in the BEM contact
  std::vector<double> angles;
  for (size_t j = 0; j < patch.strips(); ++j)
    if (patch.s_m[j] >= r.contact_s_min_m && patch.s_m[j] <= r.contact_s_max_m) angles.push_back(patch.alpha_rad[j]);
  const ConformityIndex index = ComputeConformityIndex(angles, options.conformity_threshold_deg);
  out.alpha_c_deg = index.alpha_c_deg;
  out.is_conformal = index.is_conformal;
  out.bem = std::move(r);  // the grid and pressure field the exact tangential solve works on
  return out;
}

}  // namespace conforma
