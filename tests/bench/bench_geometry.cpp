// Rigid contact geometry per wheelset pose (both wheels): S1002 on 60E1 1:40, prepared once.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "conforma/contact_candidates.hpp"
#include "conforma/geometry.hpp"
#include "conforma/standard_profiles.hpp"

namespace {

using namespace conforma;

const WheelsetTrackGeometry& track() {
  static const WheelsetTrackGeometry g(MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0),
                                                         rail_inclination_1in40()));
  return g;
}

std::vector<WheelsetPose> poses() {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> y(-0.008, 0.008), yaw(-0.01, 0.01);
  std::vector<WheelsetPose> p(256);
  for (auto& q : p) q = WheelsetPose{y(rng), 0.0, 0.0, yaw(rng)};
  return p;
}

void BM_RigidContactsPerPose(benchmark::State& state) {
  const WheelsetTrackGeometry& g = track();
  const auto ps = poses();
  size_t i = 0;
  for (auto _ : state) {
    WheelsetContactResult r = g.RigidContacts(ps[i++ % ps.size()]);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_RigidContactsPerPose)->Unit(benchmark::kMicrosecond);

void BM_MinimumVerticalGapBothWheels(benchmark::State& state) {
  const WheelsetTrackGeometry& g = track();
  const auto ps = poses();
  size_t i = 0;
  for (auto _ : state) {
    double gl, yl, gr, yr;
    const WheelsetPose& p = ps[i++ % ps.size()];
    benchmark::DoNotOptimize(g.MinimumVerticalGap(Side::Left, p, &gl, &yl));
    benchmark::DoNotOptimize(g.MinimumVerticalGap(Side::Right, p, &gr, &yr));
  }
}
BENCHMARK(BM_MinimumVerticalGapBothWheels)->Unit(benchmark::kMicrosecond);

void BM_RigidEquilibrium(benchmark::State& state) {
  const WheelsetTrackGeometry& g = track();
  const auto ps = poses();
  size_t i = 0;
  for (auto _ : state) {
    const WheelsetPose& p = ps[i++ % ps.size()];
    EquilibriumResult e = g.SolveRigidEquilibrium(p.lateral_m, p.yaw_rad);
    benchmark::DoNotOptimize(e);
  }
}
BENCHMARK(BM_RigidEquilibrium)->Unit(benchmark::kMicrosecond);

void BM_CandidatesForLoad(benchmark::State& state) {
  const WheelsetTrackGeometry& g = track();
  const auto ps = poses();
  size_t i = 0;
  for (auto _ : state) {
    CandidateResult r = FindContactCandidatesForLoad(g, Side::Left, ps[i++ % ps.size()], 50e3, Material{});
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_CandidatesForLoad)->Unit(benchmark::kMicrosecond);

}  // namespace
