#pragma once
// Shared set-up of the pipeline tests: new S1002 on 60E1 at 1:40, a rolling wheelset and its rigid-equilibrium pose.
#include <gtest/gtest.h>

#include "conforma/geometry.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma::test {

inline const WheelsetTrackGeometry& PipelineGeometry() {
  static const WheelsetTrackGeometry g(MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0),
                                                          rail_inclination_1in40()));
  return g;
}
inline WheelsetVelocity Rolling() { return {2.0, 0.0, 0.0, 2.0 / 0.46}; }
// Rigid two-rail equilibrium at lateral shift y [mm] and yaw [mrad]; expects it to converge.
inline WheelsetPose Pose(double y_mm, double yaw_mrad = 0.0) {
  const EquilibriumResult e = PipelineGeometry().SolveRigidEquilibrium(y_mm * 1e-3, yaw_mrad * 1e-3);
  EXPECT_EQ(e.status, EquilibriumStatus::Converged);
  return e.pose;
}

}  // namespace conforma::test
