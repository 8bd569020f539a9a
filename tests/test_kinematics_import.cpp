// Kinematics CSV import/export (kinematics_import.hpp): bit-identical round trip, free column order and extra
// columns, default weights, errors naming the column / file:line.
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>

#include "conforma/error.hpp"
#include "conforma/kinematics_import.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma {
namespace {

std::string TempPath(const std::string& name) {
  return testing::TempDir() + "conforma_kin_" + name + ".csv";
}

void Write(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; }

void ExpectBitIdentical(const KinematicsSample& a, const KinematicsSample& b) {
  EXPECT_EQ(a.wheelset, b.wheelset);
  const double va[] = {a.time_s, a.weight, a.pose.lateral_m, a.pose.vertical_m, a.pose.roll_rad, a.pose.yaw_rad,
                       a.velocity.forward_speed_m_s, a.velocity.lateral_velocity_m_s, a.velocity.yaw_rate_rad_s,
                       a.velocity.axle_angular_velocity_rad_s, a.vertical_load_N[0], a.vertical_load_N[1],
                       a.track_curvature_per_m};
  const double vb[] = {b.time_s, b.weight, b.pose.lateral_m, b.pose.vertical_m, b.pose.roll_rad, b.pose.yaw_rad,
                       b.velocity.forward_speed_m_s, b.velocity.lateral_velocity_m_s, b.velocity.yaw_rate_rad_s,
                       b.velocity.axle_angular_velocity_rad_s, b.vertical_load_N[0], b.vertical_load_N[1],
                       b.track_curvature_per_m};
  for (size_t k = 0; k < sizeof(va) / sizeof(va[0]); ++k)
    EXPECT_TRUE(SameBits(va[k], vb[k])) << "field " << k << ": " << va[k] << " vs " << vb[k];
}

TEST(KinematicsCsv, ExportImportRoundTripIsBitIdentical) {
  KinematicsSeries s;
  s.source = "synthetic";
  for (int k = 0; k < 7; ++k) {
    KinematicsSample x;
    x.wheelset = k % 3;
    x.time_s = k / 3.0;
    x.weight = 1.0 / 3.0;
    x.pose.lateral_m = -std::exp(-k) * 1e-3;
    x.pose.vertical_m = k == 2 ? -0.0 : 1e-300 * k;
    x.pose.roll_rad = std::nextafter(1e-3, 1.0);
    x.pose.yaw_rad = M_PI * 1e-3 * (k - 3);
    x.velocity.forward_speed_m_s = 70.0 / 3.6;
    x.velocity.lateral_velocity_m_s = std::numeric_limits<double>::denorm_min() * k;
    x.velocity.yaw_rate_rad_s = x.velocity.forward_speed_m_s / 345.0;
    x.velocity.axle_angular_velocity_rad_s = x.velocity.forward_speed_m_s / 0.43;
    x.vertical_load_N[0] = 51234.56789 + k;
    x.vertical_load_N[1] = std::sqrt(2.0) * 4e4;
    x.track_curvature_per_m = 1.0 / 345.0;
    s.samples.push_back(x);
  }
  const std::string path = TempPath("roundtrip");
  ExportKinematicsCsv(s, path);
  const KinematicsSeries r = ImportKinematicsCsv(path);
  ASSERT_EQ(r.samples.size(), s.samples.size());
  for (size_t k = 0; k < s.samples.size(); ++k) ExpectBitIdentical(s.samples[k], r.samples[k]);
  EXPECT_TRUE(std::signbit(r.samples[2].pose.vertical_m));
  // and a second export of the imported series is the same file content
  const std::string path2 = TempPath("roundtrip2");
  ExportKinematicsCsv(r, path2);
  const KinematicsSeries r2 = ImportKinematicsCsv(path2);
  for (size_t k = 0; k < s.samples.size(); ++k) ExpectBitIdentical(r.samples[k], r2.samples[k]);
}

TEST(KinematicsCsv, QuasiStaticSeriesRoundTrips) {
  TrackSetup t = MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R50E4, 0.0), rail_inclination_1in20());
  const VehicleParameters v = MetroVehicle();
  t.nominal_radius_m = {v.nominal_wheel_radius_m, v.nominal_wheel_radius_m};
  const WheelsetTrackGeometry g(t);
  TrackClass c;
  c.name = "R500";
  c.curve_radius_m = 500.0;
  c.cant_m = 0.05;
  c.speed_m_s = 15.0;
  const QuasiStaticResult q = SolveQuasiStaticCurving(v, g, c, QuasiStaticOptions{});
  ASSERT_EQ(q.status, QuasiStaticStatus::Converged);
  const std::string path = TempPath("quasistatic");
  ExportKinematicsCsv(q.series, path);
  const KinematicsSeries r = ImportKinematicsCsv(path);
  ASSERT_EQ(r.samples.size(), q.series.samples.size());
  for (size_t k = 0; k < r.samples.size(); ++k) ExpectBitIdentical(q.series.samples[k], r.samples[k]);
}

TEST(KinematicsCsv, ColumnOrderIsFreeExtraColumnsIgnoredWeightsDefaultEqual) {
  const std::string path = TempPath("order");
  Write(path,
        "# exported by some MBS code\n"
        "\n"
        "load_right_N, wheelset ,time_s,y_m,z_m,roll_rad,yaw_rad,dy_m_s,dyaw_rad_s,speed_m_s,omega_rad_s,"
        "load_left_N,Fy_axlebox_N\n"
        "50000,0,0.0,-0.001,0,0.0005,-0.002,0.01,0.05,15,42.2,40000,123\n"
        "50001,0,0.1,-0.002,0,0.0006,-0.003,0.02,0.05,15,42.2,40001,124\n"
        "# a comment between samples\n"
        "50002,1,0.0,-0.003,0,0.0007,-0.004,0.03,0.05,15,42.2,40002,125\n");
  const KinematicsSeries s = ImportKinematicsCsv(path);
  ASSERT_EQ(s.samples.size(), 3u);
  EXPECT_EQ(s.samples[1].wheelset, 0);
  EXPECT_EQ(s.samples[2].wheelset, 1);
  EXPECT_DOUBLE_EQ(s.samples[1].vertical_load_N[1], 50001.0);
  EXPECT_DOUBLE_EQ(s.samples[1].vertical_load_N[0], 40001.0);
  EXPECT_DOUBLE_EQ(s.samples[1].pose.lateral_m, -0.002);
  EXPECT_DOUBLE_EQ(s.samples[1].pose.yaw_rad, -0.003);
  EXPECT_DOUBLE_EQ(s.samples[1].velocity.lateral_velocity_m_s, 0.02);
  EXPECT_DOUBLE_EQ(s.samples[1].time_s, 0.1);
  EXPECT_DOUBLE_EQ(s.samples[0].weight, 0.5);  // two samples of wheelset 0
  EXPECT_DOUBLE_EQ(s.samples[2].weight, 1.0);  // one sample of wheelset 1
  EXPECT_EQ(s.samples[0].track_curvature_per_m, 0.0);
}

TEST(KinematicsCsv, MissingColumnIsNamedWithTheFile) {
  const std::string path = TempPath("missing");
  Write(path, "time_s,wheelset,y_m,z_m,roll_rad,yaw_rad,dy_m_s,speed_m_s,omega_rad_s,load_left_N,load_right_N\n"
              "0,0,0,0,0,0,0,15,42,40000,40000\n");
  try {
    ImportKinematicsCsv(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("dyaw_rad_s"), std::string::npos) << m;
    EXPECT_NE(m.find(path), std::string::npos) << m;
  }
}

TEST(KinematicsCsv, BadCellsGiveFileAndLine) {
  const std::string header =
      "time_s,wheelset,y_m,z_m,roll_rad,yaw_rad,dy_m_s,dyaw_rad_s,speed_m_s,omega_rad_s,load_left_N,load_right_N\n";
  struct Case { std::string row, what; };
  const Case cases[] = {{"0,0,0.001x,0,0,0,0,0,15,42,40000,40000", "y_m"},
                        {"0,0,nan,0,0,0,0,0,15,42,40000,40000", "y_m"},
                        {"0,0,0,0,0,0,0,0,15,42,-1,40000", "load_left_N"},
                        {"0,1.5,0,0,0,0,0,0,15,42,40000,40000", "wheelset"},
                        {"0,0,0,0,0,0,0,0,15,42,40000", "cells"},
                        {"0,0,0,0,0,,0,0,15,42,40000,40000", "yaw_rad"}};
  for (const Case& c : cases) {
    const std::string path = TempPath("bad");
    Write(path, "# comment\n" + header + "0,0,0,0,0,0,0,0,15,42,40000,40000\n" + c.row + "\n");
    try {
      ImportKinematicsCsv(path);
      ADD_FAILURE() << "expected InputError for " << c.row;
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(path + ":4"), std::string::npos) << m;
      EXPECT_NE(m.find(c.what), std::string::npos) << m;
    }
  }
  EXPECT_THROW(ImportKinematicsCsv(TempPath("does_not_exist_dir/x")), InputError);
}

}  // namespace
}  // namespace conforma
