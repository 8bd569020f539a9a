// Generated standard profiles against the exact definitions and the Manchester benchmark files
// (docs/profiles-and-formats.md §1.1, §1.2).
// test-links: profiles  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"

using namespace conforma;

namespace {

const std::string kExamples = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/examples/";

// Largest normal distance [m] of the points (within the z window) from the profile curve.
double max_distance(const Profile& prof, const std::vector<Eigen::Vector2d>& pts, double z_min, double* rms = nullptr) {
  double worst = 0, sum2 = 0;
  int n = 0;
  for (const auto& q : pts) {
    if (q.y() < z_min) continue;
    const double d = (prof.position(prof.closest_s(q)) - q).norm();
    worst = std::max(worst, d);
    sum2 += d * d;
    ++n;
  }
  if (rms) *rms = std::sqrt(sum2 / std::max(n, 1));
  return worst;
}

// Head width [m]: distance between the two crossings of the horizontal line z with the rail surface.
double head_width(const Profile& rail, double z) {
  std::vector<double> ys;
  const auto p = rail.sample(0.01e-3);
  for (size_t i = 0; i + 1 < p.size(); ++i)
    if ((p[i].y() - z) * (p[i + 1].y() - z) <= 0 && p[i].y() != p[i + 1].y())
      ys.push_back(p[i].x() + (p[i + 1].x() - p[i].x()) * (z - p[i].y()) / (p[i + 1].y() - p[i].y()));
  if (ys.size() < 2) return NAN;
  return *std::max_element(ys.begin(), ys.end()) - *std::min_element(ys.begin(), ys.end());
}

}  // namespace

TEST(ProfileStandard, S1002PiecewiseDefinitionChecks) {
  // §1.1 [computed] values: F(0) = 0, flange tip F(-55) = 28, F(60), F(-70) and C0 continuity at the joints.
  EXPECT_NEAR(S1002Height_mm(0.0), 0.0, 1e-9);
  EXPECT_NEAR(S1002Height_mm(-55.0), 28.0, 1e-9);
  EXPECT_NEAR(S1002Height_mm(60.0), -2.6356764, 1e-6);
  EXPECT_NEAR(S1002Height_mm(-70.0), 9.519259302, 1e-9);
  EXPECT_NEAR(S1002Height_mm(-37.5), 10.0, 1e-5);  // Sd point: 70 - 37.5 = 32.5 mm
  const Profile w = MakeS1002();
  EXPECT_EQ(w.kind(), ProfileKind::Wheel);
  for (double S : {-65.0, -55.0, -45.0, -36.0, -30.0, -10.0, 0.0, 20.0, 45.0, 59.0})
    EXPECT_NEAR(*w.height_at(S * 1e-3), S1002Height_mm(S) * 1e-3, 2e-7) << "S = " << S;
  EXPECT_NEAR(w.y_min(), -0.070, 1e-9);
  EXPECT_NEAR(w.y_max(), 0.060, 1e-9);
}

TEST(ProfileStandard, S1002MatchesManchesterBenchmarkFile) {
  const Profile gen = MakeS1002();
  const auto file = ReadProfilePoints(kExamples + "MBench_S1002_v3.prw");
  ASSERT_EQ(file.kind, ProfileKind::Wheel);
  double rms = 0;
  const double worst = max_distance(gen, file.points_m, -1.0, &rms);
  std::printf("S1002 generated vs MBench_S1002_v3.prw: %zu points, max %.3g mm, rms %.3g mm\n", file.points_m.size(),
              worst * 1e3, rms * 1e3);
  EXPECT_LE(worst, 0.001e-3);
}

TEST(ProfileStandard, UIC60At1in40MatchesManchesterBenchmarkFileOverTop12mm) {
  const Profile gen = MakeRail(RailSection::R60E1, rail_inclination_1in40());
  const auto file = ReadProfilePoints(kExamples + "MBench_UIC60_v3.prr");
  ASSERT_EQ(file.kind, ProfileKind::Rail);
  double rms = 0;
  const double worst = max_distance(gen, file.points_m, -0.012, &rms);
  std::printf("60E1 1:40 generated vs MBench_UIC60_v3.prr (top 12 mm): max %.4f mm, rms %.4f mm\n", worst * 1e3, rms * 1e3);
  EXPECT_LE(worst, 0.05e-3);
  // highest point at the origin
  double zmax = -1;
  for (const auto& q : gen.sample(0.01e-3)) zmax = std::max(zmax, q.y());
  EXPECT_NEAR(zmax, 0.0, 1e-9);
}

TEST(ProfileStandard, RailHeadWidthsFromTable) {
  // §1.2 table: head width 2|y(T3)| at z(T3), vertical rail.
  struct Row { RailSection r; double width_mm, z_mm; };
  for (const Row& row : {Row{RailSection::R60E1, 72.000, -14.300}, Row{RailSection::R54E1, 70.000, -14.100},
                         Row{RailSection::R50E4, 70.000, -14.100}, Row{RailSection::R50E6, 65.000, -13.580}}) {
    const Profile rail = MakeRail(row.r, 0.0);
    const double w = head_width(rail, row.z_mm * 1e-3);
    std::printf("%s head width at z = %.3f mm: %.4f mm (table %.3f)\n", to_string(row.r), row.z_mm, w * 1e3, row.width_mm);
    EXPECT_NEAR(w * 1e3, row.width_mm, 0.002) << to_string(row.r);
    EXPECT_NEAR(*rail.height_at(0.0), 0.0, 1e-10);
    // symmetric
    EXPECT_NEAR(*rail.height_at(0.02), *rail.height_at(-0.02), 1e-9);
  }
  // width 14 mm below the top, vertical rails (table column "width at 14 mm below top")
  EXPECT_NEAR(head_width(MakeRail(RailSection::R60E1, 0.0), -0.014) * 1e3, 71.963, 0.002);
  EXPECT_NEAR(head_width(MakeRail(RailSection::R50E6, 0.0), -0.014) * 1e3, 65.042, 0.002);
}

TEST(ProfileStandard, InclinationCantsTowardsTrackCentre) {
  // canted towards -y: the highest point moves to the field side of the head axis by R1 sin(alpha) (on R300)
  const double a = rail_inclination_1in40();
  const Profile gen = MakeRail(RailSection::R60E1, a);
  const Profile vert = MakeRail(RailSection::R60E1, 0.0);
  // the crown centre (0,-300) mm moves to (300 sin a, -300 cos a); its top point is the new origin
  const Eigen::Vector2d p = vert.position(vert.closest_s({0.02, -0.001}));
  const double c = std::cos(a), s = std::sin(a);
  const Eigen::Vector2d rotated(c * p.x() - s * p.y(), s * p.x() + c * p.y());
  const Eigen::Vector2d top(0.300 * s, 0.300 * (1.0 - c));  // rotated crown centre + (0, R1)
  const Eigen::Vector2d q = rotated - top;
  EXPECT_NEAR(*gen.height_at(q.x()), q.y(), 1e-8);
  EXPECT_NEAR(top.x() * 1e3, 7.4977, 1e-3);
}

TEST(ProfileStandard, CommittedProfileFilesMatchTheGenerators) {
  const std::filesystem::path tmp = std::filesystem::temp_directory_path() / ("conforma_std_" + std::to_string(::getpid()));
  std::filesystem::create_directories(tmp);
  WriteStandardProfiles(tmp.string());
  int n = 0;
  for (const auto& e : std::filesystem::directory_iterator(tmp)) {
    const auto committed = std::filesystem::path(CONFORMA_SOURCE_DIR) / "profiles" / e.path().filename();
    std::ifstream a(e.path()), b(committed);
    ASSERT_TRUE(b.good()) << "missing committed file " << committed;
    // line by line; numeric lines may differ in the last printed digit between compilers (1e-6 mm)
    std::string la, lb;
    int line = 0;
    bool same = true;
    while (same) {
      const bool ga = static_cast<bool>(std::getline(a, la)), gb = static_cast<bool>(std::getline(b, lb));
      ++line;
      if (!ga || !gb) { same = ga == gb; break; }
      if (la == lb) continue;
      double ya, za, yb, zb;
      same = std::sscanf(la.c_str(), "%lf %lf", &ya, &za) == 2 && std::sscanf(lb.c_str(), "%lf %lf", &yb, &zb) == 2 &&
             std::abs(ya - yb) < 1e-6 && std::abs(za - zb) < 1e-6;
    }
    EXPECT_TRUE(same) << committed << " differs from the generator at line " << line
                      << "; regenerate with WriteStandardProfiles";
    ++n;
  }
  EXPECT_EQ(n, 13);
  std::filesystem::remove_all(tmp);
}

TEST(ProfileStandard, RailFlanksReachAtLeast25mmBelowTheTop) {
  for (RailSection r : {RailSection::R60E1, RailSection::R54E1, RailSection::R50E6, RailSection::R50E4})
    for (double a : {0.0, rail_inclination_1in40(), rail_inclination_1in20()}) {
      const Profile p = MakeRail(r, a);
      EXPECT_LE(p.position(0.0).y(), -0.025) << to_string(r) << " gauge side, inclination " << a;
      EXPECT_LE(p.position(p.length()).y(), -0.025) << to_string(r) << " field side, inclination " << a;
      // gauge side first (s increases towards the field side), highest point at the origin
      EXPECT_LT(p.position(0.0).x(), p.position(p.length()).x());
      EXPECT_NEAR(*p.height_at(0.0), 0.0, 1e-9);
      // the 1:20 head flank is straight: zero curvature 20 mm below the top on the gauge side
      EXPECT_NEAR(p.curvature(p.closest_s({-0.040, -0.020})), 0.0, 1.0);
    }
}
