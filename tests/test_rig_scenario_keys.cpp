// test-links: rig
// The roller-rig scenario reader (LoadRollerRigScenario, roller_rig_plan.hpp) rejects keys it does not read, with the
// file and the key in the message (a misspelt key would otherwise leave its value at the default without a word).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "conforma/error.hpp"
#include "conforma/roller_rig_plan.hpp"

namespace conforma {
namespace {

const std::string kScenario = std::string(CONFORMA_SOURCE_DIR) + "/scenarios/roller_rig_1to5.yaml";

std::string ReadFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The shipped scenario with `from` replaced by `to` (once), written to a temporary file.
std::string Edited(const std::string& from, const std::string& to, const std::string& name) {
  std::string text = ReadFile(kScenario);
  const size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const std::string path = (std::filesystem::temp_directory_path() / name).string();
  std::ofstream(path) << text;
  return path;
}

void ExpectRejected(const std::string& path, const std::string& where, const std::string& key) {
  try {
    LoadRollerRigScenario(path);
    ADD_FAILURE() << "accepted " << key;
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path), std::string::npos) << m;
    EXPECT_NE(m.find(where + ": unknown key '" + key + "'"), std::string::npos) << m;
  }
  std::filesystem::remove(path);
}

TEST(RigScenarioKeys, TheShippedScenarioLoads) {
  const RollerRigScenario sc = LoadRollerRigScenario(kScenario);
  EXPECT_EQ(sc.plan.size(), 5u);
}

TEST(RigScenarioKeys, UnknownKeysAreRejectedWithFileAndKey) {
  ExpectRejected(Edited("gravity_m_s2: 9.81", "gravity_m_s2: 9.81\ngravity: 9.8", "rig_keys_top.yaml"), "top level",
                 "gravity");
  ExpectRejected(Edited("  wheel_radius_m: 0.0944", "  wheel_radius: 0.0944", "rig_keys_rig.yaml"), "rig",
                 "wheel_radius");
  ExpectRejected(Edited("  friction_coefficient: 0.35", "  friction: 0.35", "rig_keys_contact.yaml"), "contact",
                 "friction");
  ExpectRejected(Edited("  step_s: 0.2", "  step: 0.2", "rig_keys_wear.yaml"), "wear", "step");
  ExpectRejected(Edited("wheel_load_kg: 53", "wheel_load: 53", "rig_keys_plan.yaml"), "plan[0]", "wheel_load");
}

}  // namespace
}  // namespace conforma
