// Run time of the classic baseline: exact Hertz alone, and Hertz + FASTSIM per patch at 20x20, 30x30, 50x50
// (target <= 15 us per patch at 30x30). Patch/result buffers are reused as a simulation loop would.
#include <benchmark/benchmark.h>

#include "conforma/fastsim.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kalker.hpp"

namespace {

// Wheel-rail tread-like curvatures, varied slightly per iteration so nothing is constant-folded.
void BM_HertzForLoad(benchmark::State& state) {
  const conforma::Material steel;
  double B = 1.6;
  for (auto _ : state) {
    B = B > 9.0 ? 1.6 : B + 0.013;
    benchmark::DoNotOptimize(conforma::SolveHertzForLoad(1.087, B, 80e3, steel));
  }
}
BENCHMARK(BM_HertzForLoad);

void BM_HertzPlusFastsim(benchmark::State& state) {
  const conforma::Material steel;
  conforma::FastsimHertzInput in;
  in.normal_force_N = 80e3;
  in.creepages = {0.001, -0.0008, 0.5};
  in.friction_coefficient = 0.3;
  in.nx = in.ny = static_cast<int>(state.range(0));
  in.rolling_speed_m_per_s = 20.0;
  conforma::FastsimOptions options;
  conforma::FastsimPatch patch;
  conforma::FastsimResult result;
  double B = 1.6;
  for (auto _ : state) {
    B = B > 9.0 ? 1.6 : B + 0.013;
    const conforma::HertzResult h = conforma::SolveHertzForLoad(1.087, B, in.normal_force_N, steel);
    in.a_m = h.a_m;
    in.b_m = h.b_m;
    conforma::SolveFastsimHertz(in, options, &patch, &result);
    benchmark::DoNotOptimize(result.fx_N);
  }
}
BENCHMARK(BM_HertzPlusFastsim)->Arg(20)->Arg(30)->Arg(50);

// The value-returning entry (allocates its buffers on every call), for comparison.
void BM_HertzPlusFastsimByValue(benchmark::State& state) {
  const conforma::Material steel;
  conforma::FastsimHertzInput in;
  in.normal_force_N = 80e3;
  in.creepages = {0.001, -0.0008, 0.5};
  in.nx = in.ny = static_cast<int>(state.range(0));
  double B = 1.6;
  for (auto _ : state) {
    B = B > 9.0 ? 1.6 : B + 0.013;
    const conforma::HertzResult h = conforma::SolveHertzForLoad(1.087, B, in.normal_force_N, steel);
    in.a_m = h.a_m;
    in.b_m = h.b_m;
    benchmark::DoNotOptimize(conforma::SolveFastsimHertz(in, conforma::FastsimOptions{}).fx_N);
  }
}
BENCHMARK(BM_HertzPlusFastsimByValue)->Arg(30);

}  // namespace

namespace {
void BM_KalkerCoefficients(benchmark::State& state) {
  double ab = 0.3;
  for (auto _ : state) {
    ab = ab > 6.0 ? 0.3 : ab + 0.011;
    benchmark::DoNotOptimize(conforma::KalkerCoefficients(ab, 0.28));
  }
}
BENCHMARK(BM_KalkerCoefficients);
}  // namespace
