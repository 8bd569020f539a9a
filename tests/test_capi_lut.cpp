// The C API with a contact look-up table (conforma_model_create_with_lut): at a grid node the table's wheel forces
// are the solver's (pressure balance there; the C API's load control balances the total force, so the forces agree
// to the table's Q interpolation), and a wrong model, approach mode or a pose outside the table are input errors.
// test-links: lut  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "conforma/contact_lut.hpp"
#include "conforma/contact_lut_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma_c.h"

namespace {

// A small hertz table of the C API's default track (S1002 on 60E1 1:40), written to a temporary file.
std::string TableFile() {
  static const std::string path = [] {
    const conforma::WheelsetTrackGeometry g(conforma::MakeSymmetricTrack(
        conforma::MakeS1002(), conforma::MakeRail(conforma::RailSection::R60E1, 0.0), conforma::rail_inclination_1in40()));
    conforma::ContactLutBuildOptions b;
    for (int k = 0; k <= 16; ++k) b.grid.lateral_m.push_back(-4e-3 + 0.5e-3 * k);
    b.grid.yaw_rad = {-2e-3, 0.0, 2e-3};
    b.grid.load_N = {30e3, 50e3, 70e3};
    b.contact.model = conforma::ContactModel::Hertz;
    const std::string file = (std::filesystem::temp_directory_path() /
                              ("conforma_test_capi_lut_" + std::to_string(getpid()) + ".h5")).string();
    conforma::SaveContactLut(conforma::BuildContactLut(g, b), file);
    return file;
  }();
  static const struct Remove {  // the file goes with the process
    std::string file;
    ~Remove() { std::filesystem::remove(file); }
  } remove{path};
  return path;
}

struct Models {
  conforma_model *direct = nullptr, *lut = nullptr;
  ~Models() {
    conforma_model_destroy(direct);
    conforma_model_destroy(lut);
  }
};

conforma_wheelset_state State(double y_m) {
  conforma_wheelset_state s = {};
  s.lateral_m = y_m;
  s.forward_speed_m_s = 10.0;
  s.yaw_rate_rad_s = 10.0 / 2000.0;
  s.axle_angular_velocity_rad_s = 10.0 / 0.46 * (1.0 + 2e-4);
  return s;
}

// The hertz model of the C API's default track, solved (direct) and read from TableFile() (lut), and evaluation options
// of load control at 50 kN per wheel from the rigid equilibrium.
struct HertzModels : Models {
  conforma_contact_params contact;
  conforma_evaluation_options options;
  std::string error;
  bool Create() {
    conforma_track_params track;
    conforma_default_track_params(&track);
    conforma_default_contact_params(&contact);
    contact.model = "hertz";
    char text[CONFORMA_ERROR_TEXT];
    const std::string file = TableFile();
    const bool ok =
        conforma_model_create(&track, &contact, &direct, text, sizeof text) == CONFORMA_OK &&
        conforma_model_create_with_lut(&track, &contact, file.c_str(), &lut, text, sizeof text) == CONFORMA_OK;
    error = ok ? "" : text;
    conforma_default_evaluation_options(&options);
    options.rigid_equilibrium = 1;
    options.vertical_load_N[0] = options.vertical_load_N[1] = 50e3;
    return ok;
  }
};

}  // namespace

TEST(CApiLut, TableEvaluationMatchesTheSolverAtANode) {
  HertzModels m;
  ASSERT_TRUE(m.Create()) << m.error;
  conforma_evaluation_options o = m.options;
  for (double y : {-2e-3, 0.0, 1.5e-3}) {
    const conforma_wheelset_state s = State(y);
    conforma_wheelset_result a, b;
    ASSERT_EQ(conforma_evaluate(m.direct, &s, &o, &a), CONFORMA_OK) << a.error_message;
    ASSERT_EQ(conforma_evaluate(m.lut, &s, &o, &b), CONFORMA_OK) << b.error_message;
    for (int w = 0; w < 2; ++w) {
      ASSERT_EQ(a.wheel[w].patches_found, b.wheel[w].patches_found);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(b.wheel[w].force_track_N[i], a.wheel[w].force_track_N[i], 0.01 * 50e3);
      EXPECT_NEAR(b.wheel[w].patch[0].contact_point_track_m[1], a.wheel[w].patch[0].contact_point_track_m[1], 0.1e-3);
    }
  }
  // approach mode is not tabulated; a pose outside the table names the axis
  conforma_wheelset_result r;
  o.normal_mode = CONFORMA_GIVEN_APPROACH;
  const conforma_wheelset_state s = State(0.0);
  EXPECT_EQ(conforma_evaluate(m.lut, &s, &o, &r), CONFORMA_ERROR_INPUT);
  o.normal_mode = CONFORMA_LOAD_CONTROL;
  const conforma_wheelset_state far = State(6e-3);
  EXPECT_EQ(conforma_evaluate(m.lut, &far, &o, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("lateral shift y"), std::string::npos) << r.error_message;
}

TEST(CApiLut, WrongModelOrFileIsAnInputError) {
  conforma_track_params track;
  conforma_contact_params contact;
  conforma_default_track_params(&track);
  conforma_default_contact_params(&contact);  // conformal: not the table's model
  conforma_model* model = nullptr;
  char error[CONFORMA_ERROR_TEXT];
  const std::string file = TableFile();
  EXPECT_EQ(conforma_model_create_with_lut(&track, &contact, file.c_str(), &model, error, sizeof error),
            CONFORMA_ERROR_INPUT);
  EXPECT_EQ(model, nullptr);
  EXPECT_NE(std::string(error).find("contact model"), std::string::npos) << error;
  contact.model = "hertz";
  EXPECT_EQ(conforma_model_create_with_lut(&track, &contact, "/nonexistent/no_table.h5", &model, error, sizeof error),
            CONFORMA_ERROR_INPUT);
  EXPECT_EQ(conforma_model_create_with_lut(&track, &contact, nullptr, &model, error, sizeof error), CONFORMA_ERROR_NULL);
}

// table_creep_force = 1 (Polach on the patch ellipse): in full slip (lateral sliding of 5 % of V) both creep laws
// give the saturated force mu F_n on every patch; without a table the option is ignored (bit-identical); any value
// but 0 and 1 is an input error naming the option.
TEST(CApiLut, PolachCreepForceSaturatesAsFastsimInFullSlip) {
  HertzModels m;
  ASSERT_TRUE(m.Create()) << m.error;
  const conforma_contact_params& contact = m.contact;
  conforma_evaluation_options o = m.options;
  conforma_wheelset_state s = State(1e-3);
  s.lateral_velocity_m_s = 0.05 * s.forward_speed_m_s;
  conforma_wheelset_result fastsim, polach;
  ASSERT_EQ(conforma_evaluate(m.lut, &s, &o, &fastsim), CONFORMA_OK) << fastsim.error_message;
  o.table_creep_force = 1;
  ASSERT_EQ(conforma_evaluate(m.lut, &s, &o, &polach), CONFORMA_OK) << polach.error_message;
  for (int w = 0; w < 2; ++w) {
    ASSERT_EQ(fastsim.wheel[w].patches_found, polach.wheel[w].patches_found);
    for (int k = 0; k < fastsim.wheel[w].patches_found && k < CONFORMA_MAX_PATCHES; ++k) {
      const conforma_patch_result &f = fastsim.wheel[w].patch[k], &p = polach.wheel[w].patch[k];
      const double bound = contact.friction_coefficient * p.normal_force_N;
      EXPECT_NEAR(std::hypot(p.longitudinal_force_N, p.lateral_force_N), bound, 0.01 * bound) << "wheel " << w;
      EXPECT_NEAR(std::hypot(f.longitudinal_force_N, f.lateral_force_N),
                  contact.friction_coefficient * f.normal_force_N, 0.01 * bound) << "wheel " << w;
    }
  }
  // without a table the option is not used
  conforma_wheelset_result a, b;
  o.table_creep_force = 0;
  ASSERT_EQ(conforma_evaluate(m.direct, &s, &o, &a), CONFORMA_OK) << a.error_message;
  o.table_creep_force = 1;
  ASSERT_EQ(conforma_evaluate(m.direct, &s, &o, &b), CONFORMA_OK) << b.error_message;
  for (int w = 0; w < 2; ++w)
    for (int i = 0; i < 3; ++i) EXPECT_EQ(a.wheel[w].force_track_N[i], b.wheel[w].force_track_N[i]);
  o.table_creep_force = 2;
  conforma_wheelset_result r;
  EXPECT_EQ(conforma_evaluate(m.lut, &s, &o, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("table_creep_force"), std::string::npos) << r.error_message;
}
