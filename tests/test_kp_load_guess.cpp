// Load control's first guess (LoadControlOptions::hertz_initial_guess) changes only the path of the iteration:
// with and without it the KP load control converges to the same approach (a Hertzian, a groove and a two-patch
// wheel, every KP model), and on a Hertzian patch the guess is already within a few per cent of the KPEC answer.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "conforma/load_control.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

void ExpectSameSolution(const std::vector<WheelPatch>& patches, double load, const KpOptions& kp, const char* what) {
  LoadControlOptions with_guess, without_guess;
  with_guess.kp = without_guess.kp = kp;
  without_guess.hertz_initial_guess = false;
  const WheelNormalResult a = SolveWheelForLoad(patches, load, with_guess);
  const WheelNormalResult b = SolveWheelForLoad(patches, load, without_guess);
  ASSERT_EQ(a.status, LoadControlStatus::Ok) << what;
  ASSERT_EQ(b.status, LoadControlStatus::Ok) << what;
  EXPECT_NEAR(a.load_N / load - 1.0, 0.0, with_guess.relative_tolerance) << what;
  // N ~ delta^1.5 near the solution: a load tolerance tol moves delta by at most ~tol / 1.5 on either side
  EXPECT_NEAR(a.approach_m / b.approach_m - 1.0, 0.0, 2.0 * with_guess.relative_tolerance) << what;
  EXPECT_NEAR(a.patches[0].pmax_Pa / b.patches[0].pmax_Pa - 1.0, 0.0, 1e-9) << what;
}

TEST(KpLoadGuess, SameSolutionWithAndWithoutTheHertzGuess) {
  const Material material;
  const PatchGeometry tread = kp_test::HertzianPatch(0.55, 0.96, 0.012, 81);
  const PatchGeometry groove = kp_test::GroovePatch(10e-3, 10.05e-3, 0.42, 12e-3, 241);
  const PatchGeometry flange = kp_test::HertzianPatch(1.2, 8.0, 0.006, 61);
  for (const KpOptions& kp : {PlanarKpOptions(material), KpecOptions(material), ConformalKpOptions(material),
                              ConformalKpecOptions(material)}) {
    ExpectSameSolution({WheelPatch{&tread, 0.0, 1.0}}, 50e3, kp, "tread");
    ExpectSameSolution({WheelPatch{&groove, 0.0, 1.0}}, 10e3, kp, "groove");
    ExpectSameSolution({WheelPatch{&tread, 0.0, 1.0}, WheelPatch{&flange, 2e-5, 0.6}}, 80e3, kp, "two patches");
  }
}

TEST(KpLoadGuess, HertzianPatchNeedsFewSolves) {
  // KPEC is exact for elliptic patches (docs/physics-reference.md §3.3): the Hertz guess lands on the answer up to the
  // strip discretisation, and the power-law step finishes it.
  const PatchGeometry tread = kp_test::HertzianPatch(0.55, 0.96, 0.012, 81);
  LoadControlOptions options;
  options.kp = KpecOptions(Material{});
  options.relative_tolerance = 1e-6;
  const WheelNormalResult r = SolveWheelForLoad({WheelPatch{&tread, 0.0, 1.0}}, 50e3, options);
  ASSERT_EQ(r.status, LoadControlStatus::Ok);
  EXPECT_LE(r.evaluations, 2);
}

}  // namespace
}  // namespace conforma
