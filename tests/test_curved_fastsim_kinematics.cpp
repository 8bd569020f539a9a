// Local rigid slip on a curved patch (local_creepage.hpp): rigid-body kinematics vs the reference-creepage mode on a
// wheel rolling in a circular groove; the spin produced by the turning normal.
// test-links: fastsim_ext  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>

#include "conforma/curved_fastsim.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/load_control.hpp"
#include "conforma/local_creepage.hpp"
#include "conforma/validation/analytic_patches.hpp"

using namespace conforma;

TEST(LocalCreepage, GrooveKinematicsAgreesWithReferenceMode) {
  const double R = 0.46, Rg = 0.02, V = 20.0, xi0 = 2e-3, eta0 = -1e-3;
  const double Omega = (1.0 - xi0) * V / R;  // rolling about the axle (track y), centre above the contact point
  RigidBodyMotion motion;
  motion.velocity_m_per_s = Eigen::Vector3d(V, eta0 * V, 0.0);
  motion.angular_velocity_rad_per_s = Eigen::Vector3d(0.0, Omega, 0.0);
  motion.origin_m = Eigen::Vector3d(0.0, 0.0, R);
  motion.rolling_speed_m_per_s = V;
  PatchReferenceFrame frame;  // x, t0 = y, n0 = z (right-handed)
  KpResult kp;
  PatchGeometry geometry;
  for (int j = -10; j <= 10; ++j) {
    const double s = j * 1e-3, theta = s / Rg;
    KpStrip k;
    k.s_m = s;
    k.ds_m = 1e-3;
    k.half_length_m = 5e-3;
    k.alpha_rad = -theta;  // concave groove (patch.hpp)
    k.position_m = Eigen::Vector2d(Rg * std::sin(theta), Rg * (1.0 - std::cos(theta)));
    kp.strips.push_back(k);
    geometry.s_m.push_back(s);
    geometry.wheel_radius_m.push_back(R - k.position_m.y());
    geometry.alpha_rad.push_back(-theta);
  }
  const std::vector<FastsimCreepages> full = StripCreepagesFromKinematics(motion, frame, kp);
  ReferenceCreepages reference;
  reference.xi = xi0;
  reference.eta = eta0;
  reference.phi_per_m = 0.0;
  reference.reference_radius_m = R;
  reference.tangent_rotation_per_m = ReferenceTangentialRotation(motion, frame);
  EXPECT_NEAR(reference.tangent_rotation_per_m, Omega / V, 1e-12);
  const std::vector<FastsimCreepages> simple = StripCreepagesFromReference(reference, geometry, kp);
  ASSERT_EQ(full.size(), simple.size());
  for (size_t j = 0; j < full.size(); ++j) {
    EXPECT_NEAR(full[j].xi, simple[j].xi, 1e-12) << j;
    EXPECT_NEAR(full[j].eta, simple[j].eta, 1e-12) << j;
    EXPECT_NEAR(full[j].phi_per_m, simple[j].phi_per_m, 1e-9) << j;
    // The turning normal makes spin out of the axle rotation: phi_j = omega . n_j / V = -(Omega/V) sin(theta_j).
    EXPECT_NEAR(full[j].phi_per_m, -(Omega / V) * std::sin(kp.strips[j].s_m / Rg), 1e-9) << j;
  }
  // At the reference point the local creepages are the reference ones.
  EXPECT_NEAR(full[10].xi, xi0, 1e-12);
  EXPECT_NEAR(full[10].eta, eta0, 1e-12);
  EXPECT_NEAR(full[10].phi_per_m, 0.0, 1e-12);
}

// Flat patch: a yaw-rate spin omega_z gives the same creepages in every strip (creepages at the spin origin).
TEST(LocalCreepage, FlatPatchUniformCreepages) {
  RigidBodyMotion motion;
  const double V = 10.0, R = 0.5;
  motion.velocity_m_per_s = Eigen::Vector3d(V, 0.02 * V, 0.0);
  motion.angular_velocity_rad_per_s = Eigen::Vector3d(0.0, 0.999 * V / R, 3.0);
  motion.origin_m = Eigen::Vector3d(0.0, 0.0, R);
  motion.rolling_speed_m_per_s = V;
  KpResult kp;
  for (int j = -5; j <= 5; ++j) {
    KpStrip k;
    k.s_m = j * 1e-3;
    k.ds_m = 1e-3;
    k.half_length_m = 4e-3;
    k.x_centre_m = 0.5e-3 * j;
    k.position_m = Eigen::Vector2d(k.s_m, 0.0);
    kp.strips.push_back(k);
  }
  for (const FastsimCreepages& c : StripCreepagesFromKinematics(motion, PatchReferenceFrame{}, kp)) {
    EXPECT_NEAR(c.xi, 1e-3, 1e-12);
    EXPECT_NEAR(c.eta, 0.02, 1e-12);
    EXPECT_NEAR(c.phi_per_m, 3.0 / V, 1e-12);
  }
}

// A conformal patch (wheel of profile radius 10 mm in a 10.5 mm groove, conformal KP, 10 kN) in pure rolling: the
// per-strip rigid kinematics give spins of opposite sign on the two sides; by symmetry the lateral force in the
// reference frame and the moment about the longitudinal axis vanish. In full sliding (large xi) the tangential
// traction is mu p_n everywhere: |sum p_t dA| along x = mu times the bound load, also with a slip-dependent law
// (F/N -> mu(xi) at large xi).

TEST(CurvedFastsimConformal, GrooveSymmetryAndFullSlip) {
  Material material;
  const double r0 = 0.420, V = 20.0;
  const PatchGeometry patch = kp_test::GroovePatch(10.0e-3, 10.5e-3, r0, 12.0e-3, 241);
  KpLoadOptions load;
  load.kp = ConformalKpOptions(material);
  const KpResult kp = SolveKikPiotrowskiForLoad(patch, 1.0e4, load);
  ASSERT_EQ(kp.status, KpStatus::Ok);
  ASSERT_TRUE(kp.is_conformal);
  RigidBodyMotion motion;  // x, t0 = y, n0 = z frame; wheel centre above the reference point, rolling about y
  motion.velocity_m_per_s = Eigen::Vector3d(V, 0.0, 0.0);
  motion.angular_velocity_rad_per_s = Eigen::Vector3d(0.0, V / r0, 0.0);
  motion.origin_m = Eigen::Vector3d(0.0, 0.0, r0);
  motion.rolling_speed_m_per_s = V;
  CurvedFastsimInput in;
  in.material = material;
  in.strip_creepages = StripCreepagesFromKinematics(motion, PatchReferenceFrame{}, kp);
  const CurvedFastsimResult rolling = SolveCurvedFastsim(kp, in, CurvedFastsimOptions{});
  ASSERT_NE(rolling.status, FastsimStatus::NoContact);
  EXPECT_LT(in.strip_creepages.front().phi_per_m * in.strip_creepages.back().phi_per_m, 0.0);
  const double muN = 0.3 * rolling.bound_load_N;
  EXPECT_NEAR(rolling.force_reference_N.y(), 0.0, 1e-6 * muN);
  EXPECT_NEAR(rolling.moment_reference_Nm.x(), 0.0, 1e-6 * muN * 1e-3);
  std::printf("groove, pure rolling: Fx = %.1f N, Fn-frame force (%.3g, %.3g, %.3g) N, slip area %.1f %%\n",
              rolling.fx_N, rolling.force_reference_N.x(), rolling.force_reference_N.y(),
              rolling.force_reference_N.z(), 100 * rolling.slip_area_m2 / (rolling.slip_area_m2 + rolling.adhesion_area_m2));
  // Full sliding forwards (xi0 = 0.1 on top of the kinematics).
  motion.velocity_m_per_s.x() = V * 1.1;
  in.strip_creepages = StripCreepagesFromKinematics(motion, PatchReferenceFrame{}, kp);
  const CurvedFastsimResult sliding = SolveCurvedFastsim(kp, in, CurvedFastsimOptions{});
  EXPECT_NEAR(std::hypot(sliding.fx_N, sliding.fs_N), muN, 0.005 * muN);
  in.friction = FrictionLaw::F1a(0.5, 0.6, 50.0);
  const CurvedFastsimResult variable = SolveCurvedFastsim(kp, in, CurvedFastsimOptions{});
  EXPECT_NEAR(-variable.fx_N / variable.bound_load_N, in.friction(0.1), 0.01 * in.friction(0.1));
}
