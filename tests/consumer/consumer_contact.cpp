// Consumer of the installed package (tests/consumer/CMakeLists.txt): S1002 wheel on a 60E1 rail at 1:40, centred
// wheelset, conformal model under load control with 10 kN; exits 1 unless the solve converges and the vertical
// pressure force equals the load. Needs no data files (built-in profiles).
#include <cmath>
#include <cstdio>

#include "conforma/geometry.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact.hpp"

int main() {
  using namespace conforma;
  const WheelsetTrackGeometry geometry(
      MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0), rail_inclination_1in40()));
  const EquilibriumResult rigid = geometry.SolveRigidEquilibrium(0.0, 0.0);
  if (rigid.status != EquilibriumStatus::Converged) {
    std::fprintf(stderr, "rigid equilibrium did not converge\n");
    return 1;
  }
  WheelContactOptions options;
  options.model = ContactModel::Conformal;
  options.vertical_load_N = 10e3;
  const WheelsetVelocity rolling{2.0, 0.0, 0.0, 2.0 / 0.46};
  const WheelContactReport r = SolveWheelContact(geometry, Side::Left, rigid.pose, rolling, options);
  std::printf("status %s, %zu patch(es), vertical pressure force %.3f N for a load of %.1f N\n", to_string(r.status),
              r.patches.size(), r.pressure_vertical_force_N, options.vertical_load_N);
  const bool ok = r.status == WheelContactStatus::Ok && !r.patches.empty() &&
                  std::fabs(r.pressure_vertical_force_N - options.vertical_load_N) <= 1e-3 * options.vertical_load_N;
  std::printf("%s\n", ok ? "PASSED" : "FAILED");
  return ok ? 0 : 1;
}
