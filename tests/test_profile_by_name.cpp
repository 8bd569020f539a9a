// Profiles by built-in name or file (profile_by_name.hpp): one rule for the CLI, scenarios, the C API and Python.
// test-links: profiles  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <string>

#include "conforma/error.hpp"
#include "conforma/profile_by_name.hpp"

namespace conforma {
namespace {

TEST(ProfileByName, RailAliasesGiveTheSameSection) {
  RailSection a, b;
  ASSERT_TRUE(FindBuiltInRail("UIC60", &a));
  ASSERT_TRUE(FindBuiltInRail("60E1", &b));
  EXPECT_EQ(a, b);
  ASSERT_TRUE(FindBuiltInRail("UIC50", &a));
  EXPECT_EQ(a, RailSection::R50E4);
  EXPECT_FALSE(FindBuiltInRail("uic60", &a));  // names are exact
  bool built_in = false;
  const Profile alias = RailProfileByNameOrFile("UIC60", &built_in);
  EXPECT_TRUE(built_in);
  const Profile standard = MakeRail(RailSection::R60E1, 0.0);
  const auto a_samples = alias.samples(), s_samples = standard.samples();
  ASSERT_EQ(a_samples.size(), s_samples.size());
  for (size_t k = 0; k < a_samples.size(); ++k) EXPECT_EQ(a_samples[k], s_samples[k]);
}

TEST(ProfileByName, UnknownNameIsAnErrorNamingTheSettingAndTheChoices) {
  try {
    RailProfileByNameOrFile("60E2", nullptr, "option --rail");
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("option --rail"), std::string::npos) << m;
    EXPECT_NE(m.find("'60E2'"), std::string::npos) << m;
    EXPECT_NE(m.find("UIC60"), std::string::npos) << m;
  }
  EXPECT_THROW(WheelProfileByNameOrFile("S1003", "option --wheel"), InputError);
  // a resolver (scenario files: relative to the file) is used for files, not for built-in names
  int resolved = 0;
  const FileResolver count = [&resolved](const std::string& f) { ++resolved; return "/nonexistent/" + f; };
  EXPECT_NO_THROW(WheelProfileByNameOrFile("S1002", "wheel", count));
  EXPECT_EQ(resolved, 0);
  EXPECT_THROW(WheelProfileByNameOrFile("w.prw", "wheel", count), InputError);
  EXPECT_EQ(resolved, 1);
}

}  // namespace
}  // namespace conforma
