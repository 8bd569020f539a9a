// Quasi-static curving: one track class (all bogies of a two-bogie metro vehicle, paper 003 §3) on S1002 / 50E4
// at 1:20, V = 15 m/s, no cant; contact model hertz or conformal. Counters: LM iterations and SolveWheelContact
// calls of the whole solve.
#include <benchmark/benchmark.h>

#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/standard_profiles.hpp"

namespace {

using namespace conforma;

VehicleParameters vehicle() {
  VehicleParameters v = MetroVehicle();
  v.bogie_count = 2;
  return v;
}

const WheelsetTrackGeometry& track() {
  static const WheelsetTrackGeometry g([] {
    TrackSetup s = MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R50E4, 0.0), rail_inclination_1in20());
    const double r0 = vehicle().nominal_wheel_radius_m;
    s.nominal_radius_m = {r0, r0};
    return s;
  }());
  return g;
}

void BM_QuasiStaticCurve(benchmark::State& state, ContactModel model, double radius_m) {
  const VehicleParameters v = vehicle();
  QuasiStaticOptions o;
  o.contact.model = model;
  TrackClass t;
  t.name = "bench";
  t.curve_radius_m = radius_m;
  t.speed_m_s = 15.0;
  int iterations = 0, evaluations = 0;
  for (auto _ : state) {
    const QuasiStaticResult r = SolveQuasiStaticCurving(v, track(), t, o);
    iterations = evaluations = 0;
    for (const BogieQuasiStaticReport& b : r.bogies) iterations += b.iterations, evaluations += b.contact_evaluations;
    benchmark::DoNotOptimize(r.total_lateral_force_N);
  }
  state.counters["lm_iterations"] = iterations;
  state.counters["contact_evaluations"] = evaluations;
}

BENCHMARK_CAPTURE(BM_QuasiStaticCurve, hertz_R300, ContactModel::Hertz, 300.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_QuasiStaticCurve, hertz_R1000, ContactModel::Hertz, 1000.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_QuasiStaticCurve, hertz_tangent, ContactModel::Hertz, 0.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_QuasiStaticCurve, conformal_R300, ContactModel::Conformal, 300.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_QuasiStaticCurve, conformal_R1000, ContactModel::Conformal, 1000.0)->Unit(benchmark::kMillisecond);

}  // namespace
