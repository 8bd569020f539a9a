#pragma once
// The scalar members of the C API's conforma_patch_result (a fixed ABI with its own names) and the PatchReport field
// of the one field table (conforma/wheel_contact_fields.hpp) each is filled from: the C fill and its test use this
// table. The other members are the track-frame vectors (force_track_N, spin_moment_track_Nm, contact_point_track_m,
// normal_track), filled by conforma_c.cpp from the track-frame conversion.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "conforma/wheel_contact.hpp"
#include "conforma/wheel_contact_fields.hpp"
#include "conforma_c.h"

namespace conforma::capi {

struct CPatchField {
  const char* table_key;  // key in VisitPatchFields (the JSON key)
  size_t offset;          // of the member in conforma_patch_result
  bool is_int;            // int member (a bool field: 0 / 1), else double
};

#define CONFORMA_C_FIELD(key, member, is_int) \
  CPatchField { key, offsetof(conforma_patch_result, member), is_int }
inline constexpr CPatchField kCPatchFields[] = {
    CONFORMA_C_FIELD("fn_N", normal_force_N, false),
    CONFORMA_C_FIELD("fx_N", longitudinal_force_N, false),
    CONFORMA_C_FIELD("fy_N", lateral_force_N, false),
    CONFORMA_C_FIELD("mz_Nm", spin_moment_Nm, false),
    CONFORMA_C_FIELD("contact_angle_rad", contact_angle_rad, false),
    CONFORMA_C_FIELD("rolling_radius_m", rolling_radius_m, false),
    CONFORMA_C_FIELD("approach_m", approach_m, false),
    CONFORMA_C_FIELD("area_m2", area_m2, false),
    CONFORMA_C_FIELD("pmax_Pa", pmax_Pa, false),
    CONFORMA_C_FIELD("adhesion_area_m2", adhesion_area_m2, false),
    CONFORMA_C_FIELD("slip_area_m2", slip_area_m2, false),
    CONFORMA_C_FIELD("frictional_power_W", frictional_power_W, false),
    CONFORMA_C_FIELD("xi", creepage_longitudinal, false),
    CONFORMA_C_FIELD("eta", creepage_lateral, false),
    CONFORMA_C_FIELD("phi_per_m", creepage_spin_per_m, false),
    CONFORMA_C_FIELD("alpha_c_deg", conformity_index_deg, false),
    CONFORMA_C_FIELD("is_conformal", is_conformal, true),
};
#undef CONFORMA_C_FIELD
inline constexpr size_t kCPatchTrackFrameVectors = 4;  // the double[3] members
// A member added to conforma_patch_result (an ABI change) must be added to kCPatchFields or counted as a vector.
static_assert(sizeof(conforma_patch_result) ==
                  (16 + 3 * kCPatchTrackFrameVectors) * sizeof(double) + sizeof(double),
              "conforma_patch_result changed: map its new member to the PatchReport table in kCPatchFields");
static_assert(sizeof(kCPatchFields) / sizeof(kCPatchFields[0]) == 17, "17 scalar members of conforma_patch_result");

// For each field VisitPatchFields visits, in its (fixed) order: the kCPatchFields entries of that name, as a bit
// mask. Found once by name, so that each fill walks the visit with a counter instead of comparing every name with
// every C member (the comparisons were ~0.6 % of a conformal C API evaluation).
inline const std::vector<std::uint32_t>& CPatchFieldsOfVisit() {
  static_assert(sizeof(kCPatchFields) / sizeof(kCPatchFields[0]) <= 32, "one bit per C member");
  static const std::vector<std::uint32_t> masks = [] {
    std::vector<std::uint32_t> out;
    VisitPatchFields(PatchReport{}, [&out](const char* key, const auto&) {
      std::uint32_t mask = 0;
      for (size_t f = 0; f < sizeof(kCPatchFields) / sizeof(kCPatchFields[0]); ++f)
        if (std::strcmp(kCPatchFields[f].table_key, key) == 0) mask |= std::uint32_t{1} << f;
      out.push_back(mask);
    });
    return out;
  }();
  return masks;
}

// Fills the scalar members of `out` from `patch` through the field table.
inline void FillCPatchScalars(const PatchReport& patch, conforma_patch_result* out) {
  const std::vector<std::uint32_t>& masks = CPatchFieldsOfVisit();
  size_t visit = 0;
  VisitPatchFields(patch, [out, &masks, &visit](const char*, const auto& value) {
    using T = std::decay_t<decltype(value)>;
    const std::uint32_t mask = masks[visit++];
    if constexpr (std::is_arithmetic_v<T>) {
      for (size_t f = 0; (mask >> f) != 0; ++f) {  // (up to the highest set bit; none for a field without member)
        if (!((mask >> f) & 1u)) continue;
        char* member = reinterpret_cast<char*>(out) + kCPatchFields[f].offset;
        if (kCPatchFields[f].is_int) {
          const int v = static_cast<int>(value);
          std::memcpy(member, &v, sizeof v);
        } else {
          const double v = static_cast<double>(value);
          std::memcpy(member, &v, sizeof v);
        }
      }
    }
  });
}

}  // namespace conforma::capi
