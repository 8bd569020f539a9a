// Wheel reference dimensions Sd, Sh, qR (paper 001 §7.2, paper 003 §7) on S1002 (nominal 32.5 / 28.0 / 10.8 mm,
// exact values from the piecewise definition: 32.500 / 28.000 / 10.794 mm, docs/profiles-and-formats.md §1.1) and on
// MiniProf wheel files against the values in their headers.
// test-links: profiles  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_dimensions.hpp"

using namespace conforma;

namespace {
const std::string kData = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/";

void expect_s1002(const WheelDimensions& d, const char* what) {
  std::printf("%s: Sd = %.4f mm, Sh = %.4f mm, qR = %.4f mm\n", what, d.sd_m * 1e3, d.sh_m * 1e3, d.qr_m * 1e3);
  EXPECT_NEAR(d.sd_m * 1e3, 32.50, 0.02) << what;
  EXPECT_NEAR(d.sh_m * 1e3, 28.00, 0.02) << what;
  EXPECT_NEAR(d.qr_m * 1e3, 10.79, 0.05) << what;
}
}  // namespace

TEST(WheelDimensions, S1002Generated) {
  const WheelDimensions d = MeasureWheelDimensions(MakeS1002());
  expect_s1002(d, "S1002 generated");
  // points used: tip at S = -55 (F = 28), Sd point at S = -37.5 (F = 10), qR point at S = -48.29382 (F = 26)
  EXPECT_NEAR(d.tip.x() * 1e3, -55.0, 0.01);
  EXPECT_NEAR(d.sd_point.x() * 1e3, -37.5, 1e-3);
  EXPECT_NEAR(d.qr_point.x() * 1e3, -48.29382, 1e-3);
  EXPECT_NEAR(d.p0.y(), 0.0, 1e-9);
}

TEST(WheelDimensions, S1002ManchesterFile) {
  expect_s1002(MeasureWheelDimensions(LoadProfile(kData + "examples/MBench_S1002_v3.prw")), "MBench_S1002_v3.prw");
}

TEST(WheelDimensions, ShiftedProfileGivesSameDimensions) {
  // Sd/Sh/qR are relative to P0 and the flange back: lifting the profile by 3 mm changes nothing.
  std::vector<Eigen::Vector2d> pts = MakeS1002().samples();
  for (auto& p : pts) p.y() += 3e-3;
  const auto d = MeasureWheelDimensions(Profile::FromPoints(pts, ProfileKind::Wheel));
  expect_s1002(d, "S1002 lifted 3 mm");
}

TEST(WheelDimensions, RefusesProfilesWithoutFlange) {
  EXPECT_THROW(MeasureWheelDimensions(LoadProfile(kData + "testbank/profiles/circ_r100.prw")), InputError);
  EXPECT_THROW(MeasureWheelDimensions(LoadProfile(kData + "testbank/profiles/flat_plane.prw")), InputError);
  EXPECT_THROW(MeasureWheelDimensions(MakeRail(RailSection::R60E1, 0.0)), InputError);
  try {
    MeasureWheelDimensions(LoadProfile(kData + "testbank/profiles/flat_plane.prw"));
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no wheel flange"), std::string::npos) << e.what();
  }
}

TEST(WheelDimensions, MiniProfHeaderValues) {
  // MiniProf files with Sd/Sh/qR in the header (new style Sd=, Sh=, qR=; old style "Sd Sh qR (Sd/Sh/qR)").
  int compared = 0;
  for (const auto& e : std::filesystem::directory_iterator(kData + "testbank/profiles")) {
    if (e.path().extension() != ".whl") continue;
    ProfilePoints pts;
    try {
      pts = ReadProfilePoints(e.path().string());
    } catch (const InputError& err) {
      std::printf("%-28s refused: %s\n", e.path().filename().c_str(), err.what());
      continue;
    }
    if (!pts.header.count("Sd") || !pts.header.count("Sh") || !pts.header.count("qR")) continue;
    const double sd = std::stod(pts.header["Sd"]), sh = std::stod(pts.header["Sh"]), qr = std::stod(pts.header["qR"]);
    const WheelDimensions d = MeasureWheelDimensions(LoadProfile(e.path().string()));
    const bool new_style = pts.header["format"] == "MiniProf new style";
    std::printf("%-28s %s header Sd %.3f Sh %.3f qR %.3f | measured Sd %.3f Sh %.3f qR %.3f | diff %+.3f %+.3f %+.3f mm\n",
                e.path().filename().c_str(), new_style ? "new" : "old", sd, sh, qr, d.sd_m * 1e3, d.sh_m * 1e3,
                d.qr_m * 1e3, d.sd_m * 1e3 - sd, d.sh_m * 1e3 - sh, d.qr_m * 1e3 - qr);
    ++compared;
    if (!new_style) continue;  // old-style files here all carry the same header triple 32.58/37.11/14.71 (Sh 37 mm
                               // is 9 mm off their flange height): not values measured on these profiles
    const std::string name = e.path().filename().string();
    EXPECT_NEAR(d.qr_m * 1e3, qr, 0.05) << name;
    // right-wheel-v1-pre-dry: its header Sh equals (DiameterFlange - DiameterTaperline)/2, i.e. MiniProf took P0
    // 0.17 mm lower than the profile point at y = 70 mm (z there is 0.351 mm); Sd follows via the 70 deg flank.
    if (name == "right-wheel-v1-pre-dry.whl") continue;
    EXPECT_NEAR(d.sd_m * 1e3, sd, 0.05) << name;
    EXPECT_NEAR(d.sh_m * 1e3, sh, 0.05) << name;
  }
  EXPECT_GE(compared, 4);
}
