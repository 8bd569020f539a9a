// Curved-patch FASTSIM vs classic FASTSIM per patch at 30 x 30 (target: within 2x and <= 30 us per patch).
#include <benchmark/benchmark.h>

#include "conforma/curved_fastsim.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/local_creepage.hpp"
#include "../tangential_test_patches.hpp"

namespace {

using namespace conforma;

void BM_ClassicFastsim30(benchmark::State& state) {
  FastsimHertzInput in;
  in.a_m = 6e-3;
  in.b_m = 4e-3;
  in.normal_force_N = 80e3;
  in.creepages = {1e-3, -5e-4, 0.6};
  in.nx = in.ny = 30;
  FastsimPatch patch;
  FastsimResult result;
  for (auto _ : state) {
    SolveFastsimHertz(in, FastsimOptions{}, &patch, &result);
    benchmark::DoNotOptimize(result.fx_N);
  }
}
BENCHMARK(BM_ClassicFastsim30);

// Curved solver on a 30-strip conformal-like patch (normals turning by 0.3 rad across), per-strip creepages,
// SDEC flexibilities: includes the SDEC reduction, the bound set-up and the rotation into the reference frame.
void BM_CurvedFastsim30(benchmark::State& state) {
  KpResult kp = tangential_test::EllipticStrips(6e-3, 4e-3, 80e3, 30);
  for (KpStrip& s : kp.strips) s.alpha_rad = 0.3 * s.s_m / 4e-3;
  CurvedFastsimInput in;
  const bool per_strip = state.range(0) != 0;
  in.strip_creepages.assign(per_strip ? kp.strips.size() : 1, FastsimCreepages{1e-3, -5e-4, 0.6});
  CurvedFastsimOptions options;
  options.elements_per_strip = 30;
  CurvedFastsimWorkspace workspace;
  CurvedFastsimResult result;
  for (auto _ : state) {
    SolveCurvedFastsim(kp, in, options, &workspace, &result);
    benchmark::DoNotOptimize(result.fx_N);
  }
}
BENCHMARK(BM_CurvedFastsim30)->Arg(0)->Arg(1);

}  // namespace
