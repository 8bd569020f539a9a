// test-links: profiles
// Profile input validation shared by every entry point (src/profiles/profile_checks.cpp, issue 13 items 4, 5, 9,
// 10, spacing): orientation, truncated files, folds parametrised by arc length, noise, spacing and reversals. The
// messages name the file, the line where there is one, and the command-line flag that fixes the input.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/profile_by_name.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_dimensions.hpp"

namespace conforma {
namespace {

namespace fs = std::filesystem;

const std::string kBank = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/testbank/profiles/";
const std::string kEn15302 = std::string(CONFORMA_SHARED_DATA) + "/profiles/en15302/";
const std::string kRepoProfiles = std::string(CONFORMA_SOURCE_DIR) + "/profiles/";

struct TempDir {
  fs::path dir = fs::temp_directory_path() / ("conforma_checks_" + std::to_string(::getpid()));
  TempDir() { fs::create_directories(dir); }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  std::string file(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name, std::ios::binary) << text;
    return (dir / name).string();
  }
};

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// "y,z" lines in mm of a profile's samples, each point transformed by (sy, sz) and with normal noise on z.
std::string Csv(const Profile& p, double sy, double sz, double noise_mm = 0.0, double spacing_mm = 0.1) {
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0.0, noise_mm > 0 ? noise_mm : 1.0);
  std::ostringstream s;
  s.precision(9);
  for (const auto& q : p.sample(spacing_mm * 1e-3))
    s << sy * q.x() * 1e3 << "," << sz * q.y() * 1e3 + (noise_mm > 0 ? n(rng) : 0.0) << "\n";
  return s.str();
}

std::string LoadError(const std::string& path, const ProfileReadOptions& o) {
  try {
    LoadProfile(path, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

ProfileReadOptions Kind(ProfileKind k) {
  ProfileReadOptions o;
  o.kind = k;
  return o;
}

bool Contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Item 4: a y-mirrored S1002 and the z-down EN 15302 wheel are refused naming the file and the flag; with the
// flag they load the right way round (flange tip 28 mm up at y = -55 mm).
TEST(ProfileChecks, WheelOrientationIsCheckedAndTheFlagFixesIt) {
  TempDir tmp;
  const std::string mirrored = tmp.file("s1002_mirrored.csv", Csv(MakeS1002(), -1, 1));
  const std::string msg = LoadError(mirrored, Kind(ProfileKind::Wheel));
  EXPECT_TRUE(Contains(msg, "s1002_mirrored.csv:")) << msg;
  EXPECT_TRUE(Contains(msg, "wheel orientation")) << msg;
  EXPECT_TRUE(Contains(msg, "add --wheel-mirror")) << msg;
  ProfileReadOptions fix = Kind(ProfileKind::Wheel);
  fix.mirror_y = true;
  const Profile w = LoadProfile(mirrored, fix);
  EXPECT_NEAR(*w.height_at(-0.055), 0.028, 1e-5);

  const std::string z_down = tmp.file("s1002_zdown.csv", Csv(MakeS1002(), 1, -1));
  EXPECT_TRUE(Contains(LoadError(z_down, Kind(ProfileKind::Wheel)), "add --wheel-z-down"));

  // EN 15302 wheel files have z down (validation/en15302_conicity.cpp reads them with mirror_z)
  const std::string en = kEn15302 + "RUIC519A.dat";
  const std::string en_msg = LoadError(en, Kind(ProfileKind::Wheel));
  EXPECT_TRUE(Contains(en_msg, "RUIC519A.dat:")) << en_msg;
  EXPECT_TRUE(Contains(en_msg, "points to -z")) << en_msg;
  EXPECT_TRUE(Contains(en_msg, "add --wheel-z-down")) << en_msg;
  ProfileReadOptions en_fix = Kind(ProfileKind::Wheel);
  en_fix.mirror_z = true;
  EXPECT_GT(MeasureWheelDimensions(LoadProfile(en, en_fix)).sh_m, 0.025);
  // the flag set twice (already right + --wheel-z-down) is named for removal
  ProfileReadOptions twice = Kind(ProfileKind::Wheel);
  twice.mirror_z = true;
  EXPECT_TRUE(Contains(LoadError(tmp.file("s1002.csv", Csv(MakeS1002(), 1, 1)), twice), "remove --wheel-z-down"));
  // the same check through the by-name rule every entry point uses
  try {
    WheelProfileByNameOrFile(mirrored, "option --wheel");
    ADD_FAILURE() << "mirrored wheel accepted";
  } catch (const InputError& e) {
    EXPECT_TRUE(Contains(e.what(), "--wheel-mirror")) << e.what();
  }
}

// Item 4 (rail head on top): an upside-down rail is refused, a groove (concave running surface) and flangeless
// test wheels (circles, planes) are accepted.
TEST(ProfileChecks, RailHeadOnTopAndFlangelessShapesAccepted) {
  TempDir tmp;
  const std::string upside = tmp.file("60E1_down.csv", Csv(MakeRail(RailSection::R60E1, 0.0), 1, -1));
  const std::string msg = LoadError(upside, Kind(ProfileKind::Rail));
  EXPECT_TRUE(Contains(msg, "60E1_down.csv:")) << msg;
  EXPECT_TRUE(Contains(msg, "rail head is upside down")) << msg;
  EXPECT_TRUE(Contains(msg, "add --rail-z-down")) << msg;
  ProfileReadOptions fix = Kind(ProfileKind::Rail);
  fix.mirror_z = true;
  EXPECT_NO_THROW(LoadProfile(upside, fix));
  for (const char* f : {"groove_r1002.prr", "circ_r300.prr", "flat_plane.prr"}) EXPECT_NO_THROW(LoadProfile(kBank + f)) << f;
  for (const char* f : {"circ_r50.prw", "circ_r10.prw", "flat_plane.prw"}) EXPECT_NO_THROW(LoadProfile(kBank + f)) << f;
}

// Item 5: truncated files are refused with file:line: the Simpack point block not closed, fewer MiniProf rows than
// XYPoints, a plain column file cut inside its last number.
TEST(ProfileChecks, TruncatedFilesAreRefused) {
  TempDir tmp;
  const std::string s1002 = ReadAll(kRepoProfiles + "S1002.prw");
  const std::string cut = tmp.file("t.prw", s1002.substr(0, 30010));  // the reproduction
  const std::string msg = LoadError(cut, {});
  EXPECT_TRUE(Contains(msg, "t.prw:")) << msg;
  EXPECT_TRUE(Contains(msg, "no point.end): truncated file?")) << msg;

  const std::string ban = ReadAll(kBank + "rail_left_iter288.ban");  // XYPoints=571
  const std::string cut_ban = tmp.file("cut.ban", ban.substr(0, ban.size() * 3 / 4));
  const std::string ban_msg = LoadError(cut_ban, {});
  EXPECT_TRUE(Contains(ban_msg, "cut.ban:")) << ban_msg;
  EXPECT_TRUE(Contains(ban_msg, "XYPoints=571 but the file has only")) << ban_msg;

  // a column file cut inside the exponent of its last number (no final line break)
  std::string cols = "# y z\n";
  for (int k = 0; k <= 60; ++k) {
    char line[64];
    std::snprintf(line, sizeof line, "%.9e %.9e\n", -30.0 + k, 0.002 * (k - 30) * (k - 30));
    cols += line;
  }
  cols.pop_back();          // no line break
  cols.resize(cols.size() - 1);  // "...e+00" -> "...e+0"
  const std::string col_msg = LoadError(tmp.file("cut.csv", cols), Kind(ProfileKind::Rail));
  EXPECT_TRUE(Contains(col_msg, "cut.csv:62: the last line looks cut short")) << col_msg;
  // complete files without a final line break still load
  cols += "0";
  EXPECT_EQ(LoadError(tmp.file("whole.csv", cols), Kind(ProfileKind::Rail)), "");
}

// Item 9: measured profiles that fold back load with the default options, parametrised by arc length; the
// geometry-relevant part (the flange, the rail top) is intact.
TEST(ProfileChecks, FoldedMeasuredProfilesAreAccepted) {
  for (const char* f : {"Car7216_0001r.whl", "Car7422_0001r.whl"}) {
    const ProfilePoints pts = ReadProfilePoints(kBank + f);
    bool noted = false;
    for (const auto& n : pts.notes) noted = noted || Contains(n, "folds back");
    EXPECT_TRUE(noted) << f;
    const Profile w = LoadProfile(kBank + f);
    const WheelDimensions d = MeasureWheelDimensions(w);
    EXPECT_NEAR(d.sh_m, 0.0285, 2e-3) << f;
  }
  const Profile r = LoadProfile(kBank + "rail_left_iter288.ban");
  EXPECT_GT(r.length(), 0.05);
  // avg_low2.ban folds back too; it is also noisy, and is refused for that reason only, naming the flag
  const std::string msg = LoadError(kBank + "avg_low2.ban", {});
  EXPECT_FALSE(Contains(msg, "folds back")) << msg;
  EXPECT_TRUE(Contains(msg, "--rail-smooth-mm")) << msg;
  ProfileReadOptions smooth;
  smooth.fit.smoothing_rms_m = 0.02e-3;
  EXPECT_NO_THROW(LoadProfile(kBank + "avg_low2.ban", smooth));
}

// Item 10: 50 um of noise on S1002 (and 1 um at 0.1 mm spacing, enough for ten spurious patches) is refused
// naming --wheel-smooth-mm; with the smoothing the profile loads.
TEST(ProfileChecks, NoisyPointsAreRefusedNamingTheSmoothingFlag) {
  TempDir tmp;
  for (double noise_mm : {0.05, 0.001}) {
    const std::string path = tmp.file("noisy.csv", Csv(MakeS1002(), 1, 1, noise_mm));
    const std::string msg = LoadError(path, Kind(ProfileKind::Wheel));
    EXPECT_TRUE(Contains(msg, "noisy.csv: the points are noisy")) << noise_mm << ": " << msg;
    EXPECT_TRUE(Contains(msg, "--wheel-smooth-mm")) << msg;
    ProfileReadOptions smooth = Kind(ProfileKind::Wheel);
    smooth.fit.smoothing_rms_m = noise_mm * 1e-3;
    const Profile p = LoadProfile(path, smooth);
    EXPECT_NEAR(*p.height_at(0.0), 0.0, 3.0 * noise_mm * 1e-3);
  }
  // the clean samples load
  EXPECT_EQ(LoadError(tmp.file("clean.csv", Csv(MakeS1002(), 1, 1)), Kind(ProfileKind::Wheel)), "");
}

// Spacing: points more than 2 mm apart on the running surface and a reversal (two lines swapped on a straight
// tread) are refused with the line.
TEST(ProfileChecks, CoarseSpacingAndReversalsAreRefused) {
  TempDir tmp;
  const std::string coarse = tmp.file("coarse.csv", Csv(MakeRail(RailSection::R60E1, 0.0), 1, 1, 0.0, 3.0));
  const std::string msg = LoadError(coarse, Kind(ProfileKind::Rail));
  EXPECT_TRUE(Contains(msg, "coarse.csv:")) << msg;
  EXPECT_TRUE(Contains(msg, "apart on the running surface")) << msg;
  std::string text;
  for (int k = 0; k <= 40; ++k) {
    const int j = k == 20 ? 21 : k == 21 ? 20 : k;  // lines 21 and 22 swapped
    text += std::to_string(-20.0 + j) + ",0.0\n";
  }
  const std::string swapped = LoadError(tmp.file("swapped.csv", text), Kind(ProfileKind::Rail));
  EXPECT_TRUE(Contains(swapped, "swapped.csv:21: the curve turns back on itself")) << swapped;
}

// Plain column files without a kind name the command-line flags; built-in names refuse file options.
TEST(ProfileChecks, MessagesNameTheCommandLine) {
  TempDir tmp;
  const std::string msg = LoadError(tmp.file("k.csv", Csv(MakeS1002(), 1, 1)), {});
  EXPECT_TRUE(Contains(msg, "--wheel FILE or --rail FILE")) << msg;
  EXPECT_FALSE(Contains(msg, "set ProfileReadOptions::kind")) << msg;
  ProfileReadOptions mirror;
  mirror.mirror_y = true;
  EXPECT_THROW(WheelProfileByNameOrFile("S1002", "option --wheel", {}, mirror), InputError);
  EXPECT_THROW(RailProfileByNameOrFile("60E1", nullptr, "option --rail", {}, mirror), InputError);
  EXPECT_EQ(ParseProfileFormat("MiniProf"), ProfileFormat::MiniProf);
  EXPECT_THROW(ParseProfileFormat("xyz"), InputError);
  // --wheel-format reads a file whose extension says nothing
  const std::string odd = tmp.file("s1002.prof", ReadAll(kRepoProfiles + "S1002.prw"));
  ProfileReadOptions simpack = Kind(ProfileKind::Wheel);
  simpack.format = ProfileFormat::Simpack;
  EXPECT_NO_THROW(LoadProfile(odd, simpack));
  EXPECT_TRUE(Contains(LoadError(odd, Kind(ProfileKind::Wheel)), "--wheel-format"));
}

}  // namespace
}  // namespace conforma
