// test-links: rig
// Replay of a measured roller-rig time series (roller_rig_replay.hpp, docs/physics-reference.md §18.5): the reader's
// rules (each row's step is the time to the next row unless dt_s is given, the last row repeating the previous step;
// time must increase; line numbers in the errors) and the replay itself, which must be the samples processed one
// after the other on one rig state (the profiles wear as the run goes on), bit for bit.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "conforma/error.hpp"
#include "conforma/roller_rig_replay.hpp"

namespace conforma {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

fs::path RigDir() { return fs::temp_directory_path() / ("conforma_rig_replay_" + std::to_string(::getpid())); }

std::string RigCsv(const std::string& name, const std::string& text) {
  const fs::path dir = RigDir();
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream(file) << text;
  return file.string();
}

// 500 rpm on roller 1, roller 2 slower by the creepage xi (as test_rig_sample's samples), 50 kg per wheel
std::string Row(double t, double y, double xi) {
  const double w1 = 500.0 * 2.0 * kPi / 60.0, w2 = w1 * (1.0 - xi) / (1.0 + xi);
  char line[200];
  std::snprintf(line, sizeof line, "%.17g,%.17g,0,%.17g,%.17g,490.5,490.5\n", t, y, w1, w2);
  return line;
}

const char* kHeader = "t_s,y_m,yaw_rad,omega1_rad_s,omega2_rad_s,load_left_N,load_right_N\n";

TEST(RigReplay, StepsAreTheTimeToTheNextRow) {
  const auto samples = ReadRollerRigSamples(
      RigCsv("steps.csv", std::string("# a measured run\n") + kHeader + Row(0.0, 0.0, 0.05) + Row(0.02, 0.1e-3, 0.05) +
                              Row(0.05, 0.2e-3, 0.1) + Row(0.09, 0.2e-3, 0.1)));
  ASSERT_EQ(samples.size(), 4u);
  EXPECT_DOUBLE_EQ(samples[0].duration_s, 0.02);
  EXPECT_DOUBLE_EQ(samples[1].duration_s, 0.03);
  EXPECT_DOUBLE_EQ(samples[2].duration_s, 0.04);
  EXPECT_DOUBLE_EQ(samples[3].duration_s, 0.04);  // the last row repeats the previous step
  EXPECT_TRUE(std::isnan(samples[0].wheelset_speed_rad_s));  // no omega3 column: the torque balance is solved
  const auto one = ReadRollerRigSamples(RigCsv("one.csv", std::string(kHeader) + Row(5.0, 0.0, 0.05)));
  EXPECT_DOUBLE_EQ(one.at(0).duration_s, 0.02);
  // dt_s given: each row's own step; omega3_rad_s given: the measured wheelset speed (columns in any order)
  std::string with = std::string("dt_s,omega3_rad_s,") + kHeader;
  with += "0.01,100.5," + Row(0.0, 0.0, 0.05) + "0.005,100.25," + Row(1.0, 0.0, 0.05);
  const auto given = ReadRollerRigSamples(RigCsv("dt.csv", with));
  ASSERT_EQ(given.size(), 2u);
  EXPECT_DOUBLE_EQ(given[0].duration_s, 0.01);
  EXPECT_DOUBLE_EQ(given[1].duration_s, 0.005);
  EXPECT_DOUBLE_EQ(given[1].wheelset_speed_rad_s, 100.25);
  EXPECT_DOUBLE_EQ(given[1].time_s, 1.0);
  fs::remove_all(RigDir());
}

TEST(RigReplay, ReaderNamesTheLine) {
  try {
    ReadRollerRigSamples(RigCsv("back.csv", std::string(kHeader) + Row(0.0, 0.0, 0.05) + Row(0.02, 0.0, 0.05) +
                                                Row(0.02, 0.0, 0.05)));
    FAIL() << "a repeated time was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("back.csv:4: t_s must increase"), std::string::npos) << e.what();
  }
  EXPECT_THROW(ReadRollerRigSamples(RigCsv("empty.csv", kHeader)), InputError);
  EXPECT_THROW(ReadRollerRigSamples(RigCsv("missing.csv", "t_s,y_m\n0,0\n")), InputError);
  fs::remove_all(RigDir());
}

// The replay is the samples processed in order on one state: the same results and the same worn profiles as
// ProcessRigSample called row by row; the wear of the later rows is taken on the profiles worn by the earlier ones.
TEST(RigReplay, ReplayIsTheSamplesInOrderOnOneState) {
  const auto samples = ReadRollerRigSamples(
      RigCsv("run.csv", std::string(kHeader) + Row(0.0, 0.0, 0.05) + Row(0.02, 0.1e-3, 0.05) + Row(0.05, 0.2e-3, 0.1) +
                            Row(0.09, 0.2e-3, 0.1)));
  const RollerRigSampleOptions o = RollerRigSampleOptions::Defaults();
  RollerRigState replayed = MakeRollerRigState(o), by_hand = replayed;
  std::vector<RollerRigReplayRow> rows;
  const long failed = ReplayRollerRigSamples(o, &replayed, samples, [&](const RollerRigReplayRow& r) { rows.push_back(r); });
  EXPECT_EQ(failed, 0);
  ASSERT_EQ(rows.size(), samples.size());
  double worn = 0.0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const RollerRigSampleResult r = ProcessRigSample(o, &by_hand, samples[i]);
    ASSERT_EQ(rows[i].result.status, RollerRigSampleStatus::Ok) << rows[i].result.message;
    EXPECT_EQ(rows[i].sample.time_s, samples[i].time_s);
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(rows[i].result.kinematics.contact[k].fx_N, r.kinematics.contact[k].fx_N) << i;
      EXPECT_EQ(rows[i].result.wheel_wear_area_m2[k], r.wheel_wear_area_m2[k]) << i;
      EXPECT_GT(r.wheel_wear_area_m2[k], 0.0);  // creepage 5-10 %: every row wears
      worn += r.wheel_wear_area_m2[k];
    }
  }
  EXPECT_EQ(replayed.step, 4);
  EXPECT_DOUBLE_EQ(replayed.time_s, 0.02 + 0.03 + 0.04 + 0.04);
  for (int k = 0; k < 2; ++k) {
    const Profile& a = replayed.wheel[k];
    const Profile& b = by_hand.wheel[k];
    for (double y = a.y_min(); y <= a.y_max(); y += 0.5e-3) EXPECT_EQ(a.height_at(y), b.height_at(y)) << k << " " << y;
  }
  EXPECT_GT(worn, 0.0);
  fs::remove_all(RigDir());
}

}  // namespace
}  // namespace conforma
