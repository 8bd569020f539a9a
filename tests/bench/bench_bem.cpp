// Time per solve of the reference BEM normal solver (slow by design): a Hertzian patch (a/b = 1, 50 kN)
// on n x n elements with the half-space and the Blanco operator (curved: alpha = s / 12 mm), load given and
// approach given.
#include <benchmark/benchmark.h>

#include <cmath>

#include "conforma/bem_reference.hpp"

namespace {

using namespace conforma;

BemGrid BenchGrid(int n, bool curved) {
  // A = B = 1.087 /m (contact_hertz_creep_cases a/b = 1): Hertz a = b = 5.33 mm at 50 kN; box 1.25 a.
  BemGrid grid = QuadraticGapGrid(1.087, 1.087, n, n, 1.25 * 5.33e-3, 1.25 * 5.33e-3);
  if (curved) {
    grid.alpha_rad.resize(static_cast<size_t>(n));
    for (int j = 0; j < n; ++j) grid.alpha_rad[static_cast<size_t>(j)] = grid.s_centre_m(j) / 12e-3;
  }
  return grid;
}

// range(0) = n, range(1) = 0 half-space / 1 Blanco (curved), range(2) = 0 load given / 1 approach given.
void BM_BemNormal(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool blanco = state.range(1) == 1;
  const BemGrid grid = BenchGrid(n, blanco);
  BemOptions options;
  options.influence = blanco ? BemInfluence::Blanco : BemInfluence::HalfSpace;
  if (state.range(2) == 0) {
    options.normal_force_N = 50e3;
  } else {
    options.control = BemLoadControl::Approach;
    options.approach_m = 6.177e-5;  // Hertz approach of the a/b = 1 case
  }
  const Material material;
  int iterations = 0;
  for (auto _ : state) {
    const BemResult r = SolveBemNormal(grid, material, options);
    iterations = r.iterations;
    benchmark::DoNotOptimize(r.max_pressure_Pa);
  }
  state.counters["cg_iterations"] = iterations;
}
BENCHMARK(BM_BemNormal)
    ->ArgsProduct({{32, 64}, {0, 1}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
