#pragma once
// The Manchester wheel and rail from profile FILES, as a C API model and as the C++ geometry with the same
// profiles (a file is taken as canted: inclination 0), for the tests that compare the C API with the C++ pipeline.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"
#include "conforma_c.h"

struct CApiMBenchModel {
  std::string wheel = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/examples/MBench_S1002_v3.prw";
  std::string rail = std::string(CONFORMA_SHARED_DATA) + "/profiles/contact/examples/MBench_UIC60_v3.prr";
  conforma_model* model = nullptr;
  std::unique_ptr<conforma::WheelsetTrackGeometry> geometry;

  // C model with the default parameters (an error fails the calling test) and the C++ geometry.
  void Create() {
    conforma_track_params track;
    conforma_contact_params contact;
    conforma_default_track_params(&track);
    conforma_default_contact_params(&contact);
    track.wheel_profile = wheel.c_str();
    track.rail_profile = rail.c_str();
    char error[CONFORMA_ERROR_TEXT];
    ASSERT_EQ(conforma_model_create(&track, &contact, &model, error, sizeof error), CONFORMA_OK) << error;
    conforma::ProfileReadOptions wo, ro;
    wo.kind = conforma::ProfileKind::Wheel;
    ro.kind = conforma::ProfileKind::Rail;
    geometry = std::make_unique<conforma::WheelsetTrackGeometry>(
        conforma::MakeSymmetricTrack(conforma::LoadProfile(wheel, wo), conforma::LoadProfile(rail, ro), 0.0));
  }
  ~CApiMBenchModel() { conforma_model_destroy(model); }

  // The Manchester pose at lateral shift y_mm (yaw = 2.4 y mrad, 2 m/s, r0 = 0.46 m) and the velocity the C++
  // pipeline gets for it.
  static conforma_wheelset_state State(double y_mm) {
    conforma_wheelset_state s{};
    s.lateral_m = y_mm * 1e-3;
    s.yaw_rad = 2.4 * y_mm * 1e-3;
    s.forward_speed_m_s = 2.0;
    s.axle_angular_velocity_rad_s = 2.0 / 0.46;
    return s;
  }
  static conforma::WheelsetVelocity Velocity() { return conforma::WheelsetVelocity{2.0, 0.0, 0.0, 2.0 / 0.46}; }
  // Evaluation options: the defaults with the rigid wheelset equilibrium first (as the reference computes it).
  static conforma_evaluation_options RigidEquilibriumOptions() {
    conforma_evaluation_options o;
    conforma_default_evaluation_options(&o);
    o.rigid_equilibrium = 1;
    return o;
  }
};
