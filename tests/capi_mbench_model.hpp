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
};
