// The KP solvers refuse a PatchGeometry with a non-finite value, naming the field and the strip, whatever the
// position of the bad value (the fast finiteness pass of kp_patch_interpolant.cpp must not miss any), and solve
// the same patch unchanged when every value is finite; load control (which prepares each patch once) too.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "conforma/error.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

TEST(KpPatchInput, EveryNonFiniteValueIsNamed) {
  const PatchGeometry good = kp_test::HertzianPatch(0.55, 0.96, 0.012, 81);
  const KpOptions options = ConformalKpecOptions(Material{});
  const double bad_values[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                               -std::numeric_limits<double>::infinity()};
  for (const char* field : {"gap_m", "longitudinal_curvature_per_m", "alpha_rad", "x_offset_m"}) {
    for (size_t index : {size_t{0}, size_t{37}, good.s_m.size() - 1}) {
      for (double bad : bad_values) {
        PatchGeometry patch = good;
        if (patch.alpha_rad.empty()) patch.alpha_rad.assign(patch.s_m.size(), 0.0);
        if (patch.x_offset_m.empty()) patch.x_offset_m.assign(patch.s_m.size(), 0.0);
        std::vector<double>& values = std::string(field) == "gap_m"                          ? patch.gap_m
                                      : std::string(field) == "longitudinal_curvature_per_m" ? patch.longitudinal_curvature_per_m
                                      : std::string(field) == "alpha_rad"                    ? patch.alpha_rad
                                                                                             : patch.x_offset_m;
        values[index] = bad;
        try {
          SolveKikPiotrowskiForApproach(patch, 2e-5, options);
          ADD_FAILURE() << field << "[" << index << "] = " << bad << " was accepted";
        } catch (const InputError& error) {
          EXPECT_NE(std::string(error.what()).find(std::string(field) + "[" + std::to_string(index) + "]"),
                    std::string::npos)
              << error.what();
        }
        KpLoadOptions load_options;
        load_options.kp = options;
        EXPECT_THROW(SolveKikPiotrowskiForLoad(patch, 1e4, load_options), InputError) << field << " " << index;
      }
    }
  }
}

TEST(KpPatchInput, FinitePatchSolves) {
  const PatchGeometry patch = kp_test::HertzianPatch(0.55, 0.96, 0.012, 81);
  const KpResult result = SolveKikPiotrowskiForApproach(patch, 2e-5, ConformalKpecOptions(Material{}));
  EXPECT_EQ(result.status, KpStatus::Ok);
  EXPECT_GT(result.fn_N, 0.0);
}

}  // namespace
}  // namespace conforma
