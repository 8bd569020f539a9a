// The `reference` model (BEM normal solve on the 0.2 mm grid, wheel load control, docs/physics-reference.md §10.4)
// for one wheel, as `conforma contact --model reference --side left --json` solves it (rigid equilibrium pose, 10 kN,
// V = 2 m/s, the CLI's track defaults):
//   tread:   S1002 / 60E1 at 1:40, y = 0                          (Manchester tread case)
//   flange:  S1002 / 60E1 at 1:40, y = 7 mm, yaw = 16.8 mrad      (flange contact)
//   worn:    worn_high_mileage.prw / site_b_hr.prr, inclination 0, y = 15.5 mm (worn pair)
// Targets of issue 14 for normal + tangential per wheel: tread <= 0.2 s, flange <= 0.05 s, worn <= 1 s; the normal
// part at most about a third of that. Counters: load-control iterations, patches, p_max of the first patch (MPa).
#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact.hpp"

namespace {

using namespace conforma;

std::unique_ptr<WheelsetTrackGeometry> Track(const Profile& wheel, const Profile& rail, double inclination_rad) {
  TrackSetup setup = MakeSymmetricTrack(wheel, rail, inclination_rad);
  // the defaults of `conforma contact` (src/app/cli_setup.hpp)
  setup.gauge_m = 1.435;
  setup.gauge_height_m = 0.014;
  setup.flange_back_distance_m = 1.360;
  setup.flange_back_position_m = -0.070;
  setup.nominal_radius_m = {0.460, 0.460};
  setup.validate();
  return std::make_unique<WheelsetTrackGeometry>(std::move(setup));
}

const WheelsetTrackGeometry& NewPair() {
  static const auto g = Track(MakeS1002(), MakeRail(RailSection::R60E1, 0.0), rail_inclination_1in40());
  return *g;
}

const WheelsetTrackGeometry& WornPair() {
  static const auto g = [] {
    const std::string bank = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/testbank/profiles/";
    ProfileReadOptions w, r;
    w.kind = ProfileKind::Wheel;
    r.kind = ProfileKind::Rail;
    return Track(LoadProfile(bank + "worn_high_mileage.prw", w), LoadProfile(bank + "site_b_hr.prr", r), 0.0);
  }();
  return *g;
}

void BM_ReferenceWheel(benchmark::State& state, bool worn, double y_mm, double yaw_mrad) {
  const WheelsetTrackGeometry& geometry = worn ? WornPair() : NewPair();
  const EquilibriumResult eq = geometry.SolveRigidEquilibrium(y_mm * 1e-3, yaw_mrad * 1e-3);
  if (eq.status == EquilibriumStatus::NoContact) {
    state.SkipWithError("no rigid contact");
    return;
  }
  const double r0 = geometry.setup().nominal_radius_m[0];
  const WheelsetVelocity velocity{2.0, 0.0, 0.0, 2.0 / r0};
  WheelContactOptions options;
  options.model = ContactModel::Reference;
  WheelContactReport report;
  for (auto _ : state) {
    report = SolveWheelContact(geometry, Side::Left, eq.pose, velocity, options);
    benchmark::DoNotOptimize(report.vertical_force_N);
  }
  state.counters["load_iterations"] = report.load_iterations;
  state.counters["patches"] = static_cast<double>(report.patches.size());
  state.counters["pmax_MPa"] = report.patches.empty() ? 0.0 : report.patches.front().pmax_Pa * 1e-6;
}

BENCHMARK_CAPTURE(BM_ReferenceWheel, tread, false, 0.0, 0.0)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReferenceWheel, flange, false, 7.0, 16.8)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_ReferenceWheel, worn, true, 15.5, 0.0)->Unit(benchmark::kMillisecond);

}  // namespace
