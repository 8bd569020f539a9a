#pragma once
// The field tables of the wheel-contact pipeline (wheel_contact.hpp): each struct's fields listed ONCE, as a visitor
// that calls v(name, value) for every field, so that the writers and the cache key cannot drift apart.
//
//   VisitPatchFields        PatchReport: every scalar, with the keys of `conforma contact --json` (units in the
//                           names) in the order of the JSON writer (src/app/report_json.cpp) and of the Python
//                           dict (python/conforma_module.cpp). Values: double, bool, const std::string& and
//                           const char* (the model name). Not `cells` and reference_s_on_rail_m (see
//                           kPatchFieldsNotVisited).
//   VisitWheelReportFields  WheelContactReport: every field but `patches`; "pose" is passed as the WheelsetPose
//                           itself (its keys: VisitPoseFields), "warnings" as the std::vector<std::string>.
//   VisitCellFields         ContactCell (the per-element fields), then the derived wear index.
//   VisitNormalOptionFields / VisitTangentialOptionFields
//                           WheelContactOptions, split as the WheelContactCache keys are: everything the normal
//                           stage reads, then the rest (what only the tangential stage reads). Nested structs are
//                           visited field by field ("material.poisson_ratio"); values are references to the fields
//                           (mutable when the options are), of type double, int, bool or an enum.
//
// Guards that a new field cannot be forgotten:
//   * WheelContactOptions (a forgotten option silently returns stale cached results): a static_assert below counts
//     the members of WheelContactOptions and of its nested option structs (aggregate initialisation: exact, also
//     for a field that would fit into padding, unlike sizeof) and compares with the number of fields the two
//     visitors visit. It fails the build with "a field was added to WheelContactOptions: add it to
//     VisitNormalOptionFields / VisitTangentialOptionFields". tests/test_wheel_contact_fields.cpp checks that
//     every visited field is a distinct member and that changing any one of them changes the cache key.
//   * PatchReport, WheelContactReport: tests/test_wheel_contact_fields.cpp counts their members against the
//     visitors (test time: std::string members keep these visitors out of constant evaluation).
//
// Adding a field: add it to its struct AND to its visitor here (at the END of a visitor, so that existing key
// and output orders stay as they are); a nested option struct needs its count added to kOptionLeafFields.
#include <cmath>
#include <cstddef>
#include <tuple>
#include <type_traits>
#include <utility>

#include "conforma/wheel_contact.hpp"

namespace conforma {

// ---- results ------------------------------------------------------------------------------------------------

template <class Visitor>
void VisitPatchFields(const PatchReport& p, Visitor&& v) {
  v("normal_status", p.normal_status);
  v("tangential_status", p.tangential_status);
  v("fn_N", p.fn_N);
  v("fx_N", p.fx_N);
  v("fy_N", p.fy_N);
  v("mz_Nm", p.mz_Nm);
  v("pmax_Pa", p.pmax_Pa);
  v("p0_Pa", p.p0_Pa);
  v("area_m2", p.area_m2);
  v("a_m", p.a_m);
  v("b_m", p.b_m);
  v("width_m", p.width_m);
  v("length_m", p.length_m);
  v("approach_m", p.approach_m);
  v("contact_angle_rad", p.contact_angle_rad);
  v("y_contact_rail_m", p.y_contact_rail_m);
  v("z_contact_rail_m", p.z_contact_rail_m);
  v("y_contact_wheel_m", p.y_contact_wheel_m);
  v("rolling_radius_m", p.rolling_radius_m);
  v("lead_m", p.lead_m);
  v("xi", p.xi);
  v("eta", p.eta);
  v("phi_per_m", p.phi_per_m);
  v("alpha_c_deg", p.alpha_c_deg);
  v("is_conformal", p.is_conformal);
  v("adhesion_area_m2", p.adhesion_area_m2);
  v("slip_area_m2", p.slip_area_m2);
  v("frictional_power_W", p.frictional_power_W);
  v("vertical_force_N", p.vertical_force_N);
  v("lateral_force_N", p.lateral_force_N);
  v("model", to_string(p.model));
  v("auto_alpha_c_deg", p.auto_alpha_c_deg);
  v("normal_iterations", p.normal_iterations);
  v("normal_residual", p.normal_residual);
  v("tangential_iterations", p.tangential_iterations);
  v("tangential_residual", p.tangential_residual);
}
// PatchReport members that VisitPatchFields leaves out on purpose (not in the JSON or the Python dict): the
// per-cell fields (`cells`, written by their own code), reference_s_on_rail_m (internal; the stress runner
// reads it), and the wheel-on-roller roller_rolling_radius_m and roller_angle_rad (for the roller-rig kinematics in
// C++; 0 on a rail, so left out of the outputs until the rig reports them). tests/test_wheel_contact_fields.cpp
// checks: members of PatchReport = visited + these.
constexpr std::size_t kPatchFieldsNotVisited = 4;

// ContactCell (WheelContactOptions::keep_fields): every member with its unit in the name, then the derived wear
// index; the columns of `conforma contact --fields` (src/app/contact_fields_export.cpp). in_slip is a bool.
//   wear_index_Pa: T gamma / A of the element, |traction . slip| (Pa x dimensionless slip), the frictional power
//   per unit area and rolling speed (docs/physics-reference.md §8.4)
inline double CellWearIndexPa(const ContactCell& c) {
  return std::fabs(c.traction_x_Pa * c.slip_x + c.traction_s_Pa * c.slip_s);
}
template <class Visitor>
void VisitCellFields(const ContactCell& c, Visitor&& v) {
  v("x_m", c.x_m);
  v("s_m", c.s_m);
  v("rail_s_m", c.rail_s_m);
  v("wheel_y_m", c.wheel_y_m);
  v("area_m2", c.area_m2);
  v("length_x_m", c.length_x_m);
  v("pressure_Pa", c.pressure_Pa);
  v("traction_x_Pa", c.traction_x_Pa);
  v("traction_s_Pa", c.traction_s_Pa);
  v("slip_x", c.slip_x);
  v("slip_s", c.slip_s);
  v("in_slip", c.in_slip);
  v("wear_index_Pa", CellWearIndexPa(c));
}
constexpr std::size_t kCellDerivedFields = 1;  // wear_index_Pa: visited, not a member

template <class Visitor>
void VisitPoseFields(const WheelsetPose& pose, Visitor&& v) {
  v("y_m", pose.lateral_m);
  v("z_m", pose.vertical_m);
  v("roll_rad", pose.roll_rad);
  v("yaw_rad", pose.yaw_rad);
}

template <class Visitor>
void VisitWheelReportFields(const WheelContactReport& r, Visitor&& v) {
  v("side", to_string(r.side));
  v("model", to_string(r.model));
  v("status", to_string(r.status));
  v("pose", r.pose);  // a WheelsetPose: VisitPoseFields
  v("vertical_force_N", r.vertical_force_N);
  v("pressure_vertical_force_N", r.pressure_vertical_force_N);
  v("lateral_force_N", r.lateral_force_N);
  v("load_iterations", r.load_iterations);
  v("candidate_load_N", r.candidate_load_N);
  v("candidate_searches", r.candidate_searches);
  v("warnings", r.warnings);  // std::vector<std::string>
}

// ---- options (the WheelContactCache keys) -------------------------------------------------------------------

namespace fields_detail {
template <class Options>
using EnableIfOptions = std::enable_if_t<std::is_same_v<std::remove_const_t<Options>, WheelContactOptions>, int>;
}  // namespace fields_detail

// Everything the normal stage reads (the normal-problem cache key). The first 15 fields are in the order of the
// original hand-written key; the fields after them were missing from it.
template <class Options, class Visitor, fields_detail::EnableIfOptions<Options> = 0>
constexpr void VisitNormalOptionFields(Options& o, Visitor&& v) {
  v("model", o.model);
  v("material.shear_modulus_Pa", o.material.shear_modulus_Pa);
  v("material.poisson_ratio", o.material.poisson_ratio);
  v("vertical_load_N", o.vertical_load_N);
  v("load_tolerance", o.load_tolerance);
  v("kp_strips", o.kp_strips);
  v("exact_element_size_m", o.exact_element_size_m);  // where bem_x_elements was
  v("candidate_strip_width_m", o.candidate_strip_width_m);
  v("conformity_threshold_deg", o.conformity_threshold_deg);
  v("conformal_variable_penetration", o.conformal_variable_penetration);
  v("auto_selection.conformity_threshold_deg", o.auto_selection.conformity_threshold_deg);
  v("auto_selection.virtual_penetration_factor", o.auto_selection.virtual_penetration_factor);
  v("auto_selection.gap_fit_tolerance", o.auto_selection.gap_fit_tolerance);
  v("auto_selection.curvature_tolerance", o.auto_selection.curvature_tolerance);
  v("auto_selection.min_strips", o.auto_selection.min_strips);
  v("max_touching_contact_angle_rad", o.max_touching_contact_angle_rad);
  v("auto_selection.min_hertz_axis_ratio", o.auto_selection.min_hertz_axis_ratio);
  v("exact_max_elements", o.exact_max_elements);
  v("patch_combine_distance_m", o.patch_combine_distance_m);
  v("load_balance", o.load_balance);  // issue 15; with Total the normal stage also reads the tangential fields
}

// The rest: what only the tangential stage reads (with the velocity, the whole-report cache key), in the order of
// the original hand-written key. material.density_kg_m3 is read by neither stage today; it is kept here, where the
// original key had it.
template <class Options, class Visitor, fields_detail::EnableIfOptions<Options> = 0>
constexpr void VisitTangentialOptionFields(Options& o, Visitor&& v) {
  v("friction_coefficient", o.friction_coefficient);
  v("fastsim_elements", o.fastsim_elements);
  v("solve_tangential", o.solve_tangential);
  v("keep_fields", o.keep_fields);
  v("fastsim.bound", o.fastsim.bound);
  v("fastsim.blend_flexibilities", o.fastsim.blend_flexibilities);
  v("fastsim.marching", o.fastsim.marching);
  v("creepages_given", o.creepages_given);
  v("creepages.longitudinal", o.creepages.longitudinal);
  v("creepages.lateral", o.creepages.lateral);
  v("creepages.spin_per_m", o.creepages.spin_per_m);
  v("material.density_kg_m3", o.material.density_kg_m3);
  v("friction_law.kind", o.friction_law.kind);
  v("friction_law.parameters[0]", o.friction_law.parameters[0]);
  v("friction_law.parameters[1]", o.friction_law.parameters[1]);
  v("friction_law.parameters[2]", o.friction_law.parameters[2]);
  v("friction_law.parameters[3]", o.friction_law.parameters[3]);
  v("kp_spin_about_patch_centre", o.kp_spin_about_patch_centre);  // issue 15 item 2
  v("kp_local_flexibilities", o.kp_local_flexibilities);
}

// ---- the guard ----------------------------------------------------------------------------------------------

namespace fields_detail {

// Number of members of an aggregate: the largest N for which T{x1, ..., xN} compiles with arguments convertible to
// anything (a nested struct member takes one argument: no brace elision, the argument converts to it).
struct AnyMember {
  template <class T>
  constexpr operator T() const noexcept;  // declared only: used in unevaluated contexts
};
template <class T, class Indices, class = void>
struct BraceInitializable : std::false_type {};
template <class T, std::size_t... I>
struct BraceInitializable<T, std::index_sequence<I...>, std::void_t<decltype(T{(void(I), AnyMember{})...})>>
    : std::true_type {};
template <class T, std::size_t N = 0>
constexpr std::size_t AggregateMemberCount() {
  static_assert(std::is_aggregate_v<T>, "the field guard counts the members of an aggregate");
  if constexpr (BraceInitializable<T, std::make_index_sequence<N + 1>>::value)
    return AggregateMemberCount<T, N + 1>();
  else
    return N;
}

// Leaf fields of WheelContactOptions: its members, each nested option struct counted by its own members.
constexpr std::size_t kNestedOptionStructs = 5;  // material, auto_selection, fastsim, creepages, friction_law
// friction_law's parameter array is one member visited element by element
constexpr std::size_t kFrictionLawLeafFields =
    AggregateMemberCount<FrictionLaw>() - 1 + std::tuple_size_v<decltype(FrictionLaw::parameters)>;
constexpr std::size_t kOptionLeafFields = AggregateMemberCount<WheelContactOptions>() - kNestedOptionStructs +
                                          AggregateMemberCount<Material>() +
                                          AggregateMemberCount<ModelSelectionOptions>() +
                                          AggregateMemberCount<FastsimOptions>() + AggregateMemberCount<Creepages>() +
                                          kFrictionLawLeafFields;

constexpr std::size_t VisitedOptionFields() {
  const WheelContactOptions o{};
  std::size_t n = 0;
  const auto count = [&n](const char*, const auto&) { ++n; };
  VisitNormalOptionFields(o, count);
  VisitTangentialOptionFields(o, count);
  return n;
}

}  // namespace fields_detail

static_assert(fields_detail::VisitedOptionFields() == fields_detail::kOptionLeafFields,
              "a field was added to WheelContactOptions: add it to VisitNormalOptionFields / "
              "VisitTangentialOptionFields (include/conforma/wheel_contact_fields.hpp)");

}  // namespace conforma
