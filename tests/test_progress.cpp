// Progress display of the long commands (src/app/progress.hpp, issue 17): the bar and line formats, the ETA
// arithmetic (mean time per unit so far), the throttling of lines, quiet mode, and updates from parallel threads
// through the library's ProgressCounter (conforma/progress.hpp). No timed test: the clock is a fake one.
// test-links: base  (CMakeLists.txt also compiles src/app/progress.cpp into this test)

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "../src/app/progress.hpp"
#include "conforma/progress.hpp"

namespace {

using conforma::ProgressCounter;
using conforma::cli::ProgressMode;
using conforma::cli::ProgressReporter;

// A clock the test sets by hand (seconds).
struct FakeClock {
  double t = 100.0;
  std::function<double()> fn() {
    return [this] { return t; };
  }
};

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> v;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

TEST(Progress, EtaIsTheMeanTimePerUnitTimesTheUnitsLeft) {
  EXPECT_DOUBLE_EQ(ProgressReporter::EtaSeconds(3, 7, 12.0), 16.0);  // 4 s per unit, 4 left
  EXPECT_DOUBLE_EQ(ProgressReporter::EtaSeconds(7, 7, 30.0), 0.0);
  EXPECT_DOUBLE_EQ(ProgressReporter::EtaSeconds(1.2, 5.0, 6.0), 19.0);  // simulated seconds: 5 wall s per unit
  EXPECT_LT(ProgressReporter::EtaSeconds(0, 7, 5.0), 0.0);   // before the first unit: unknown
  EXPECT_LT(ProgressReporter::EtaSeconds(3, 0, 5.0), 0.0);   // total unknown
  EXPECT_DOUBLE_EQ(ProgressReporter::EtaSeconds(9, 7, 5.0), 0.0);  // past the total: nothing left
}

TEST(Progress, BarAndLineTexts) {
  // 30 * 3/7 = 12.9: 12 filled
  EXPECT_EQ(ProgressReporter::BarText("hertz", 3, 7, "step", 0, "120 km", 12.0),
            "[hertz] [############..................] 3/7 step, 120 km, elapsed 12 s, ETA 16 s");
  EXPECT_EQ(ProgressReporter::LineText("hertz", 3, 7, "step", 0, "120 km", 12.3),
            "hertz: 3/7 step 120 km elapsed 12.3 s ETA 16 s");  // 12.3 / 3 * 4 = 16.4
  // before the first unit: no ETA; no detail: no separator
  EXPECT_EQ(ProgressReporter::BarText("mbench hertz", 0, 21, "case", 0, "", 0.4),
            "[mbench hertz] [..............................] 0/21 case, elapsed 0 s");
  EXPECT_EQ(ProgressReporter::LineText("lut build", 0, 21, "node", 0, "", 0.44), "lut build: 0/21 node elapsed 0.4 s");
  // total unknown: no bar, no total, no ETA
  EXPECT_EQ(ProgressReporter::BarText("x", 5, 0, "case", 0, "", 3.0), "[x] 5 case, elapsed 3 s");
  // simulated seconds with decimals; the bar full at the end
  EXPECT_EQ(ProgressReporter::LineText("dynamics", 1.2, 5, "s", 2, "", 6.0), "dynamics: 1.20/5.00 s elapsed 6.0 s ETA 19 s");
  EXPECT_EQ(ProgressReporter::BarText("d", 5, 5, "s", 1, "", 20.0),
            "[d] [##############################] 5.0/5.0 s, elapsed 20 s, ETA 0 s");
}

TEST(Progress, LinesModePrintsOneFlushedLinePerUpdateWithTheClockGiven) {
  FakeClock clock;
  std::ostringstream out;
  {
    ProgressReporter p("hertz", 3, "step", ProgressMode::Lines, out, clock.fn());
    clock.t += 10.0;
    p.Update(1, "50 km");
    EXPECT_EQ(out.str(), "hertz: 1/3 step 50 km elapsed 10.0 s ETA 20 s\n");  // written at once, not at the end
    clock.t += 14.0;
    p.Update(2, "100 km");
    clock.t += 6.0;
    p.Update(3, "150 km");
    p.Finish();
  }
  EXPECT_EQ(out.str(),
            "hertz: 1/3 step 50 km elapsed 10.0 s ETA 20 s\n"
            "hertz: 2/3 step 100 km elapsed 24.0 s ETA 12 s\n"
            "hertz: 3/3 step 150 km elapsed 30.0 s ETA 0 s\n");
}

TEST(Progress, LinesModeOfManyUnitsPrintsEveryFivePercent) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter p("stress", 1000, "case", ProgressMode::Lines, out, clock.fn());
  for (int k = 1; k <= 1000; ++k) {
    clock.t += 0.01;
    p.Update(k);
  }
  const auto lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 20u);  // 50, 100, ..., 1000
  EXPECT_EQ(lines.front().rfind("stress: 50/1000 case elapsed 0.5 s ETA ", 0), 0u) << lines.front();
  EXPECT_EQ(lines.back().rfind("stress: 1000/1000 case", 0), 0u) << lines.back();
  // a run of at most 100 units: every update
  std::ostringstream few;
  ProgressReporter q("bench", 100, "case", ProgressMode::Lines, few, clock.fn());
  for (int k = 1; k <= 100; ++k) q.Update(k);
  EXPECT_EQ(Lines(few.str()).size(), 100u);
}

TEST(Progress, LineStepForSimulatedTime) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter p("dynamics", 1.0, "s", ProgressMode::Lines, out, clock.fn());
  p.SetDecimals(2);
  p.SetLineStep(0.1);
  for (int k = 1; k <= 100; ++k) p.Update(0.01 * k);  // output samples every 0.01 s
  const auto lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 10u);
  EXPECT_EQ(lines[0].rfind("dynamics: 0.10/1.00 s", 0), 0u) << lines[0];
  EXPECT_EQ(lines[9].rfind("dynamics: 1.00/1.00 s", 0), 0u) << lines[9];
}

TEST(Progress, QuietModeWritesNothing) {
  FakeClock clock;
  std::ostringstream out;
  {
    ProgressReporter p("hertz", 3, "step", ProgressMode::Quiet, out, clock.fn());
    for (int k = 1; k <= 3; ++k) {
      clock.t += 1.0;
      p.Update(k, "detail");
      p.Suspend();
    }
    p.Finish();
  }
  EXPECT_TRUE(out.str().empty()) << out.str();
}

TEST(Progress, BarRedrawsInPlaceAtMostTenTimesASecondAndEndsItsLine) {
  FakeClock clock;
  std::ostringstream out;
  {
    ProgressReporter p("hertz", 4, "step", ProgressMode::Bar, out, clock.fn());
    clock.t += 8.0;
    p.Update(1, "a");  // drawn
    clock.t += 0.05;
    p.Update(2, "b");  // 0.05 s after the last redraw: skipped
    clock.t += 0.10;
    p.Update(3, "c");  // drawn
    clock.t += 0.01;
    p.Update(4, "d");  // the last unit: always drawn
  }                    // the destructor ends the line
  const std::string s = out.str();
  EXPECT_EQ(s,
            "\r[hertz] [#######.......................] 1/4 step, a, elapsed 8 s, ETA 24 s\033[K"
            "\r[hertz] [######################........] 3/4 step, c, elapsed 8 s, ETA 3 s\033[K"
            "\r[hertz] [##############################] 4/4 step, d, elapsed 8 s, ETA 0 s\033[K\n");
}

TEST(Progress, SuspendErasesTheBarAndTheNextUpdateRedrawsIt) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter p("curving", 2, "class", ProgressMode::Bar, out, clock.fn());
  p.Update(0, "straight");
  p.Suspend();
  EXPECT_EQ(out.str(), "\r[curving] [..............................] 0/2 class, straight, elapsed 0 s\033[K\r\033[K");
  out.str("");
  p.Update(1, "R 300");  // at once, although no time has passed
  EXPECT_EQ(out.str().rfind("\r[curving] [###############...............] 1/2 class, R 300", 0), 0u) << out.str();
  p.Finish();
  p.Finish();  // once
  EXPECT_EQ(out.str().back(), '\n');
  EXPECT_EQ(out.str().find('\n'), out.str().size() - 1);
}

TEST(Progress, BarIsCutToTheTerminalWidth) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter p("hertz", 4, "step", ProgressMode::Bar, out, clock.fn());
  p.SetMaxWidth(20);
  p.Update(1, "a long detail that would wrap");
  EXPECT_EQ(out.str(), "\r[hertz] [#######....\033[K");
}

// The total given with the update (a library runner's ProgressFunction): a run of more than 100 units then prints
// every 5 %.
TEST(Progress, FunctionTakesTheTotalFromTheRunner) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter p("lut build", 0.0, "node", ProgressMode::Lines, out, clock.fn());
  const conforma::ProgressFunction f = p.Function();
  for (int k = 1; k <= 400; ++k) f(k, 400, "node " + std::to_string(k - 1));
  const auto lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 20u);
  EXPECT_EQ(lines[0].rfind("lut build: 20/400 node node 19 elapsed 0.0 s ETA 0 s", 0), 0u) << lines[0];
  EXPECT_EQ(lines[19].rfind("lut build: 400/400 node node 399", 0), 0u) << lines[19];
}

TEST(Progress, OlderUpdatesAreIgnored) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter p("lut check", 10, "sample", ProgressMode::Lines, out, clock.fn());
  p.Update(5);
  p.Update(4);  // overtaken
  p.Update(6);
  const auto lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1].rfind("lut check: 6/10 sample", 0), 0u);
}

// The library's counter from several threads at once: every unit counted once, in order, lines intact.
TEST(Progress, CounterFromParallelThreadsCountsEveryUnitOnce) {
  FakeClock clock;
  std::ostringstream out;
  ProgressReporter p("mbench", 80, "case", ProgressMode::Lines, out, clock.fn());
  ProgressCounter counter([&p](double done, double, const std::string& what) { p.Update(done, what); }, 80);
  std::vector<std::thread> threads;
  for (int t = 0; t < 8; ++t)
    threads.emplace_back([&counter, t] {
      for (int k = 0; k < 10; ++k) ProgressCounter::Unit unit(counter, "case " + std::to_string(10 * t + k));
    });
  for (std::thread& t : threads) t.join();
  const auto lines = Lines(out.str());
  ASSERT_EQ(lines.size(), 80u);
  for (int k = 0; k < 80; ++k)
    EXPECT_EQ(lines[k].rfind("mbench: " + std::to_string(k + 1) + "/80 case case ", 0), 0u) << lines[k];
}

TEST(Progress, CounterWithoutAFunctionDoesNothing) {
  ProgressCounter counter(conforma::ProgressFunction(), 3);
  counter.Finished("a");
  { ProgressCounter::Unit unit(counter, "b"); }
  SUCCEED();
}

}  // namespace
