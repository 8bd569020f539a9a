#pragma once
// Figures that a published wear study reports for the case a scenario stands for (scenario key `published`), and
// their comparison with a run of the wear loop: `conforma compare` puts them side by side in its report
// (docs/physics-reference.md §8.11). Nothing here is used by the solvers.
//
// Scenario file:
//   published:
//     source: "paper 003 §7, Figs. 16-24"      (required: where the figures are printed)
//     steps: 7                                  (wheel steps of the published runs; compared at that step)
//     models:                                   (contact model name as in --models -> its published figures)
//       conformal: { km: 49905, tread_wear_mm: 2.784, flange_wear_mm: 0.78, sd: rises, sh: rises, qr: falls }
//       hertz:     { km: 73287, tread_wear_mm: 2.782, flange_wear_mm: 0.5,  sd: rises, sh: rises, qr: rises }
// Every figure is optional (a missing one is not compared); trends are rises | falls | flat.
#include <string>
#include <vector>

#include "conforma/wheel_dimensions.hpp"

namespace conforma {

// Direction of a wheel dimension (Sd, Sh, qR) from the new to the last profile of a run.
enum class Trend {
  Unknown,  // not published / not finite
  Rises,    // grows by at least the flat tolerance
  Falls,    // shrinks by at least the flat tolerance
  Flat      // changes by less than the flat tolerance
};
const char* to_string(Trend trend);  // "-", "rises", "falls", "flat"
Trend ParseTrend(const std::string& text);  // rises | falls | flat; throws InputError otherwise

// A change smaller than this is "flat": the resolution of a wheel-profile gauge such as MiniProf/Calipri is
// ~0.01 mm, and the wear loop's own step-to-step noise in Sd/qR on tangent-dominated lines is of that order.
constexpr double kFlatTrendTolerance_m = 0.02e-3;
Trend TrendOf(double initial_m, double final_m, double flat_tolerance_m = kFlatTrendTolerance_m);

struct PublishedModelFigures {
  std::string model;            // contact model name as `conforma compare --models` spells it
  double km = -1.0;             // distance after `steps` wheel steps; < 0: not published
  double tread_wear_m = -1.0;   // tread wear depth after `steps`; < 0: not published
  double flange_wear_m = -1.0;  // flange wear depth after `steps`; < 0: not published
  Trend sd = Trend::Unknown, sh = Trend::Unknown, qr = Trend::Unknown;
};

struct PublishedStudy {
  std::string source;  // where the figures are printed (paper, section, figures)
  int steps = 0;       // wheel steps of the published runs (0: compare the last step of each run)
  std::vector<PublishedModelFigures> models;
  bool empty() const { return models.empty(); }
  const PublishedModelFigures* find(const std::string& model) const;  // nullptr if not published
};

// One model's run, reduced to what the comparison needs.
struct RunFigures {
  std::string model;
  int steps = 0;  // wheel steps completed
  double km = 0.0, tread_wear_m = 0.0, flange_wear_m = 0.0;
  WheelDimensions initial, last;
};

// One compared quantity: ours against the published one and whether they agree. For distances and depths
// "agree" is not asked (the figures are shown side by side); for trends and the two ratios below it is.
struct PublishedCheck {
  std::string what;         // e.g. "conformal Sd", "km conformal / hertz", "hertz tread / flange"
  std::string ours, published;
  bool compared = false;    // a yes/no question with both answers known
  bool agrees = false;
};

// The checks, in report order: per model Sd, Sh, qR trends and tread wear > 2 x flange wear (the published ratio
// decides which side of 2 is expected: "> 2" when the published tread / flange is above 2); then, for every pair of
// published models both run, whether the first needs fewer km than the second, as published.
std::vector<PublishedCheck> ComparePublished(const PublishedStudy& study, const std::vector<RunFigures>& runs);

}  // namespace conforma
