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
#include "c_patch_fields.hpp"
#include "conforma_c.h"

namespace {

// The C fill's own table (capi/c_patch_fields.hpp): C member -> table key.
double CValue(const conforma_patch_result& p, const conforma::capi::CPatchField& f) {
  const char* member = reinterpret_cast<const char*>(&p) + f.offset;
  if (f.is_int) return static_cast<double>(*reinterpret_cast<const int*>(member));
  return *reinterpret_cast<const double*>(member);
}

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
  for (const conforma::capi::CPatchField& m : conforma::capi::kCPatchFields)
    EXPECT_EQ(names.count(m.table_key), 1u) << m.table_key << " is not in the table";

  int patches = 0, two_patch_wheels = 0;
  for (double y_mm : {0.0, 3.0, 5.0, 6.0, 6.5, 7.0, 8.0}) {
    const conforma_wheelset_state s = CApiMBenchModel::State(y_mm);  // Manchester: yaw = 2.4 y mrad
    const conforma_evaluation_options o = CApiMBenchModel::RigidEquilibriumOptions();
    conforma_wheelset_result r;
    ASSERT_EQ(conforma_evaluate(model, &s, &o, &r), CONFORMA_OK) << r.error_message;

    const conforma::EquilibriumResult eq = geometry.SolveRigidEquilibrium(s.lateral_m, s.yaw_rad);
    const conforma::WheelsetVelocity v = CApiMBenchModel::Velocity();
    for (conforma::Side side : {conforma::Side::Left, conforma::Side::Right}) {
      const conforma::WheelContactReport ref = conforma::SolveWheelContact(geometry, side, eq.pose, v, options);
      const conforma_wheel_result& w = r.wheel[conforma::side_index(side)];
      ASSERT_EQ(w.patches_found, static_cast<int>(ref.patches.size())) << y_mm;
      EXPECT_EQ(w.vertical_position_m, ref.pose.vertical_m);
      EXPECT_EQ(w.load_iterations, ref.load_iterations);
      two_patch_wheels += w.patch_count > 1;
      for (int j = 0; j < w.patch_count; ++j, ++patches) {
        const std::map<std::string, double> table = TableValues(ref.patches[j]);
        for (const conforma::capi::CPatchField& m : conforma::capi::kCPatchFields)
          EXPECT_EQ(CValue(w.patch[j], m), table.at(m.table_key)) << m.table_key << " y " << y_mm << " patch " << j;
        // the mapping itself, member by member (not through the table)
        const conforma::PatchReport& p = ref.patches[j];
        EXPECT_EQ(w.patch[j].normal_force_N, p.fn_N);
        EXPECT_EQ(w.patch[j].longitudinal_force_N, p.fx_N);
        EXPECT_EQ(w.patch[j].lateral_force_N, p.fy_N);
        EXPECT_EQ(w.patch[j].spin_moment_Nm, p.mz_Nm);
        EXPECT_EQ(w.patch[j].creepage_longitudinal, p.xi);
        EXPECT_EQ(w.patch[j].creepage_lateral, p.eta);
        EXPECT_EQ(w.patch[j].creepage_spin_per_m, p.phi_per_m);
        EXPECT_EQ(w.patch[j].conformity_index_deg, p.alpha_c_deg);
        EXPECT_EQ(w.patch[j].is_conformal, p.is_conformal ? 1 : 0);
      }
    }
  }
  EXPECT_GE(patches, 8);
  EXPECT_GT(two_patch_wheels, 0);
}

}  // namespace
