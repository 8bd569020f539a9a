// The conformal model at its default grid (s31e30) over the 30 patches of `conforma bench` (benchmark_cases.hpp):
// time per patch, load controlled (as the bench times it), approach given, and the normal solve alone. Targets
// (issue 6): <= 50 us per patch load controlled, <= 3x the Hertz model.
#include <benchmark/benchmark.h>

#include <vector>

#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/wheel_contact.hpp"

namespace {

using namespace conforma;

const std::vector<BenchCase>& Cases() {
  static const std::vector<BenchCase> cases = MakeBenchCases(CONFORMA_SHARED_DATA);  // read-only after init
  return cases;
}

// mode 0: load controlled + tangential; 1: approach given + tangential; 2: approach given, normal only;
// 3: load controlled, normal only. model 0: conformal, 1: hertz.
void BM_ConformalBenchCases(benchmark::State& state) {
  const std::vector<BenchCase>& cases = Cases();
  const int mode = static_cast<int>(state.range(0));
  PatchSolveOptions base;
  base.model = state.range(1) == 0 ? ContactModel::Conformal : ContactModel::Hertz;
  std::vector<PatchSolveOptions> options(cases.size(), base);
  for (size_t k = 0; k < cases.size(); ++k) {
    if (mode == 1 || mode == 2) options[k].approach_m = SolveBenchCase(cases[k], base).approach_m;
    options[k].solve_tangential = mode < 2;
    if (options[k].approach_m < 0.0) options[k].approach_m = 0.0;
  }
  for (auto _ : state) {
    for (size_t k = 0; k < cases.size(); ++k) benchmark::DoNotOptimize(SolveBenchCase(cases[k], options[k]));
  }
  state.counters["patches"] = static_cast<double>(cases.size());  // time / patches = time per patch
}

// Load control alone (the one load control through the patch solver, tolerance 1e-6 as the bench, normal problem
// only): mean root-finder steps per patch (the two bracket ends come on top).
void BM_ConformalBenchLoadControl(benchmark::State& state) {
  const std::vector<BenchCase>& cases = Cases();
  PatchSolveOptions options;
  options.model = ContactModel::Conformal;
  options.solve_tangential = false;
  int steps = 0, not_converged = 0;
  for (auto _ : state) {
    steps = 0;
    not_converged = 0;
    for (const BenchCase& c : cases) {
      const PatchSolution r = SolveBenchPatch(c, options);
      steps += r.load.iterations;
      not_converged += r.load.status != LoadControlStatus::Ok;
      benchmark::DoNotOptimize(r);
    }
  }
  state.counters["root_steps_per_patch"] = static_cast<double>(steps) / static_cast<double>(cases.size());
  state.counters["not_converged"] = not_converged;
}
BENCHMARK(BM_ConformalBenchLoadControl)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_ConformalBenchCases)
    ->ArgsProduct({{0, 1, 2, 3}, {0}})
    ->ArgNames({"mode", "model"})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ConformalBenchCases)->Args({0, 1})->ArgNames({"mode", "model"})->Unit(benchmark::kMillisecond);

}  // namespace
