// Run time of Polach's analytic creep force with spin (polach_creep_force.hpp, docs/physics-reference.md §7.3) per
// contact, against Hertz-ellipse FASTSIM at the default 30 x 30 (bench_hertz_fastsim.cpp) on the same inputs.
#include <benchmark/benchmark.h>

#include "conforma/fastsim.hpp"
#include "conforma/polach_creep_force.hpp"

namespace {

// Creepages and a/b varied per iteration so nothing is constant-folded; the creep force regime spans linear to
// saturated (xi up to ~6e-3, spin up to ~2 1/m). The same sequence for both benchmarks.
struct InputSweep {
  double t = 0.0;
  template <class Input>
  void Next(Input* in) {
    t = t > 1.0 ? 0.0 : t + 0.0137;
    const double ab = 0.5 + 1.5 * t;
    in->a_m = 6e-3 * ab;
    in->b_m = 6e-3;
    in->creepages = {6e-3 * t - 2e-3, 1e-3 - 2e-3 * t, 2.0 * t - 0.5};
  }
};

void BM_PolachCreepForce(benchmark::State& state) {
  conforma::PolachInput in;
  in.normal_force_N = 80e3;
  in.friction_coefficient = 0.3;
  InputSweep sweep;
  for (auto _ : state) {
    sweep.Next(&in);
    const conforma::PolachResult r = conforma::SolvePolachCreepForce(in);
    benchmark::DoNotOptimize(r.fx_N);
    benchmark::DoNotOptimize(r.fy_N);
  }
}
BENCHMARK(BM_PolachCreepForce);

void BM_FastsimHertzSameInputs(benchmark::State& state) {
  conforma::FastsimHertzInput in;
  in.normal_force_N = 80e3;
  in.friction_coefficient = 0.3;
  conforma::FastsimOptions options;
  conforma::FastsimPatch patch;
  conforma::FastsimResult result;
  InputSweep sweep;
  for (auto _ : state) {
    sweep.Next(&in);
    conforma::SolveFastsimHertz(in, options, &patch, &result);
    benchmark::DoNotOptimize(result.fx_N);
  }
}
BENCHMARK(BM_FastsimHertzSameInputs);

}  // namespace
