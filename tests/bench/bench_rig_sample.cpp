// Roller-rig real time (issue 18, item 5): one 20 ms sample through the C API (conforma_rig_process_sample: both
// contacts, contact model + FASTSIM 20 x 20, Archard wear of wheel and roller, profile update, the sliding-mean filter
// every 10 samples), on a rig state that keeps wearing from sample to sample. Targets: <= 1 ms median with the Hertz
// model, <= 5 ms with the conformal one. Arguments: model (0 hertz, 1 conformal), wheelset speed (0: moment balance,
// 1: eq. 2, 2: measured), profiles in contact updated every `update` samples (1: every sample, as the paper; 10: at
// the filter steps). Run: conforma_bench --benchmark_filter=RigSample --benchmark_repetitions=10
//                             --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <cmath>

#include "conforma_c.h"

namespace {

void BM_RigSample(benchmark::State& st) {
  const int model = static_cast<int>(st.range(0)), speed = static_cast<int>(st.range(1));
  const int update = static_cast<int>(st.range(2));
  conforma_rig_params p;
  conforma_default_rig_params(&p);
  p.model = model == 0 ? "hertz" : "conformal";
  p.eq2_wheelset_speed = speed == 1 ? 1 : 0;
  p.profile_update_every_steps = update;
  conforma_rig* rig = nullptr;
  char err[CONFORMA_ERROR_TEXT];
  if (conforma_rig_create(&p, &rig, err, sizeof err) != CONFORMA_OK) {
    st.SkipWithError(err);
    return;
  }
  const double w1 = 500.0 * 2.0 * 3.14159265358979323846 / 60.0, xi = 0.05;
  conforma_rig_sample s{};
  s.duration_s = 0.02;
  s.roller_speed_rad_s[0] = w1;
  s.roller_speed_rad_s[1] = w1 * (1.0 - xi) / (1.0 + xi);
  s.wheel_load_N[0] = s.wheel_load_N[1] = 50.0 * 9.81;
  // measured omega_3: the eq. 2 value at the nominal radii (opposite creepages)
  s.wheelset_speed_rad_s = speed == 2 ? 2.0 / (0.0944 / (s.roller_speed_rad_s[0] * 0.185) +
                                               0.0944 / (s.roller_speed_rad_s[1] * 0.185))
                                      : 0.0;
  long i = 0, failed = 0;
  for (auto _ : st) {
    s.time_s = 0.02 * i;
    s.lateral_m = 0.2e-3 * std::sin(2.0 * 3.14159265358979323846 * s.time_s);  // 1 Hz, 0.2 mm
    conforma_rig_result r;
    if (conforma_rig_process_sample(rig, &s, &r) != CONFORMA_OK || r.status != 0) ++failed;
    benchmark::DoNotOptimize(r.contact[0].longitudinal_force_N);
    ++i;
  }
  st.counters["failed"] = static_cast<double>(failed);
  conforma_rig_destroy(rig);
}
BENCHMARK(BM_RigSample)
    ->ArgsProduct({{0, 1}, {0, 1, 2}, {1, 10}})
    ->ArgNames({"conformal", "speed", "update"})
    ->Unit(benchmark::kMillisecond);

}  // namespace
