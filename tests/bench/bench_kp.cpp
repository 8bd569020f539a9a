// Time per patch of planar KP, KPEC and conformal KP at the default resolution (KpOptions::strips_across_contact),
// approach given and load given. Cases: a Hertzian tread patch (a/b = 1.33) and the R 10.05 mm conformal groove.
#include <benchmark/benchmark.h>

#include "conforma/validation/analytic_patches.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"

namespace {

using namespace conforma;

PatchGeometry BenchPatch(int which) {
  if (which == 0) return kp_test::HertzianPatch(0.55, 0.96, 0.012, 81);  // a/b ~ 1.33 tread-like
  return kp_test::GroovePatch(10e-3, 10.05e-3, 0.42, 12e-3, 241);
}

KpOptions BenchOptions(int model) {
  Material material;
  if (model == 0) return PlanarKpOptions(material);
  if (model == 1) return KpecOptions(material);
  return ConformalKpOptions(material);
}

// state.range(0): model 0 = kp, 1 = kpec, 2 = conformal; range(1): patch 0 = Hertzian, 1 = groove.
void BM_KpForApproach(benchmark::State& state) {
  const PatchGeometry patch = BenchPatch(static_cast<int>(state.range(1)));
  const KpOptions options = BenchOptions(static_cast<int>(state.range(0)));
  const double approach = state.range(1) == 0 ? 6.0e-5 : 1.6e-5;
  for (auto _ : state) benchmark::DoNotOptimize(SolveKikPiotrowskiForApproach(patch, approach, options));
}

void BM_KpForLoad(benchmark::State& state) {
  const PatchGeometry patch = BenchPatch(static_cast<int>(state.range(1)));
  KpLoadOptions options;
  options.kp = BenchOptions(static_cast<int>(state.range(0)));
  const double load = state.range(1) == 0 ? 50.0e3 : 10.0e3;
  for (auto _ : state) benchmark::DoNotOptimize(SolveKikPiotrowskiForLoad(patch, load, options));
}

BENCHMARK(BM_KpForApproach)->ArgsProduct({{0, 1, 2}, {0, 1}})->ArgNames({"model", "patch"})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_KpForLoad)->ArgsProduct({{0, 1, 2}, {0, 1}})->ArgNames({"model", "patch"})->Unit(benchmark::kMicrosecond);

}  // namespace
