// Published wear-study figures against a run (published_study.hpp; docs/physics-reference.md §8.11).
#include "conforma/published_study.hpp"

#include <cmath>
#include <cstdio>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(Trend trend) {
  switch (trend) {
    case Trend::Rises: return "rises";
    case Trend::Falls: return "falls";
    case Trend::Flat: return "flat";
    case Trend::Unknown: break;
  }
  return "-";
}

Trend ParseTrend(const std::string& text) {
  if (text == "rises") return Trend::Rises;
  if (text == "falls") return Trend::Falls;
  if (text == "flat") return Trend::Flat;
  throw InputError("trend '" + text + "': expected rises, falls or flat");
}

Trend TrendOf(double initial_m, double final_m, double flat_tolerance_m) {
  if (!std::isfinite(initial_m) || !std::isfinite(final_m)) return Trend::Unknown;
  const double d = final_m - initial_m;
  if (std::abs(d) < flat_tolerance_m) return Trend::Flat;
  return d > 0.0 ? Trend::Rises : Trend::Falls;
}

const PublishedModelFigures* PublishedStudy::find(const std::string& model) const {
  for (const PublishedModelFigures& m : models)
    if (m.model == model) return &m;
  return nullptr;
}

namespace {

std::string Format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string Signed(double initial_m, double final_m) {  // "rises (+0.123 mm)"
  char buf[64];
  std::snprintf(buf, sizeof buf, "%s (%+.3f mm)", to_string(TrendOf(initial_m, final_m)), (final_m - initial_m) * 1e3);
  return buf;
}

}  // namespace

std::vector<PublishedCheck> ComparePublished(const PublishedStudy& study, const std::vector<RunFigures>& runs) {
  std::vector<PublishedCheck> checks;
  for (const RunFigures& run : runs) {
    const PublishedModelFigures* pub = study.find(run.model);
    if (pub == nullptr) continue;
    const struct {
      const char* name;
      double initial, last;
      Trend published;
    } dims[] = {{"Sd", run.initial.sd_m, run.last.sd_m, pub->sd},
                {"Sh", run.initial.sh_m, run.last.sh_m, pub->sh},
                {"qR", run.initial.qr_m, run.last.qr_m, pub->qr}};
    for (const auto& d : dims) {
      if (d.published == Trend::Unknown) continue;
      PublishedCheck c;
      c.what = run.model + " " + d.name;
      c.ours = Signed(d.initial, d.last);
      c.published = to_string(d.published);
      c.compared = true;
      c.agrees = TrendOf(d.initial, d.last) == d.published;
      checks.push_back(c);
    }
    if (pub->tread_wear_m > 0.0 && pub->flange_wear_m > 0.0) {
      // tread wear more than twice the flange wear, as the published run has it (or not)
      const double ours = run.flange_wear_m > 0.0 ? run.tread_wear_m / run.flange_wear_m : INFINITY;
      const double published = pub->tread_wear_m / pub->flange_wear_m;
      PublishedCheck c;
      c.what = run.model + " tread / flange wear > 2";
      c.ours = Format("%.2f", ours);
      c.published = Format("%.2f", published);
      c.compared = true;
      c.agrees = (ours > 2.0) == (published > 2.0);
      checks.push_back(c);
    }
  }
  for (size_t a = 0; a < runs.size(); ++a)
    for (size_t b = 0; b < runs.size(); ++b) {
      if (a == b) continue;
      const PublishedModelFigures* pa = study.find(runs[a].model);
      const PublishedModelFigures* pb = study.find(runs[b].model);
      if (pa == nullptr || pb == nullptr || !(pa->km > 0.0) || !(pb->km > 0.0) || !(pa->km < pb->km)) continue;
      if (!(runs[a].km > 0.0) || !(runs[b].km > 0.0)) continue;
      // the published pair in the order "fewer km first": does our run put them in the same order?
      PublishedCheck c;
      c.what = "km " + runs[a].model + " / " + runs[b].model + " < 1";
      c.ours = Format("%.3f", runs[a].km / runs[b].km);
      c.published = Format("%.3f", pa->km / pb->km);
      c.compared = true;
      c.agrees = runs[a].km < runs[b].km;
      checks.push_back(c);
    }
  return checks;
}

}  // namespace conforma
