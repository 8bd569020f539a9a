// The C API's statuses agree with the command line (issue 13, item 11): rigid_equilibrium is a flag (0 or 1, anything
// else is CONFORMA_ERROR_INPUT naming it), an absurd load is an input error as in `conforma contact` (not
// NO_CONTACT), and the wheel results carry the plausibility warnings.
// test-links: pipeline  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "conforma/wheel_contact.hpp"
#include "capi_mbench_model.hpp"
#include "conforma_c.h"

namespace {

// A model of `track` with `contact`, evaluated once at s with o (the model is destroyed before returning).
void EvaluateOnce(const conforma_track_params& track, const conforma_contact_params& contact,
                  const conforma_wheelset_state& s, const conforma_evaluation_options& o, conforma_wheelset_result* r) {
  conforma_model* model = nullptr;
  char error[CONFORMA_ERROR_TEXT];
  ASSERT_EQ(conforma_model_create(&track, &contact, &model, error, sizeof error), CONFORMA_OK) << error;
  struct Destroy { conforma_model* m; ~Destroy() { conforma_model_destroy(m); } } destroy{model};
  ASSERT_EQ(conforma_evaluate(model, &s, &o, r), CONFORMA_OK) << r->error_message;
}

TEST(CApiStatus, RigidEquilibriumMustBeZeroOrOne) {
  CApiMBenchModel mbench;
  ASSERT_NO_FATAL_FAILURE(mbench.Create());
  const conforma_wheelset_state s = CApiMBenchModel::State(3.0);
  conforma_evaluation_options o = CApiMBenchModel::RigidEquilibriumOptions();
  conforma_wheelset_result r;
  for (int flag : {0, 1}) {
    o.rigid_equilibrium = flag;
    EXPECT_NE(conforma_evaluate(mbench.model, &s, &o, &r), CONFORMA_ERROR_INPUT) << flag << ": " << r.error_message;
  }
  for (int flag : {5, -1, 2}) {
    o.rigid_equilibrium = flag;
    EXPECT_EQ(conforma_evaluate(mbench.model, &s, &o, &r), CONFORMA_ERROR_INPUT) << flag;
    EXPECT_NE(std::string(r.error_message).find("rigid_equilibrium"), std::string::npos) << r.error_message;
  }
}

TEST(CApiStatus, AbsurdLoadIsAnInputErrorAsInTheCommandLine) {
  // the default track (S1002 on 60E1): a 1e9 N wheel load is above kMaxWheelLoadN (10 MN), an input error naming
  // vertical_load_N, as `conforma contact --load-N 1e9` (exit 2); 1e7 N is still solved
  conforma_track_params track;
  conforma_contact_params contact;
  conforma_default_track_params(&track);
  conforma_default_contact_params(&contact);
  conforma_model* model = nullptr;
  char error[CONFORMA_ERROR_TEXT];
  ASSERT_EQ(conforma_model_create(&track, &contact, &model, error, sizeof error), CONFORMA_OK) << error;
  struct Destroy { conforma_model* m; ~Destroy() { conforma_model_destroy(m); } } destroy{model};
  const conforma_wheelset_state s = CApiMBenchModel::State(0.0);
  for (int rigid : {0, 1}) {
    conforma_evaluation_options o = CApiMBenchModel::RigidEquilibriumOptions();
    o.rigid_equilibrium = rigid;
    o.vertical_load_N[0] = o.vertical_load_N[1] = 1e9;
    conforma_wheelset_result r;
    EXPECT_EQ(conforma_evaluate(model, &s, &o, &r), CONFORMA_ERROR_INPUT) << "rigid_equilibrium " << rigid;
    EXPECT_NE(std::string(r.error_message).find("vertical_load_N"), std::string::npos) << r.error_message;
  }
}

// The plausibility warnings reach the C API as `conforma contact --json` lists them (issue 13: all warnings in every
// output): mu = 5 and a 1e7 N load (p_max above the material limit) are named; a plain evaluation has none.
TEST(CApiStatus, WarningsAsTheCommandLineListsThem) {
  conforma_track_params track;
  conforma_contact_params contact;
  conforma_default_track_params(&track);
  conforma_default_contact_params(&contact);
  contact.model = "hertz";
  const conforma_wheelset_state s = CApiMBenchModel::State(0.0);
  conforma_evaluation_options o = CApiMBenchModel::RigidEquilibriumOptions();
  for (double mu : {0.3, 5.0}) {
    contact.friction_coefficient = mu;
    conforma_wheelset_result r;
    ASSERT_NO_FATAL_FAILURE(EvaluateOnce(track, contact, s, o, &r));
    for (int k = 0; k < 2; ++k) {
      const std::string text = r.wheel[k].warnings;
      if (mu == 0.3) {
        EXPECT_EQ(r.wheel[k].warning_count, 0) << text;
        EXPECT_EQ(text, "");
      } else {
        EXPECT_EQ(r.wheel[k].warning_count, 1) << text;
        EXPECT_EQ(text.rfind("friction_coefficient:", 0), 0u) << text;
      }
    }
    if (mu == 0.3) {
      o.vertical_load_N[0] = o.vertical_load_N[1] = 1e7;
      ASSERT_NO_FATAL_FAILURE(EvaluateOnce(track, contact, s, o, &r));
      // Hertz carries it, at ~5.6 GPa: named as above the material limit
      EXPECT_NE(std::string(r.wheel[0].warnings).find("pressure_limit:"), std::string::npos) << r.wheel[0].warnings;
      o = CApiMBenchModel::RigidEquilibriumOptions();
    }
  }
  EXPECT_EQ(conforma_api_version(), 4);  // 4: conforma_evaluation_options.table_creep_force
}

// The exact model through the C API (issue 14): the same creep forces as the pipeline's SolveWheelContact, i.e. as
// `conforma contact --model exact`; "reference" is accepted for it.
TEST(CApiStatus, ExactModelAsThePipelineSolvesIt) {
  conforma_track_params track;
  conforma_contact_params contact;
  conforma_default_track_params(&track);
  conforma_default_contact_params(&contact);
  const conforma_wheelset_state s = CApiMBenchModel::State(0.0);
  const conforma_evaluation_options o = CApiMBenchModel::RigidEquilibriumOptions();
  double fx[2] = {0.0, 0.0};
  int k = 0;
  for (const char* name : {"exact", "reference"}) {
    contact.model = name;
    conforma_wheelset_result r;
    ASSERT_NO_FATAL_FAILURE(EvaluateOnce(track, contact, s, o, &r));
    ASSERT_GE(r.wheel[0].patch_count, 1);
    EXPECT_GT(r.wheel[0].patch[0].normal_force_N, 0.0);
    EXPECT_GT(r.wheel[0].patch[0].adhesion_area_m2, 0.0);  // a tangential solution, partial slip on the tread
    fx[k++] = r.wheel[0].patch[0].longitudinal_force_N;
  }
  EXPECT_EQ(fx[0], fx[1]);
  EXPECT_NE(fx[0], 0.0);
}

// Session 25's fuzzing of the C API: input that came back as NaN forces with CONFORMA_OK, as "no contact", or that
// was silently replaced by a default, is CONFORMA_ERROR_INPUT naming the field; the handle's last error names a NULL
// result.
TEST(CApiStatus, AbsurdStatesAndParametersAreInputErrors) {
  CApiMBenchModel mbench;
  ASSERT_NO_FATAL_FAILURE(mbench.Create());
  const conforma_evaluation_options o = CApiMBenchModel::RigidEquilibriumOptions();
  conforma_wheelset_result r;
  struct Case {
    const char* named;
    void (*change)(conforma_wheelset_state*);
  };
  const Case states[] = {
      {"yaw_rate_rad_s", [](conforma_wheelset_state* s) { s->yaw_rate_rad_s = 1e300; }},
      {"lateral_velocity_m_s", [](conforma_wheelset_state* s) { s->lateral_velocity_m_s = 1e9; }},
      {"axle_angular_velocity_rad_s", [](conforma_wheelset_state* s) { s->axle_angular_velocity_rad_s = 1e300; }},
      {"axle_angular_velocity_rad_s", [](conforma_wheelset_state* s) { s->forward_speed_m_s = 1e-300; }},
      {"state.yaw_rad", [](conforma_wheelset_state* s) { s->yaw_rad = 1e9; }},
  };
  for (const Case& c : states) {
    conforma_wheelset_state s = CApiMBenchModel::State(3.0);
    c.change(&s);
    EXPECT_EQ(conforma_evaluate(mbench.model, &s, &o, &r), CONFORMA_ERROR_INPUT) << c.named;
    EXPECT_NE(std::string(r.error_message).find(c.named), std::string::npos) << r.error_message;
  }
  // a push-down of 30 mm below rigid contact (came back as "no contact", zero forces)
  conforma_evaluation_options deep = o;
  deep.normal_mode = CONFORMA_GIVEN_APPROACH;
  deep.approach_m = 0.03;
  const conforma_wheelset_state s = CApiMBenchModel::State(3.0);
  EXPECT_EQ(conforma_evaluate(mbench.model, &s, &deep, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("approach_m"), std::string::npos) << r.error_message;
  EXPECT_EQ(conforma_evaluate(mbench.model, &s, &o, nullptr), CONFORMA_ERROR_NULL);
  char last[CONFORMA_ERROR_TEXT];
  conforma_model_last_error(mbench.model, last, sizeof last);
  EXPECT_NE(std::string(last).find("result is NULL"), std::string::npos) << last;

  struct Params {
    const char* named;
    void (*change)(conforma_track_params*, conforma_contact_params*);
  };
  const Params params[] = {
      {"rail_inclination_rad", [](conforma_track_params* t, conforma_contact_params*) { t->rail_inclination_rad = NAN; }},
      {"gauge_m", [](conforma_track_params* t, conforma_contact_params*) { t->gauge_m = 1435.0; }},
      {"kp_strips", [](conforma_track_params*, conforma_contact_params* c) { c->kp_strips = 1 << 30; }},
      {"shear_modulus_Pa", [](conforma_track_params*, conforma_contact_params* c) { c->shear_modulus_Pa = 100.0; }},
      {"neither", [](conforma_track_params* t, conforma_contact_params*) {
         static const std::string long_name(4999, 'a');
         t->wheel_profile = long_name.c_str();
       }},
  };
  for (const Params& c : params) {
    conforma_track_params track;
    conforma_contact_params contact;
    conforma_default_track_params(&track);
    conforma_default_contact_params(&contact);
    c.change(&track, &contact);
    conforma_model* model = nullptr;
    char error[CONFORMA_ERROR_TEXT];
    EXPECT_EQ(conforma_model_create(&track, &contact, &model, error, sizeof error), CONFORMA_ERROR_INPUT) << c.named;
    EXPECT_NE(std::string(error).find(c.named), std::string::npos) << error;
    conforma_model_destroy(model);
  }
}

}  // namespace
