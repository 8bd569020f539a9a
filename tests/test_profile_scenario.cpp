// test-links: simulation
// Scenario files read profile files with the same checks and options as the command line (issue 13 items 4 and 10):
// profiles.wheel_mirror / wheel_z_down / wheel_units / wheel_smoothing_mm / wheel_format and the rail_ ones.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "conforma/error.hpp"
#include "conforma/scenario.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma {
namespace {

namespace fs = std::filesystem;

std::string ParseError(const std::string& yaml, const std::string& dir) {
  try {
    ParseScenario(yaml, "test.yaml", dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(ProfileScenario, ProfileFileOptionsAndChecks) {
  const fs::path dir = fs::temp_directory_path() / ("conforma_profile_scenario_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  {
    std::ofstream out(dir / "mirrored.csv");  // S1002 mirrored in y, in metres
    out.precision(12);
    for (const auto& q : MakeS1002().sample(0.1e-3)) out << -q.x() << "," << q.y() << "\n";
  }
  const std::string base = "track_classes: [{radius_m: 0, speed_kmh: 60, share: 1}]\n"
                           "profiles:\n  wheel: mirrored.csv\n  rail: 60E1\n";
  // in metres and mirrored: both options needed
  std::string msg = ParseError(base + "  wheel_units: m\n", dir.string());
  EXPECT_NE(msg.find("profiles.wheel"), std::string::npos) << msg;
  EXPECT_NE(msg.find("--wheel-mirror"), std::string::npos) << msg;
  EXPECT_NE(msg.find("profiles.wheel_mirror"), std::string::npos) << msg;
  EXPECT_EQ(ParseError(base + "  wheel_units: m\n  wheel_mirror: true\n", dir.string()), "");
  const Scenario s = ParseScenario(base + "  wheel_units: m\n  wheel_mirror: true\n", "test.yaml", dir.string());
  EXPECT_NEAR(*s.wheel.height_at(-0.055), 0.028, 1e-5);
  // bad values are named
  EXPECT_NE(ParseError(base + "  wheel_units: inch\n", dir.string()).find("profiles.wheel_units"), std::string::npos);
  EXPECT_NE(ParseError(base + "  wheel_smoothing_mm: 50\n", dir.string()).find("profiles.wheel_smoothing_mm"),
            std::string::npos);
  EXPECT_NE(ParseError(base + "  rail_format: foo\n", dir.string()).find("profiles.rail_format"), std::string::npos);
  // file options with a built-in name are refused
  EXPECT_NE(ParseError(base + "  wheel_units: m\n  wheel_mirror: true\n  rail_mirror: true\n", dir.string())
                .find("built-in"),
            std::string::npos);
  std::error_code ignored;
  fs::remove_all(dir, ignored);
}

}  // namespace
}  // namespace conforma
