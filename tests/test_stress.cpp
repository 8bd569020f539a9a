// Stress suite, fast CI subset (stress.hpp; the long run is `conforma stress --cases 100000`): ~2000 random
// situations over new, worn and noisy profiles, grooves and degenerate patches without NaN/inf, crash or force
// jump; issue 3's wheelset check on a subset; identical results for 1 and 2 OpenMP threads.
// test-links: validation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cstdio>

#include "conforma/validation/stress.hpp"

namespace conforma {
namespace {

const StressSetup& Profiles() {
  static const StressSetup setup = StressSetup::Make(CONFORMA_SHARED_DATA);
  return setup;
}

void Report(const char* label, const StressSummary& s) {
  std::printf("%s: %ld cases (%ld wheel, %ld groove, %ld degenerate), %ld patches, NaN %ld, crashes %ld, "
              "InputError %ld (unexpected %ld), no contact %ld, not converged %ld, continuity pairs %ld (jumps %ld, "
              "steep %ld, violations %ld, max |dF|/load %.2e)\n",
              label, s.cases, s.wheel_cases, s.patch_cases, s.degenerate_cases, s.patches, s.non_finite, s.crashes,
              s.input_errors, s.unexpected_input_errors, s.no_contact, s.not_converged, s.continuity_pairs,
              s.continuity_jumps, s.continuity_steep, s.continuity_violations, s.max_continuity_fraction);
  for (const std::string& f : s.failures) std::printf("  %s\n", f.c_str());
}

TEST(Stress, RandomSituationsGiveFiniteContinuousResults) {
  StressOptions o;
  o.cases = 2000;
  const StressSummary s = RunStress(Profiles(), o);
  Report("stress", s);
  EXPECT_EQ(s.cases, 2000);
  EXPECT_EQ(s.non_finite, 0);
  EXPECT_EQ(s.crashes, 0);
  EXPECT_EQ(s.unexpected_input_errors, 0);
  EXPECT_EQ(s.continuity_violations, 0);
  EXPECT_GT(s.continuity_pairs, 100);
  // most random poses touch (the rest: wheel beyond the rail head at extreme shifts)
  EXPECT_GT(s.patches, s.wheel_cases / 2);
}

TEST(Stress, WheelsetPosesOfIssue3ForTheConformalModel) {
  StressOptions o;
  o.wheelset_mode = true;
  o.cases = 600;
  o.continuity_every = 0;
  const StressSummary s = RunStress(Profiles(), o);
  Report("wheelset", s);
  EXPECT_EQ(s.non_finite, 0);
  EXPECT_EQ(s.crashes, 0);
  EXPECT_EQ(s.unexpected_input_errors, 0);
  EXPECT_GT(s.patches, s.cases);  // two wheels per pose
}

TEST(Stress, ResultsIndependentOfTheThreadCount) {
  StressOptions o;
  o.cases = 240;
  o.first_case = 5000;
  o.threads = 1;
  const StressSummary one = RunStress(Profiles(), o);
  o.threads = 2;
  const StressSummary two = RunStress(Profiles(), o);
  EXPECT_EQ(one.digest, two.digest);
}

}  // namespace
}  // namespace conforma
