// Load control's first guess (KpLoadOptions::hertz_initial_guess) changes only the path of the iteration:
// with and without it the KP load control converges to the same approach (a Hertzian and a groove patch, every
// KP model).
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/validation/analytic_patches.hpp"

namespace conforma {
namespace {

void ExpectSameSolution(const PatchGeometry& patch, double load, const KpOptions& kp, const char* what) {
  KpLoadOptions with_guess, without_guess;
  with_guess.kp = without_guess.kp = kp;
  without_guess.hertz_initial_guess = false;
  const KpResult a = SolveKikPiotrowskiForLoad(patch, load, with_guess);
  const KpResult b = SolveKikPiotrowskiForLoad(patch, load, without_guess);
  ASSERT_EQ(a.status, KpStatus::Ok) << what;
  ASSERT_EQ(b.status, KpStatus::Ok) << what;
  EXPECT_NEAR(a.fn_N / load - 1.0, 0.0, with_guess.relative_tolerance) << what;
  // N ~ delta^1.5 near the solution: a load tolerance tol moves delta by at most ~tol / 1.5 on either side
  EXPECT_NEAR(a.approach_m / b.approach_m - 1.0, 0.0, 2.0 * with_guess.relative_tolerance) << what;
  EXPECT_NEAR(a.pmax_Pa / b.pmax_Pa - 1.0, 0.0, 1e-9) << what;
}

TEST(KpLoadGuess, SameSolutionWithAndWithoutTheHertzGuess) {
  const Material material;
  const PatchGeometry tread = kp_test::HertzianPatch(0.55, 0.96, 0.012, 81);
  const PatchGeometry groove = kp_test::GroovePatch(10e-3, 10.05e-3, 0.42, 12e-3, 241);
  for (const KpOptions& kp : {PlanarKpOptions(material), KpecOptions(material), ConformalKpOptions(material),
                              ConformalKpecOptions(material)}) {
    ExpectSameSolution(tread, 50e3, kp, "tread");
    ExpectSameSolution(groove, 10e3, kp, "groove");
  }
}

}  // namespace
}  // namespace conforma
