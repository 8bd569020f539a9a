// The C API's patch fields (capi/conforma_c.h, a fixed ABI with its own names) against the PatchReport field table
// (conforma/wheel_contact_fields.hpp): every contact-frame member of conforma_patch_result is the table's field of
// the mapped name, bit for bit, for poses with one and two patches; the mapped names exist in the table; the
// per-wheel fields equal the report's.
// test-links: pipeline  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <type_traits>

#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/wheel_contact.hpp"
#include "conforma/wheel_contact_fields.hpp"
#include "capi_mbench_model.hpp"
#include "conforma_c.h"

namespace {

// C member -> table key. The other members are track-frame vectors (force_track_N, spin_moment_track_Nm,
// contact_point_track_m, normal_track), checked by test_capi_threads.
struct Mapped {
  const char* table_key;
  double (*c_value)(const conforma_patch_result&);
};
#define CONFORMA_C_FIELD(key, member) \
  Mapped { key, [](const conforma_patch_result& p) { return static_cast<double>(p.member); } }
const Mapped kMapped[] = {
    CONFORMA_C_FIELD("fn_N", normal_force_N),
    CONFORMA_C_FIELD("fx_N", longitudinal_force_N),
    CONFORMA_C_FIELD("fy_N", lateral_force_N),
    CONFORMA_C_FIELD("mz_Nm", spin_moment_Nm),
    CONFORMA_C_FIELD("contact_angle_rad", contact_angle_rad),
    CONFORMA_C_FIELD("rolling_radius_m", rolling_radius_m),
    CONFORMA_C_FIELD("approach_m", approach_m),
    CONFORMA_C_FIELD("area_m2", area_m2),
    CONFORMA_C_FIELD("pmax_Pa", pmax_Pa),
    CONFORMA_C_FIELD("adhesion_area_m2", adhesion_area_m2),
    CONFORMA_C_FIELD("slip_area_m2", slip_area_m2),
    CONFORMA_C_FIELD("frictional_power_W", frictional_power_W),
    CONFORMA_C_FIELD("xi", creepage_longitudinal),
    CONFORMA_C_FIELD("eta", creepage_lateral),
    CONFORMA_C_FIELD("phi_per_m", creepage_spin_per_m),
    CONFORMA_C_FIELD("alpha_c_deg", conformity_index_deg),
    CONFORMA_C_FIELD("is_conformal", is_conformal),
};
#undef CONFORMA_C_FIELD
constexpr size_t kTrackFrameMembers = 4;  // the double[3] vectors

// A member added to conforma_patch_result (an ABI change) must be added to kMapped or counted as a track-frame one:
// 17 scalars (16 double, 1 int) and 4 double[3].
static_assert(sizeof(conforma_patch_result) == (16 + 3 * kTrackFrameMembers) * sizeof(double) + sizeof(double),
              "conforma_patch_result changed: map its new member to the PatchReport table in kMapped");
static_assert(sizeof(kMapped) / sizeof(kMapped[0]) == 17, "17 scalar members of conforma_patch_result");

// The table's numeric fields of one patch by key (bools as 0 / 1).
std::map<std::string, double> TableValues(const conforma::PatchReport& p) {
  std::map<std::string, double> out;
  conforma::VisitPatchFields(p, [&out](const char* key, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    if constexpr (std::is_arithmetic_v<T>) out[key] = static_cast<double>(value);
  });
  return out;
}

TEST(CApiFields, EveryCPatchFieldIsTheTableFieldOfItsName) {
  CApiMBenchModel mbench;
  ASSERT_NO_FATAL_FAILURE(mbench.Create());
  conforma_model* model = mbench.model;
  const conforma::WheelsetTrackGeometry& geometry = *mbench.geometry;
  conforma::WheelContactOptions options;  // the C defaults: conformal, the C++ defaults otherwise
  options.model = conforma::ContactModel::Conformal;

  const std::map<std::string, double> names = TableValues(conforma::PatchReport{});
  for (const Mapped& m : kMapped) EXPECT_EQ(names.count(m.table_key), 1u) << m.table_key << " is not in the table";

  int patches = 0, two_patch_wheels = 0;
  for (double y_mm : {0.0, 3.0, 5.0, 6.0, 6.5, 7.0, 8.0}) {
    conforma_wheelset_state s{};
    s.lateral_m = y_mm * 1e-3;
    s.yaw_rad = 2.4 * y_mm * 1e-3;
    s.forward_speed_m_s = 2.0;
    s.axle_angular_velocity_rad_s = 2.0 / 0.46;
    conforma_evaluation_options o;
    conforma_default_evaluation_options(&o);
    o.rigid_equilibrium = 1;
    conforma_wheelset_result r;
    ASSERT_EQ(conforma_evaluate(model, &s, &o, &r), CONFORMA_OK) << r.error_message;

    const conforma::EquilibriumResult eq = geometry.SolveRigidEquilibrium(s.lateral_m, s.yaw_rad);
    const conforma::WheelsetVelocity v{2.0, 0.0, 0.0, 2.0 / 0.46};
    for (conforma::Side side : {conforma::Side::Left, conforma::Side::Right}) {
      const conforma::WheelContactReport ref = conforma::SolveWheelContact(geometry, side, eq.pose, v, options);
      const conforma_wheel_result& w = r.wheel[conforma::side_index(side)];
      ASSERT_EQ(w.patches_found, static_cast<int>(ref.patches.size())) << y_mm;
      EXPECT_EQ(w.vertical_position_m, ref.pose.vertical_m);
      EXPECT_EQ(w.load_iterations, ref.load_iterations);
      two_patch_wheels += w.patch_count > 1;
      for (int j = 0; j < w.patch_count; ++j, ++patches) {
        const std::map<std::string, double> table = TableValues(ref.patches[j]);
        for (const Mapped& m : kMapped)
          EXPECT_EQ(m.c_value(w.patch[j]), table.at(m.table_key)) << m.table_key << " y " << y_mm << " patch " << j;
      }
    }
  }
  EXPECT_GE(patches, 8);
  EXPECT_GT(two_patch_wheels, 0);
}

}  // namespace
