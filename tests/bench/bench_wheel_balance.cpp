// One wheel through the pipeline (SolveWheelContact) with load control, balancing the pressure alone (the behaviour
// before issue 15) or the total vertical force (pressure and creep forces, the default; docs/physics-reference.md
// §3.6.1), or the total one with the candidates found for the pressure forces' load (total_consistent, §3.6.1 step 4):
// the cost of the coupling per wheel and the load-control iterations. S1002 on 60E1 at 1:40, 10 kN, the
// wheelset at its rigid equilibrium with yaw 1 mrad, 20 m/s, creepages from the kinematics (left wheel).
#include <benchmark/benchmark.h>

#include "conforma/geometry.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact.hpp"

namespace {

using namespace conforma;

const WheelsetTrackGeometry& Track() {
  static const WheelsetTrackGeometry g(MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0),
                                                          rail_inclination_1in40()));  // read-only after init
  return g;
}

void BM_WheelLoadBalance(benchmark::State& state, ContactModel model, LoadBalance balance, double lateral_m) {
  const EquilibriumResult e = Track().SolveRigidEquilibrium(lateral_m, 1e-3);
  const WheelsetVelocity v{20.0, 0.0, 0.0, 20.0 / 0.46};
  WheelContactOptions o;
  o.model = model;
  o.load_balance = balance;
  WheelContactReport r;
  for (auto _ : state) {
    r = SolveWheelContact(Track(), Side::Left, e.pose, v, o);
    benchmark::DoNotOptimize(r);
  }
  state.counters["load_iterations"] = r.load_iterations;
  state.counters["patches"] = static_cast<double>(r.patches.size());
  state.counters["Fz_over_load"] = r.vertical_force_N / o.vertical_load_N;
  state.counters["candidate_searches"] = r.candidate_searches;
}

}  // namespace

BENCHMARK_CAPTURE(BM_WheelLoadBalance, conformal_pressure_y3mm, ContactModel::Conformal, LoadBalance::Pressure, 3e-3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_WheelLoadBalance, conformal_total_y3mm, ContactModel::Conformal, LoadBalance::Total, 3e-3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_WheelLoadBalance, conformal_pressure_y7mm_flange, ContactModel::Conformal, LoadBalance::Pressure,
                  7e-3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_WheelLoadBalance, conformal_total_y7mm_flange, ContactModel::Conformal, LoadBalance::Total, 7e-3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_WheelLoadBalance, hertz_pressure_y7mm_flange, ContactModel::Hertz, LoadBalance::Pressure, 7e-3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_WheelLoadBalance, hertz_total_y7mm_flange, ContactModel::Hertz, LoadBalance::Total, 7e-3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_WheelLoadBalance, conformal_total_consistent_y3mm, ContactModel::Conformal,
                  LoadBalance::TotalConsistent, 3e-3)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_WheelLoadBalance, conformal_total_consistent_y7mm_flange, ContactModel::Conformal,
                  LoadBalance::TotalConsistent, 7e-3)
    ->Unit(benchmark::kMicrosecond);
