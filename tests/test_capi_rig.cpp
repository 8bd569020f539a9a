// test-links: rig
// The roller-rig C entry (conforma_c.h, conforma_rig_process_sample) gives the same numbers as the C++ call
// (ProcessRigSample) sample after sample on its own evolving state, and reports bad input and failures as statuses.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "conforma/roller_rig_sample.hpp"
#include "conforma_c.h"

namespace {

constexpr double kPi = 3.14159265358979323846;

conforma_rig_sample CSample(int i) {
  conforma_rig_sample s{};
  s.time_s = 0.02 * i;
  s.duration_s = 0.02;
  s.lateral_m = 0.2e-3 * std::sin(0.3 * i);
  s.roller_speed_rad_s[0] = 500.0 * 2.0 * kPi / 60.0;
  s.roller_speed_rad_s[1] = s.roller_speed_rad_s[0] * 0.95 / 1.05;
  s.wheel_load_N[0] = 50.0 * 9.81;
  s.wheel_load_N[1] = 48.0 * 9.81;
  s.wheelset_speed_rad_s = 0.0;  // solved
  return s;
}

TEST(CApiRig, SameNumbersAsTheCppCall) {
  for (const char* model : {"hertz", "conformal"}) {
    conforma_rig_params p;
    conforma_default_rig_params(&p);
    p.model = model;
    conforma_rig* rig = nullptr;
    char err[CONFORMA_ERROR_TEXT];
    ASSERT_EQ(conforma_rig_create(&p, &rig, err, sizeof err), CONFORMA_OK) << err;
    struct Destroy { conforma_rig* r; ~Destroy() { conforma_rig_destroy(r); } } destroy{rig};

    conforma::RollerRigSampleOptions o = conforma::RollerRigSampleOptions::Defaults();
    o.kinematics.contact.model = conforma::ParseContactModel(model);
    conforma::RollerRigState state = conforma::MakeRollerRigState(o);
    for (int i = 0; i < 12; ++i) {  // past the first filter (step 10)
      const conforma_rig_sample cs = CSample(i);
      conforma_rig_result cr;
      ASSERT_EQ(conforma_rig_process_sample(rig, &cs, &cr), CONFORMA_OK) << cr.error_message;
      conforma::RollerRigSample s;
      s.time_s = cs.time_s;
      s.duration_s = cs.duration_s;
      s.lateral_m = cs.lateral_m;
      s.roller_speed_rad_s = {cs.roller_speed_rad_s[0], cs.roller_speed_rad_s[1]};
      s.wheel_load_N = {cs.wheel_load_N[0], cs.wheel_load_N[1]};
      const conforma::RollerRigSampleResult r = conforma::ProcessRigSample(o, &state, s);
      ASSERT_EQ(cr.status, 0) << model << " " << i << ": " << cr.error_message;
      EXPECT_EQ(cr.status, static_cast<int>(r.status));
      EXPECT_EQ(cr.kinematics_status, static_cast<int>(r.kinematics.status));
      EXPECT_EQ(cr.wheelset_speed_rad_s, r.kinematics.wheelset_speed_rad_s) << model << " " << i;
      EXPECT_EQ(cr.filtered, r.filtered ? 1 : 0);
      EXPECT_EQ(cr.step, r.step);
      for (int k = 0; k < 2; ++k) {
        const conforma::RollerRigContactResult& c = r.kinematics.contact[k];
        EXPECT_EQ(cr.contact[k].normal_force_N, c.fn_N);
        EXPECT_EQ(cr.contact[k].longitudinal_force_N, c.fx_N) << model << " " << i << " " << k;
        EXPECT_EQ(cr.contact[k].creepage_longitudinal, c.xi);
        EXPECT_EQ(cr.contact[k].wheel_wear_area_m2, r.wheel_wear_area_m2[k]);
        EXPECT_EQ(cr.contact[k].roller_wear_max_depth_m, r.roller_wear_max_depth_m[k]);
        EXPECT_EQ(cr.contact[k].spring_force_N, r.kinematics.spring_force_N[k]);
      }
      EXPECT_GT(cr.contact[0].wheel_wear_area_m2, 0.0);
    }
  }
}

TEST(CApiRig, ErrorsAndStatuses) {
  conforma_rig_params p;
  conforma_default_rig_params(&p);
  conforma_rig* rig = nullptr;
  char err[CONFORMA_ERROR_TEXT];
  p.roller_radius_m = -1.0;
  EXPECT_EQ(conforma_rig_create(&p, &rig, err, sizeof err), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(err).find("roller_radius_m"), std::string::npos) << err;
  EXPECT_EQ(rig, nullptr);
  conforma_default_rig_params(&p);
  p.strip_mean_elements = 0.5;  // paper 000 eq. 16's C must be >= 1
  EXPECT_EQ(conforma_rig_create(&p, &rig, err, sizeof err), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(err).find("strip_mean_elements"), std::string::npos) << err;
  conforma_default_rig_params(&p);
  EXPECT_EQ(conforma_rig_create(nullptr, &rig, err, sizeof err), CONFORMA_ERROR_NULL);
  ASSERT_EQ(conforma_rig_create(&p, &rig, err, sizeof err), CONFORMA_OK) << err;
  conforma_rig_sample s = CSample(0);
  conforma_rig_result r;
  s.duration_s = -0.02;
  EXPECT_EQ(conforma_rig_process_sample(rig, &s, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("duration"), std::string::npos) << r.error_message;
  s = CSample(0);
  s.wheel_load_N[1] = 0.0;  // no contact on the right wheel: a status, not an error
  EXPECT_EQ(conforma_rig_process_sample(rig, &s, &r), CONFORMA_OK);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.kinematics_status, 3);
  EXPECT_GT(std::string(r.error_message).size(), 0u);
  EXPECT_EQ(conforma_rig_process_sample(nullptr, &s, &r), CONFORMA_ERROR_NULL);
  // a sample of 1e300 s removed 2e289 m and destroyed the rig's profiles (fuzzing, session 25): refused, and the
  // next sample is answered as on a fresh rig
  s = CSample(0);
  conforma_rig_result before;
  ASSERT_EQ(conforma_rig_process_sample(rig, &s, &before), CONFORMA_OK) << before.error_message;
  s.duration_s = 1e300;
  EXPECT_EQ(conforma_rig_process_sample(rig, &s, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("duration_s"), std::string::npos) << r.error_message;
  s = CSample(0);
  ASSERT_EQ(conforma_rig_process_sample(rig, &s, &r), CONFORMA_OK) << r.error_message;
  EXPECT_EQ(r.status, 0) << r.error_message;
  EXPECT_GT(r.contact[0].wheel_wear_max_depth_m, 0.0);
  s.lateral_velocity_m_s = 1e300;
  EXPECT_EQ(conforma_rig_process_sample(rig, &s, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("lateral velocity"), std::string::npos) << r.error_message;
  conforma_rig_destroy(rig);
  conforma_rig_destroy(nullptr);
}

}  // namespace
