// Wear laws: USFD regimes and units (paper 003 eqs. 14-17, docs/physics-reference.md §8.1), Archard maps
// (paper 000 Tables 2-3, docs/physics-reference.md §8.2), wear-law files.
// test-links: wear  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "conforma/error.hpp"
#include "conforma/wear_law.hpp"

using namespace conforma;

namespace {
const std::string kLawDir = std::string(CONFORMA_SOURCE_DIR) + "/profiles/wear_laws/";
}

TEST(WearLaw, UsfdRegimeBoundaries) {
  // mild: K = 5.3 I
  EXPECT_DOUBLE_EQ(usfd_wear_rate(0.0), 0.0);
  EXPECT_DOUBLE_EQ(usfd_wear_rate(5.0), 26.5);
  EXPECT_NEAR(usfd_wear_rate(10.4 - 1e-9), 55.12, 1e-6);  // left of the mild/severe limit
  EXPECT_EQ(usfd_regime(10.4 - 1e-9), WearRegime::Mild);
  // severe plateau 55.0 on [10.4, 77.2] (closed at both ends, docs/physics-reference.md §8.1)
  EXPECT_DOUBLE_EQ(usfd_wear_rate(10.4), 55.0);
  EXPECT_EQ(usfd_regime(10.4), WearRegime::Severe);
  EXPECT_DOUBLE_EQ(usfd_wear_rate(40.0), 55.0);
  EXPECT_DOUBLE_EQ(usfd_wear_rate(77.2), 55.0);
  EXPECT_EQ(usfd_regime(77.2), WearRegime::Severe);
  // catastrophic restarts near zero: 61.9 * 77.2 - 4778.7 = -0.02 -> clamped to 0; 77.3 -> 6.17
  EXPECT_EQ(usfd_regime(77.2 + 1e-9), WearRegime::Catastrophic);
  EXPECT_DOUBLE_EQ(usfd_wear_rate(77.2 + 1e-9), 0.0);
  EXPECT_NEAR(usfd_wear_rate(77.3), 61.9 * 77.3 - 4778.7, 1e-9);
  EXPECT_NEAR(usfd_wear_rate(77.3), 6.17, 1e-9);
  EXPECT_NEAR(usfd_wear_rate(100.0), 1411.3, 1e-9);
  // paper 003 prints 55.1 for the plateau: selectable
  UsfdCoefficients paper003;
  paper003.severe_rate = 55.1;
  EXPECT_DOUBLE_EQ(usfd_wear_rate(20.0, paper003), 55.1);
  EXPECT_THROW(usfd_wear_rate(-1.0), InputError);
  EXPECT_THROW(usfd_wear_rate(std::nan("")), InputError);
}

TEST(WearLaw, WearIndexAndDepthUnits) {
  // Hand example: p_t = (400, 300) MPa, s = (0.1, 0): I_w = |p_t . s| = 40 MPa = 40 N/mm^2 (severe)
  //   K_w = 55.0 ug/(m mm^2); a cell of dx = 0.5 mm: 55.0 * 0.5e-3 m = 0.0275 ug/mm^2;
  //   rho = 7850 kg/m^3 = 7850 ug/mm^3 -> depth = 0.0275 / 7850 mm = 3.5032e-6 mm = 3.5032e-9 m.
  const Eigen::Vector2d traction(4e8, 3e8), slip(0.1, 0.0);
  EXPECT_NEAR(wear_index_N_mm2(traction, slip), 40.0, 1e-12);
  EXPECT_NEAR(wear_index_N_mm2(-traction, slip), 40.0, 1e-12);  // sign convention of p_t does not matter
  EXPECT_NEAR(depth_per_rolled_metre_from_rate(55.0, 7850.0), 7.00637e-6, 1e-11);
  WearLaw law;  // default: USFD table
  const double per_metre = law.depth_per_rolled_metre(traction, slip, 1e9, 30.0, Material{});
  EXPECT_NEAR(per_metre * 0.5e-3, 3.5032e-9, 1e-13);
  // mild: p_t = 50 MPa along slip 0.1 -> I = 5 -> K = 26.5 -> 26.5/7850 mm per m
  EXPECT_NEAR(law.depth_per_rolled_metre({5e7, 0}, {0.1, 0}, 1e9, 30.0, Material{}), 26.5 / 7850.0 * 1e-3, 1e-15);
  // adhesion (no slip): no wear
  EXPECT_EQ(law.depth_per_rolled_metre({5e8, 0}, {0.0, 0.0}, 1e9, 30.0, Material{}), 0.0);
}

TEST(WearLaw, UsfdFileAgreesWithBuiltIn) {
  const WearLaw file = LoadWearLaw(kLawDir + "usfd.csv");
  ASSERT_EQ(file.kind, WearLawKind::WearIndex);
  const WearIndexLaw table = WearIndexLaw::Usfd();
  double worst = 0.0;
  for (int k = 0; k <= 30000; ++k) {
    const double I = 0.01 * k + 0.0037;  // never exactly on a breakpoint
    const double ref = usfd_wear_rate(I);
    worst = std::max(worst, std::abs(file.wear_index.rate(I) - ref) / std::max(1.0, ref));
    worst = std::max(worst, std::abs(table.rate(I) - ref) / std::max(1.0, ref));
  }
  EXPECT_LT(worst, 1e-12);
  // on both sides of the jumps
  for (double I : {10.4, 77.2})
    for (double e : {-1e-7, 1e-7}) EXPECT_NEAR(file.wear_index.rate(I + e), usfd_wear_rate(I + e), 1e-5);
  // exactly at a jump the table takes the left value: 55.12 at 10.4 (closed form: 55.0, severe);
  // 55.0 at 77.2 in both.
  EXPECT_NEAR(file.wear_index.rate(10.4), 55.12, 1e-12);
  EXPECT_NEAR(file.wear_index.rate(77.2), 55.0, 1e-12);
  // round trip through the writer
  const WearLaw again = ParseWearLaw(FormatWearLaw(file), "round trip");
  for (double I : {3.0, 30.0, 150.0, 400.0}) EXPECT_DOUBLE_EQ(again.wear_index.rate(I), file.wear_index.rate(I));
}

TEST(WearLaw, ArchardMaps) {
  const ArchardMap jendel = ArchardMap::Jendel();
  jendel.validate();
  const double H = jendel.hardness_Pa;
  EXPECT_DOUBLE_EQ(jendel.coefficient(1e9, 0.1), 5.5e-4);   // K2
  EXPECT_DOUBLE_EQ(jendel.coefficient(1e9, 0.2), 5.5e-4);   // bin limit belongs to the lower bin
  EXPECT_DOUBLE_EQ(jendel.coefficient(1e9, 0.5), 35e-4);    // K3
  EXPECT_DOUBLE_EQ(jendel.coefficient(1e9, 2.0), 5.5e-4);   // K4
  EXPECT_DOUBLE_EQ(jendel.coefficient(0.81 * H, 0.5), 350e-4);  // K1: p > 0.8 H
  ArchardMap::Paper000Wheel().validate();
  ArchardMap::Paper000Roller().validate();
  EXPECT_DOUBLE_EQ(ArchardMap::Paper000Wheel().coefficient(1e6, 0.45), 31.8e-4);
  EXPECT_DOUBLE_EQ(ArchardMap::Paper000Roller().coefficient(1e6, 0.35), 48.2e-4);
  // depth (paper 000 eqs. 8-9): p = 1 GPa, s = (0.006, 0.008) -> |s| = 0.01, V = 30 m/s -> v_slip = 0.3 m/s (K3)
  //   depth per metre rolled = k p |s| / H = 35e-4 * 1e9 * 0.01 / 2.75e9 = 1.272727e-5
  WearLaw law;
  law.kind = WearLawKind::Archard;
  law.archard = jendel;
  EXPECT_NEAR(law.depth_per_rolled_metre({0, 0}, {0.006, 0.008}, 1e9, 30.0, Material{}), 1.2727272727e-5, 1e-14);
  // same file
  const WearLaw file = LoadWearLaw(kLawDir + "archard_jendel.csv");
  ASSERT_EQ(file.kind, WearLawKind::Archard);
  for (double p : {1e8, 1e9, 2.3e9})
    for (double v : {0.05, 0.2, 0.3, 0.69, 0.7, 5.0})
      EXPECT_DOUBLE_EQ(file.archard.coefficient(p, v), jendel.coefficient(p, v)) << p << " " << v;
  EXPECT_DOUBLE_EQ(file.archard.hardness_Pa, jendel.hardness_Pa);
  const WearLaw wheel_file = LoadWearLaw(kLawDir + "archard_paper000_wheel.csv");
  const ArchardMap wheel = ArchardMap::Paper000Wheel();
  EXPECT_DOUBLE_EQ(wheel_file.archard.hardness_Pa, wheel.hardness_Pa);
  for (double p : {1e8, 0.7e9, 0.9e9})
    for (double v : {0.05, 0.15, 0.25, 0.35, 0.45, 0.6, 0.7, 3.0})
      EXPECT_DOUBLE_EQ(wheel_file.archard.coefficient(p, v), wheel.coefficient(p, v)) << p << " " << v;
}

TEST(WearLaw, MalformedFilesNameTheLine) {
  auto message = [](const std::string& text) {
    try {
      ParseWearLaw(text, "law.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("kind,wear_index\npoint,0,0\npoint,abc,3\n").find("law.csv:3"), std::string::npos);
  EXPECT_NE(message("point,0,0\n").find("law.csv:1"), std::string::npos);
  EXPECT_NE(message("kind,magic\n").find("unknown kind"), std::string::npos);
  EXPECT_NE(message("kind,wear_index\npoint,0,0\npoint,5,1\npoint,4,2\n").find("decreases"), std::string::npos);
  EXPECT_NE(message("kind,wear_index\npoint,1,0\npoint,5,1\n").find("I_w = 0"), std::string::npos);
  EXPECT_NE(message("kind,archard\nbin,0.2,1e-4,1e-2\n").find("inf"), std::string::npos);
  EXPECT_NE(message("kind,archard\nbin,0.2,1e-4\n").find("law.csv:2"), std::string::npos);
  EXPECT_THROW(LoadWearLaw(kLawDir + "does_not_exist.csv"), InputError);
}
