// Profile file readers and writers: every shared test-bank file loads or is refused with a clear message,
// orientation conventions (MiniProf vs Simpack copies of the same rail), round trips, malformed-input errors.
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
