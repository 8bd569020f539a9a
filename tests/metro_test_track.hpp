#pragma once
// The paper-003 metro track of the kinematics tests: 711 mm S1002 wheels on 50E4 rails at 1:20 (paper 003 Table 1).
#include "conforma/geometry.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma::test {

constexpr double kMetroWheelRadius = 0.711 / 2.0;  // m

inline const WheelsetTrackGeometry& MetroTrackGeometry() {
  static const WheelsetTrackGeometry g([] {
    TrackSetup s = MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R50E4, 0.0), rail_inclination_1in20());
    s.nominal_radius_m = {kMetroWheelRadius, kMetroWheelRadius};
    return s;
  }());
  return g;
}

}  // namespace conforma::test
