// Profile file readers and writers: every shared test-bank file loads or is refused with a clear message,
// orientation conventions (MiniProf vs Simpack copies of the same rail), round trips, malformed-input errors.
// test-links: profiles  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <unistd.h>

#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_dimensions.hpp"

using namespace conforma;
namespace fs = std::filesystem;

namespace {

const std::string kData = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/";

class TempDir {
 public:
  TempDir() : path_(fs::temp_directory_path() / ("conforma_io_" + std::to_string(::getpid()))) { fs::create_directories(path_); }
  ~TempDir() { fs::remove_all(path_); }
  std::string file(const std::string& name, const std::string& text) const {
    const std::string p = (path_ / name).string();
    std::ofstream(p) << text;
    return p;
  }
  std::string path(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

// The InputError message of loading `path`, or "" if it loads.
std::string load_error(const std::string& path, const ProfileReadOptions& o = {}) {
  try {
    LoadProfile(path, o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

double max_distance(const Profile& prof, const std::vector<Eigen::Vector2d>& pts) {
  double worst = 0;
  for (const auto& q : pts) worst = std::max(worst, (prof.position(prof.closest_s(q)) - q).norm());
  return worst;
}

}  // namespace

TEST(ProfileIo, EveryTestBankFileLoadsOrIsRefusedClearly) {
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(kData + "testbank/profiles")) {
    std::string ext = e.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext == ".prw" || ext == ".prr" || ext == ".ban" || ext == ".whl") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 30u);
  int loaded = 0;
  for (const auto& f : files) {
    try {
      const auto pts = ReadProfilePoints(f.string());
      const Profile p = LoadProfile(f.string());
      ++loaded;
      std::printf("LOADED  %-28s %-5s %4zu pts  y [%8.3f, %8.3f] mm  length %7.2f mm", f.filename().c_str(),
                  to_string(p.kind()), pts.points_m.size(), p.y_min() * 1e3, p.y_max() * 1e3, p.length() * 1e3);
      for (const auto& n : pts.notes) std::printf(" | %s", n.c_str());
      std::printf("\n");
      EXPECT_GT(p.length(), 0.005) << f;  // CONTACT's unit check: 5..500 mm
      EXPECT_LT(p.length(), 0.5) << f;
    } catch (const InputError& e) {
      std::printf("REFUSED %-28s %s\n", f.filename().c_str(), e.what());
      EXPECT_NE(std::string(e.what()).find(f.filename().string()), std::string::npos) << "message must name the file";
    }
  }
  std::printf("%d of %zu files loaded\n", loaded, files.size());
}

TEST(ProfileIo, MiniProfAndSimpackCopiesOfTheBenchmarkRailAgree) {
  // MBench_UIC60_v3.ban (MiniProf: y mirrored, z down, stray quotes) and .prr (Simpack) hold the same rail.
  const Profile prr = LoadProfile(kData + "examples/MBench_UIC60_v3.prr");
  const auto ban = ReadProfilePoints(kData + "examples/MBench_UIC60_v3.ban");
  ASSERT_EQ(ban.kind, ProfileKind::Rail);
  EXPECT_EQ(ban.points_m.size(), 495u);
  const double d = max_distance(prr, ban.points_m);
  std::printf("MBench_UIC60_v3.ban vs .prr: max distance %.2e mm\n", d * 1e3);
  EXPECT_LT(d, 1e-6);
  // our convention: crown up (highest point at the origin), gauge side (steeper 1:40-canted side) at -y
  EXPECT_NEAR(*prr.height_at(0.0), 0.0, 1e-6);
  EXPECT_LT(prr.y_min(), -0.043);
  EXPECT_GT(prr.y_max(), 0.030);
  EXPECT_LT(prr.y_max(), 0.031);
}

TEST(ProfileIo, SimpackAndMiniProfWheelOrientation) {
  // Simpack S1002: flange at negative y, back at -70 mm, tip z = +28 mm at y = -55 mm.
  const Profile s = LoadProfile(kData + "examples/MBench_S1002_v3.prw");
  EXPECT_NEAR(*s.height_at(-0.055), 0.028, 1e-6);
  // MiniProf wheel: flange back at y_file = 0 -> -70 mm, flange at negative y, z(taping line) = 0, tip up.
  const Profile m = LoadProfile(kData + "testbank/profiles/left-wheel-v1-pre-dry.whl");
  EXPECT_NEAR(*m.height_at(0.0), 0.0, 1e-7);  // shift used the chord, the spline differs slightly
  EXPECT_NEAR(m.y_min(), -0.070, 0.0005);
  const auto tip = m.height_at(-0.051);  // flange tip of a worn S1002-like wheel near y = -51 mm
  ASSERT_TRUE(tip.has_value());
  EXPECT_GT(*tip, 0.027);
}

TEST(ProfileIo, RoundTripSimpackAndCsv) {
  TempDir tmp;
  for (const Profile& p : {MakeS1002(), MakeRail(RailSection::R60E1, rail_inclination_1in40())}) {
    const bool wheel = p.kind() == ProfileKind::Wheel;
    const std::string f = tmp.path(wheel ? "w.prw" : "r.prr");
    SaveProfileSimpack(p, f);
    const Profile back = LoadProfile(f);
    EXPECT_EQ(back.kind(), p.kind());
    EXPECT_NEAR(back.length(), p.length(), 1e-7);
    const double d = max_distance(back, p.sample(0.05e-3));
    std::printf("Simpack round trip %s: max distance %.2e mm\n", to_string(p.kind()), d * 1e3);
    EXPECT_LT(d, 1e-7);
    const std::string c = tmp.path(wheel ? "w.csv" : "r.csv");
    SaveProfileCsv(p, c);
    ProfileReadOptions o;
    o.kind = p.kind();
    const Profile back_csv = LoadProfile(c, o);
    EXPECT_LT(max_distance(back_csv, p.sample(0.05e-3)), 1e-7);
  }
  // saving a wheel as .prr is refused
  EXPECT_THROW(SaveProfileSimpack(MakeS1002(), tmp.path("x.prr")), InputError);
}

TEST(ProfileIo, PlainColumnFilesWithUnitsAndMirroring) {
  TempDir tmp;
  // S1002 in metres, y mirrored and z mirrored, semicolon separated, with a header line
  std::string text = "S;F\n";
  for (double S = -69.0; S <= 60.0; S += 0.5) {
    char buf[80];
    std::snprintf(buf, sizeof buf, "%.9f; %.9f\n", -S * 1e-3, -S1002Height_mm(S) * 1e-3);
    text += buf;
  }
  ProfileReadOptions o;
  o.kind = ProfileKind::Wheel;
  o.length_unit_m = 1.0;
  o.mirror_y = o.mirror_z = true;
  const Profile p = LoadProfile(tmp.file("s1002_m.txt", text), o);
  EXPECT_NEAR(*p.height_at(-0.055), 0.028, 2e-6);
  EXPECT_NEAR(*p.height_at(0.0), 0.0, 1e-6);
  // the shared analytic table (mm, '#' comment header) equals the generator
  ProfileReadOptions mm;
  mm.kind = ProfileKind::Wheel;
  const Profile t = LoadProfile(std::string(CONFORMA_SHARED_DATA) + "/profiles/analytic/S1002_analytic_DLR.txt", mm);
  std::vector<Eigen::Vector2d> tab;  // away from the vertical tangent at -70 mm the 0.1 mm table is fine
  for (const auto& q : t.sample(0.1e-3))
    if (q.x() > -0.0695) tab.push_back(q);
  EXPECT_LT(max_distance(MakeS1002(), tab), 2e-7);
}

// Each malformed file must be refused with an InputError whose message names the file and the line.
TEST(ProfileIo, MalformedFilesNameFileAndLine) {
  TempDir tmp;
  ProfileReadOptions rail;
  rail.kind = ProfileKind::Rail;
  struct Case { std::string name, text, expect; };
  const std::string good = "  point.begin\n-10 1\n-5 0.2\n0 0\n5 0.2\n10 1\n point.end\n";
  const std::vector<Case> cases = {
      {"empty.prr", "header.begin\n type = 0\nheader.end\nspline.begin\n point.begin\n point.end\nspline.end\n",
       "empty.prr: no profile points"},
      {"abc.prr", "header.begin\n type = 0\nheader.end\nspline.begin\n point.begin\n-10 1\n-5 abc\n0 0\n",
       "abc.prr:7: non-numeric value 'abc'"},
      {"trunc.prr", "header.begin\n type = 0\nheader.end\nspline.begin\n point.begin\n-10 1\n-5 0.2\n0 0\n5 0.2\n10 1\n",
       "trunc.prr:10: the file ends inside the point.begin block of line 5 (no point.end): truncated file?"},
      {"key.prr", "header.begin\n type = 0\nheader.end\nspline.begin\n shift.y = 1.0x\n" + good + "spline.end\n",
       "key.prr:5: non-numeric value '1.0x'"},
      {"rot.prr", "spline.begin\n rotate = 0.1\n" + good + "spline.end\n", "rot.prr:2: rotate != 0 is not supported"},
      {"type.prr", "header.begin\n type = 1\nheader.end\n" + good, "type.prr:2: header type says wheel"},
      {"fold.prr", "point.begin\n-2 0\n-1 0\n0 0\n-0.5 0.001\n1 0.002\n2 0.003\npoint.end\n",
       "fold.prr:4: the curve turns back on itself"},
      {"cols.csv", "y_mm,z_mm\n-10,1\n-5,0.2\n0,x\n5,0.2\n", "cols.csv:4: non-numeric value 'x'"},
      {"one.csv", "-10,1\n-5\n", "one.csv:2: expected two columns"},
      {"nopts.csv", "# nothing here\ny,z\n", "nopts.csv: no profile points"},
      {"short.ban", "ColumnDef=X,Y\n\n1 2\n2 3\n3 zz\n", "short.ban:5: non-numeric value 'zz'"},
      {"cdef.ban", "ColumnDef=A,C\n\n1 2\n", "cdef.ban:1: ColumnDef 'A,C' has no X and Y columns"},
      {"few.whl", "ColumnDef=X,Y\n\n1 2\n2 3\n", "few.whl: no profile points found"},
      {"nan.prr", "point.begin\n-10 1\n-5 nan\n0 0\n5 1\npoint.end\n", "nan.prr:3: non-numeric value 'nan'"},
      {"foo.xyz", "1 2\n", "foo.xyz: unknown profile file type"},
  };
  for (const auto& c : cases) {
    const std::string path = tmp.file(c.name, c.text);
    const std::string msg = load_error(path, c.name.find(".csv") != std::string::npos ? rail : ProfileReadOptions{});
    EXPECT_NE(msg.find(c.expect), std::string::npos) << "file " << c.name << " gave: '" << msg << "'";
  }
  // a self-intersection (a curve allowed to fold) names the line of the crossing segment
  ProfileReadOptions fold_ok;
  fold_ok.fit.function_of_y = false;
  const std::string msg =
      load_error(tmp.file("cross.prr", "point.begin\n-10 0\n0 0\n0 -1\n-4 -1\n-4 1\n-3 1\n10 2\npoint.end\n"), fold_ok);
  EXPECT_NE(msg.find("cross.prr:5: profile self-intersects: the segment starting at line 2"), std::string::npos) << msg;
  // a column file without a kind is refused, a missing file too
  const std::string no_kind = load_error(tmp.path("cols.csv"));
  EXPECT_NE(no_kind.find("give the kind (command line: --wheel FILE or --rail FILE, `profile info --kind wheel|rail`"),
            std::string::npos) << no_kind;
  EXPECT_NE(load_error(tmp.path("missing.prr")).find("cannot open"), std::string::npos);
}
