// test-links: hertz_fastsim
// Similitude rules of scaled roller rigs (conforma/similitude.hpp, docs/physics-reference.md §7.6): scaling and
// unscaling, paper 000's "37 kg per wheel at 1:5 ~ 10 t/axle", and the contact factors against the Hertz solution.
#include <gtest/gtest.h>

#include <cmath>

#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/similitude.hpp"

namespace conforma {
namespace {

const SimilitudeQuantity kAll[] = {
    SimilitudeQuantity::Length,          SimilitudeQuantity::Time,          SimilitudeQuantity::Speed,
    SimilitudeQuantity::AngularSpeed,    SimilitudeQuantity::Acceleration,  SimilitudeQuantity::Mass,
    SimilitudeQuantity::Force,           SimilitudeQuantity::Stiffness,     SimilitudeQuantity::Damping,
    SimilitudeQuantity::ContactSemiAxis, SimilitudeQuantity::ContactPressure, SimilitudeQuantity::CreepCoefficient,
    SimilitudeQuantity::Creepage};

TEST(Similitude, ScalingThenUnscalingGivesBackTheValue) {
  for (SimilitudeRule rule : {SimilitudeRule::ContactStress, SimilitudeRule::Weight})
    for (double phi : {0.2, 0.25, 1.0 / 3.5})
      for (SimilitudeQuantity q : kAll) {
        const SimilitudeOptions o{phi, rule};
        const double full = 1234.5;
        EXPECT_NEAR(ScaleToFull(ScaleToModel(full, q, o), q, o), full, 1e-12 * full) << to_string(q);
      }
  EXPECT_THROW(SimilitudeFactor(SimilitudeQuantity::Force, SimilitudeOptions{0.0, SimilitudeRule::Weight}),
               InputError);
  EXPECT_EQ(SimilitudeRuleFromName("weight"), SimilitudeRule::Weight);
  EXPECT_THROW(SimilitudeRuleFromName("froude"), InputError);
}

// Internal consistency: speed = length / time, acceleration = speed / time, force = mass x acceleration (inertia),
// stiffness = force / length, damping = force / speed, for both rules.
TEST(Similitude, DerivedFactorsAreDimensionallyConsistent) {
  for (SimilitudeRule rule : {SimilitudeRule::ContactStress, SimilitudeRule::Weight}) {
    const SimilitudeOptions o{0.2, rule};
    auto f = [&](SimilitudeQuantity q) { return SimilitudeFactor(q, o); };
    EXPECT_NEAR(f(SimilitudeQuantity::Speed), f(SimilitudeQuantity::Length) / f(SimilitudeQuantity::Time), 1e-12);
    EXPECT_NEAR(f(SimilitudeQuantity::Acceleration), f(SimilitudeQuantity::Speed) / f(SimilitudeQuantity::Time), 1e-12);
    EXPECT_NEAR(f(SimilitudeQuantity::Force), f(SimilitudeQuantity::Mass) * f(SimilitudeQuantity::Acceleration),
                1e-12);
    EXPECT_NEAR(f(SimilitudeQuantity::Stiffness), f(SimilitudeQuantity::Force) / f(SimilitudeQuantity::Length), 1e-12);
    EXPECT_NEAR(f(SimilitudeQuantity::Damping), f(SimilitudeQuantity::Force) / f(SimilitudeQuantity::Speed), 1e-12);
    EXPECT_NEAR(f(SimilitudeQuantity::AngularSpeed), f(SimilitudeQuantity::Speed) / f(SimilitudeQuantity::Length),
                1e-12);
  }
  // gravity is kept only by the weight rule
  EXPECT_DOUBLE_EQ(SimilitudeFactor(SimilitudeQuantity::Acceleration, {0.2, SimilitudeRule::Weight}), 1.0);
  EXPECT_NEAR(SimilitudeFactor(SimilitudeQuantity::Acceleration, {0.2, SimilitudeRule::ContactStress}), 5.0, 1e-12);
}

// Paper 000 §5.1: "37 kg vertically on each wheel, around 10 tons/axle in full scale". The weight rule (force phi^3)
// gives 2 x 37 x 125 = 9.25 t; the contact-stress rule (force phi^2) gives 1.85 t.
TEST(Similitude, PaperLoadOf37KgPerWheelIsAbout10TonnesPerAxleUnderTheWeightRule) {
  const double weight_t = 2.0 * ScaleToFull(37.0, SimilitudeQuantity::Force, {0.2, SimilitudeRule::Weight}) * 1e-3;
  const double stress_t =
      2.0 * ScaleToFull(37.0, SimilitudeQuantity::Force, {0.2, SimilitudeRule::ContactStress}) * 1e-3;
  EXPECT_NEAR(weight_t, 9.25, 1e-9);
  EXPECT_NEAR(stress_t, 1.85, 1e-9);
  EXPECT_LT(std::abs(weight_t - 10.0), 1.0);  // "around 10 tons/axle"
  EXPECT_GT(std::abs(stress_t - 10.0), 5.0);
}

// The contact factors are those of the Hertz solution with the same steel and every radius scaled by phi.
TEST(Similitude, ContactFactorsMatchHertz) {
  const Material steel;
  const double A = 1.06, B = 6.12, N = 45e3;  // full-scale wheel on rail, 45 kN
  const HertzResult full = SolveHertzForLoad(A, B, N, steel);
  for (SimilitudeRule rule : {SimilitudeRule::ContactStress, SimilitudeRule::Weight}) {
    const SimilitudeOptions o{0.2, rule};
    const HertzResult model = SolveHertzForLoad(A / 0.2, B / 0.2, ScaleToModel(N, SimilitudeQuantity::Force, o), steel);
    EXPECT_NEAR(model.a_m / full.a_m, SimilitudeFactor(SimilitudeQuantity::ContactSemiAxis, o), 1e-9);
    EXPECT_NEAR(model.b_m / full.b_m, SimilitudeFactor(SimilitudeQuantity::ContactSemiAxis, o), 1e-9);
    EXPECT_NEAR(model.p0_Pa / full.p0_Pa, SimilitudeFactor(SimilitudeQuantity::ContactPressure, o), 1e-9);
    EXPECT_NEAR(model.a_m * model.b_m / (full.a_m * full.b_m),
                SimilitudeFactor(SimilitudeQuantity::CreepCoefficient, o), 1e-9);
  }
}

}  // namespace
}  // namespace conforma
