// Published-study figures: scenario key `published`, trends and the findings the compare report checks
// (published_study.hpp).
// test-links: simulation  (CMakeLists.txt links the test with this library only; the layers below come with it)
#include <gtest/gtest.h>

#include "conforma/error.hpp"
#include "conforma/published_study.hpp"
#include "conforma/scenario.hpp"

using namespace conforma;

namespace {

const char* kClasses = "track_classes: [{radius_m: 0, speed_kmh: 60, share: 1}]\n";

RunFigures MakeRun(const std::string& model, double km, double tread_mm, double flange_mm, double dsd_mm, double dqr_mm) {
  RunFigures r;
  r.model = model;
  r.steps = 7;
  r.km = km;
  r.tread_wear_m = tread_mm * 1e-3;
  r.flange_wear_m = flange_mm * 1e-3;
  r.initial.sd_m = 32.5e-3;
  r.initial.sh_m = 28.0e-3;
  r.initial.qr_m = 10.8e-3;
  r.last = r.initial;
  r.last.sd_m += dsd_mm * 1e-3;
  r.last.sh_m += 0.5e-3;
  r.last.qr_m += dqr_mm * 1e-3;
  return r;
}

}  // namespace

TEST(PublishedStudy, TrendHasAFlatBandOfTheGaugeResolution) {
  EXPECT_EQ(TrendOf(32.5e-3, 32.6e-3), Trend::Rises);
  EXPECT_EQ(TrendOf(32.5e-3, 32.4e-3), Trend::Falls);
  EXPECT_EQ(TrendOf(32.5e-3, 32.5e-3 + 0.5 * kFlatTrendTolerance_m), Trend::Flat);
  EXPECT_EQ(TrendOf(32.5e-3, 32.5e-3 - 0.5 * kFlatTrendTolerance_m), Trend::Flat);
  EXPECT_EQ(TrendOf(32.5e-3, NAN), Trend::Unknown);
}

TEST(PublishedStudy, ScenarioReadsTheFiguresInSiUnits) {
  const Scenario s = ParseScenario(std::string(kClasses) +
                                       "published:\n  source: paper 003 §7\n  steps: 7\n  models:\n"
                                       "    conformal: {km: 49905, tread_wear_mm: 2.784, flange_wear_mm: 0.78, sd: rises, "
                                       "sh: rises, qr: falls}\n    hertz: {km: 73287, qr: rises}\n",
                                   "p.yaml");
  ASSERT_EQ(s.published.models.size(), 2u);
  EXPECT_EQ(s.published.source, "paper 003 §7");
  EXPECT_EQ(s.published.steps, 7);
  const PublishedModelFigures* c = s.published.find("conformal");
  ASSERT_NE(c, nullptr);
  EXPECT_DOUBLE_EQ(c->km, 49905.0);
  EXPECT_DOUBLE_EQ(c->tread_wear_m, 2.784e-3);
  EXPECT_DOUBLE_EQ(c->flange_wear_m, 0.78e-3);
  EXPECT_EQ(c->qr, Trend::Falls);
  const PublishedModelFigures* h = s.published.find("hertz");
  ASSERT_NE(h, nullptr);
  EXPECT_LT(h->tread_wear_m, 0.0);  // not published
  EXPECT_EQ(h->sd, Trend::Unknown);
  EXPECT_TRUE(ParseScenario(kClasses, "p.yaml").published.empty());
}

TEST(PublishedStudy, BadFiguresAreInputErrorsNamingTheKey) {
  const auto message = [](const std::string& published) {
    try {
      ParseScenario(std::string(kClasses) + published, "p.yaml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("published: {models: {hertz: {km: 1}}}\n").find("published: source missing"), std::string::npos);
  EXPECT_NE(message("published: {source: s, models: {hertzian: {km: 1}}}\n").find("published.models.hertzian"),
            std::string::npos);
  EXPECT_NE(message("published: {source: s, models: {hertz: {sd: grows}}}\n").find("published.models.hertz.sd"),
            std::string::npos);
  EXPECT_NE(message("published: {source: s, models: {hertz: {km: -3}}}\n").find("published.models.hertz.km: must be > 0"),
            std::string::npos);
  EXPECT_NE(message("published: {source: s, models: {hertz: {speed: 3}}}\n").find("unknown key 'speed'"),
            std::string::npos);
  EXPECT_NE(message("published: {source: s, models: {}}\n").find("published.models"), std::string::npos);
}

TEST(PublishedStudy, FindingsAgreeOnlyWhereTheRunReproducesThem) {
  PublishedStudy study;
  study.source = "test";
  study.steps = 7;
  PublishedModelFigures c{"conformal", 49905.0, 2.784e-3, 0.78e-3, Trend::Rises, Trend::Rises, Trend::Falls};
  PublishedModelFigures h{"hertz", 73287.0, 2.782e-3, 0.5e-3, Trend::Rises, Trend::Rises, Trend::Rises};
  study.models = {c, h};
  // conformal: fewer km, tread 3x flange, Sd rises, qR rises (published: falls); hertz: flange-dominated, Sd falls
  const std::vector<PublishedCheck> checks =
      ComparePublished(study, {MakeRun("conformal", 30000, 0.9, 0.3, +0.1, +0.1), MakeRun("hertz", 40000, 0.4, 0.4, -0.1, +0.1)});
  ASSERT_EQ(checks.size(), 9u);  // 2 x (Sd, Sh, qR, tread/flange) + the km order
  const auto find = [&](const std::string& what) {
    for (const PublishedCheck& k : checks)
      if (k.what == what) return k;
    ADD_FAILURE() << "no check " << what;
    return PublishedCheck{};
  };
  EXPECT_TRUE(find("conformal Sd").agrees);
  EXPECT_TRUE(find("conformal Sh").agrees);
  EXPECT_FALSE(find("conformal qR").agrees);
  EXPECT_TRUE(find("conformal tread / flange wear > 2").agrees);
  EXPECT_FALSE(find("hertz Sd").agrees);
  EXPECT_TRUE(find("hertz qR").agrees);
  EXPECT_FALSE(find("hertz tread / flange wear > 2").agrees);
  const PublishedCheck km = find("km conformal / hertz < 1");
  EXPECT_TRUE(km.agrees);
  EXPECT_EQ(km.ours, "0.750");
  EXPECT_EQ(km.published, "0.681");
  // the same runs with the km order reversed: the finding is no longer reproduced
  const std::vector<PublishedCheck> reversed =
      ComparePublished(study, {MakeRun("conformal", 50000, 0.9, 0.3, +0.1, +0.1), MakeRun("hertz", 40000, 0.4, 0.4, -0.1, +0.1)});
  EXPECT_FALSE(reversed.back().agrees);
  EXPECT_EQ(reversed.back().what, "km conformal / hertz < 1");
  // a model the study did not publish is not compared
  EXPECT_TRUE(ComparePublished(study, {MakeRun("kp", 1, 1, 1, 0, 0)}).empty());
}
