// Per rail step summary of a wear run (rail_step_summary.hpp).
#include "conforma/rail_step_summary.hpp"

#include <cmath>

namespace conforma {

const Profile& RailBeforeStep(const WearSimulationResult& r, size_t k, int side) {
  return k == 0 ? r.initial_rail[side] : r.rails[k - 1][side];
}

std::vector<RailStepSummary> SummariseRailSteps(const WearSimulationResult& r) {
  std::vector<RailStepSummary> out;
  const size_t n = std::min(r.rails.size(), r.rail_results.size() / 2);
  for (size_t k = 0; k < n; ++k) {
    RailStepSummary s;
    s.rail_step = static_cast<int>(k);
    const WearStepRecord* last = nullptr;
    for (const WearStepRecord& w : r.steps)
      if (w.rail_step == s.rail_step) {
        ++s.wheel_steps;
        s.wheel_km = w.km;
        s.wheels_valid = s.wheels_valid && w.validity.valid;
        last = &w;
      }
    if (last) {
      s.wheel_removed = MeasureRemovedAlongNormals(r.initial_wheel, last->wheel);
      s.tread_wear_m = last->tread_wear_m;
      s.flange_wear_m = last->flange_wear_m;
    }
    for (int side = 0; side < 2; ++side) {
      const RailStepResult& rr = r.rail_results[2 * k + side];
      const Profile& before = RailBeforeStep(r, k, side);
      RailSideStepSummary& o = s.side[side];
      o.status = rr.status;
      o.valid = rr.status == ProfileUpdateStatus::Updated && rr.validity.valid;
      o.max_abs_curvature_1_m = rr.validity.max_abs_curvature_1_m;
      o.removed = MeasureRemovedAlongNormals(before, r.rails[k][side]);
      o.cumulative = MeasureRemovedAlongNormals(r.initial_rail[side], r.rails[k][side]);
      o.weights = rr.weights;
      o.passages = rr.passages_step;
      for (size_t j = 0; j < rr.virtual_rails.size(); ++j) {
        o.virtual_removed.push_back(MeasureRemovedAlongNormals(before, rr.virtual_rails[j]));
        o.virtual_mean_area_m2 += rr.weights[j] * o.virtual_removed.back().area_m2;
      }
      if (o.virtual_mean_area_m2 != 0.0)
        o.area_residual = std::abs(o.removed.area_m2 - o.virtual_mean_area_m2) / std::abs(o.virtual_mean_area_m2);
    }
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace conforma
