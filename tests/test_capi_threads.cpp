// The C API (capi/conforma_c.h): several threads evaluating wheelset poses on ONE shared model handle give results
// bit-identical to a serial run; the track-frame totals agree with the contact-frame patch forces; errors come
// back as codes and texts, never as exceptions.
// test-links: pipeline  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/wheel_contact.hpp"
#include "capi_mbench_model.hpp"
#include "conforma_c.h"

namespace {

struct ModelHolder {
  conforma_model* model = nullptr;
  explicit ModelHolder(const char* model_name) {
    conforma_track_params track;
    conforma_contact_params contact;
    conforma_default_track_params(&track);
    conforma_default_contact_params(&contact);
    contact.model = model_name;
    char error[CONFORMA_ERROR_TEXT];
    EXPECT_EQ(conforma_model_create(&track, &contact, &model, error, sizeof error), CONFORMA_OK) << error;
  }
  ~ModelHolder() { conforma_model_destroy(model); }
};

conforma_wheelset_state State(int k) {
  conforma_wheelset_state s{};
  s.lateral_m = -4e-3 + 1e-3 * (k % 12);   // -4 .. 7 mm: tread, flange root and two-patch cases
  s.yaw_rad = 1e-3 * ((k % 5) - 2);
  s.forward_speed_m_s = 20.0;
  s.lateral_velocity_m_s = 0.01 * ((k % 3) - 1);
  s.yaw_rate_rad_s = 0.001 * ((k % 4) - 1.5);
  s.axle_angular_velocity_rad_s = 20.0 / 0.46 * (1.0 + 1e-3 * ((k % 7) - 3));
  return s;
}

conforma_evaluation_options Options() {
  conforma_evaluation_options o;
  conforma_default_evaluation_options(&o);
  o.rigid_equilibrium = 1;
  o.vertical_load_N[0] = 10e3;
  o.vertical_load_N[1] = 8e3;
  return o;
}

}  // namespace

TEST(CApiThreads, ConcurrentEvaluationsOnOneHandleEqualTheSerialRun) {
  ModelHolder h("conformal");
  ASSERT_NE(h.model, nullptr);
  const int cases = 48;
  const conforma_evaluation_options options = Options();
  std::vector<conforma_wheelset_result> serial(cases);
  for (int k = 0; k < cases; ++k) {
    conforma_wheelset_state s = State(k);
    ASSERT_EQ(conforma_evaluate(h.model, &s, &options, &serial[k]), CONFORMA_OK) << serial[k].error_message;
  }
  int two_patch = 0;
  for (const auto& r : serial) two_patch += r.wheel[0].patches_found > 1;
  EXPECT_GT(two_patch, 0);  // the set includes flange-root cases with two patches

  const int threads = 4;
  std::vector<conforma_wheelset_result> parallel(cases);
  std::vector<int> status(cases, -1);
  std::vector<std::thread> pool;
  for (int t = 0; t < threads; ++t)
    pool.emplace_back([&, t]() {
      // each thread walks the cases in its own order, so different poses overlap in time
      for (int i = 0; i < cases; ++i) {
        const int k = (i * 7 + t * 13) % cases;
        if (k % threads != t) continue;
        conforma_wheelset_state s = State(k);
        status[k] = conforma_evaluate(h.model, &s, &options, &parallel[k]);
      }
    });
  // also a thread evaluating every case again on the same handle, racing with the others
  std::vector<conforma_wheelset_result> extra(cases);
  pool.emplace_back([&]() {
    for (int k = cases - 1; k >= 0; --k) {
      conforma_wheelset_state s = State(k);
      conforma_evaluate(h.model, &s, &options, &extra[k]);
    }
  });
  for (auto& th : pool) th.join();
  for (int k = 0; k < cases; ++k) {
    ASSERT_EQ(status[k], CONFORMA_OK) << k;
    EXPECT_EQ(std::memcmp(&serial[k], &parallel[k], sizeof serial[k]), 0) << "case " << k;
    EXPECT_EQ(std::memcmp(&serial[k], &extra[k], sizeof serial[k]), 0) << "case " << k;
  }
}

// parallel_wheels = 1 (the wheels on two OpenMP threads) and 0 (the default: both on the calling thread) give the
// same result to the last bit, in load control and given approach; any other value is an input error.
TEST(CApiThreads, ParallelWheelsEqualTheSerialWheels) {
  ModelHolder h("conformal");
  ASSERT_NE(h.model, nullptr);
  conforma_evaluation_options parallel = Options(), serial = Options();
  EXPECT_EQ(serial.parallel_wheels, 0);
  parallel.parallel_wheels = 1;
  for (int mode : {CONFORMA_LOAD_CONTROL, CONFORMA_GIVEN_APPROACH}) {
    parallel.normal_mode = serial.normal_mode = mode;
    for (int k = 0; k < 12; ++k) {
      conforma_wheelset_state s = State(k);
      conforma_wheelset_result a, b;
      ASSERT_EQ(conforma_evaluate(h.model, &s, &parallel, &a), CONFORMA_OK) << a.error_message;
      ASSERT_EQ(conforma_evaluate(h.model, &s, &serial, &b), CONFORMA_OK) << b.error_message;
      EXPECT_EQ(std::memcmp(&a, &b, sizeof a), 0) << "mode " << mode << " case " << k;
    }
  }
  conforma_evaluation_options bad = Options();
  bad.parallel_wheels = 2;
  conforma_wheelset_state s = State(0);
  conforma_wheelset_result r;
  EXPECT_EQ(conforma_evaluate(h.model, &s, &bad, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("options.parallel_wheels"), std::string::npos) << r.error_message;
}

TEST(CApiThreads, TrackFrameTotalsAgreeWithThePatchForcesAndTheLoad) {
  ModelHolder h("conformal");
  ASSERT_NE(h.model, nullptr);
  const conforma_evaluation_options options = Options();
  for (int k = 0; k < 12; ++k) {
    conforma_wheelset_state s = State(k);
    conforma_wheelset_result r;
    ASSERT_EQ(conforma_evaluate(h.model, &s, &options, &r), CONFORMA_OK) << r.error_message;
    for (int w = 0; w < 2; ++w) {
      const conforma_wheel_result& wr = r.wheel[w];
      ASSERT_EQ(wr.status, CONFORMA_WHEEL_OK) << k << " " << w;
      ASSERT_EQ(wr.patch_count, wr.patches_found);
      double fz = 0, fx = 0, fn_check = 0;
      for (int j = 0; j < wr.patch_count; ++j) {
        const conforma_patch_result& p = wr.patch[j];
        fz += p.force_track_N[2];
        fx += p.force_track_N[0];
        EXPECT_NEAR(std::hypot(p.normal_track[1], p.normal_track[2]), 1.0, 1e-12);
        // the creep force along the track is the track-frame x force; the normal force is (nearly) the
        // projection of the resultant on the normal (the KP lateral pressure part is the rest)
        EXPECT_DOUBLE_EQ(p.force_track_N[0], p.longitudinal_force_N);
        const double along_normal = p.force_track_N[1] * p.normal_track[1] + p.force_track_N[2] * p.normal_track[2];
        EXPECT_NEAR(along_normal, p.normal_force_N, 0.02 * p.normal_force_N);
        // the spin moment vector lies along the normal; its magnitude is |Mz|
        const double m = std::sqrt(p.spin_moment_track_Nm[1] * p.spin_moment_track_Nm[1] +
                                   p.spin_moment_track_Nm[2] * p.spin_moment_track_Nm[2]);
        EXPECT_NEAR(m, std::fabs(p.spin_moment_Nm), 1e-9 * (1.0 + std::fabs(p.spin_moment_Nm)));
        fn_check += p.normal_force_N;
      }
      EXPECT_NEAR(wr.force_track_N[2], fz, 1e-9 * std::fabs(fz));
      EXPECT_NEAR(wr.force_track_N[0], fx, 1e-9 * (1.0 + std::fabs(fx)));
      EXPECT_GT(fn_check, 0.0);
      // the wheel centre sits about the taping-line radius above the rails, ~0.75 m out on its side
      EXPECT_NEAR(wr.wheel_centre_track_m[2], 0.46, 0.01);
      EXPECT_NEAR(wr.wheel_centre_track_m[1], (w == 0 ? 1.0 : -1.0) * 0.75 + s.lateral_m, 0.01);
    }
  }
}

TEST(CApiThreads, CentredWheelsetGivesMirrorForcesInTheTrackFrame) {
  ModelHolder h("conformal");
  conforma_wheelset_state s{};
  s.forward_speed_m_s = 10.0;
  s.axle_angular_velocity_rad_s = 10.0 / 0.46;
  const conforma_evaluation_options options = [] {
    conforma_evaluation_options o = Options();
    o.vertical_load_N[1] = 10e3;
    return o;
  }();
  conforma_wheelset_result r;
  ASSERT_EQ(conforma_evaluate(h.model, &s, &options, &r), CONFORMA_OK) << r.error_message;
  const auto& L = r.wheel[0];
  const auto& R = r.wheel[1];
  const double scale = L.force_track_N[2];
  EXPECT_NEAR(L.force_track_N[0], R.force_track_N[0], 1e-6 * scale);
  EXPECT_NEAR(L.force_track_N[1], -R.force_track_N[1], 1e-6 * scale);  // lateral forces cancel across the axle
  EXPECT_NEAR(L.force_track_N[2], R.force_track_N[2], 1e-6 * scale);
  // moments about the wheel centres: mirror images (axial vectors: x and z flip, y stays)
  EXPECT_NEAR(L.moment_track_Nm[0], -R.moment_track_Nm[0], 1e-6 * scale);
  EXPECT_NEAR(L.moment_track_Nm[1], R.moment_track_Nm[1], 1e-6 * scale);
  EXPECT_NEAR(L.moment_track_Nm[2], -R.moment_track_Nm[2], 1e-6 * scale);
  // the vertical load is carried; the contact points sit under the wheels
  EXPECT_NEAR(L.force_track_N[2], 10e3, 10e3 * 0.05);  // creep forces tilt the resultant slightly
  EXPECT_NEAR(L.patch[0].contact_point_track_m[1], -R.patch[0].contact_point_track_m[1], 1e-9);
}

TEST(CApiThreads, BadInputIsAnErrorCodeWithAMessageNamingTheParameter) {
  ModelHolder h("conformal");
  conforma_wheelset_state s = State(0);
  s.yaw_rad = std::nan("");
  conforma_wheelset_result r;
  EXPECT_EQ(conforma_evaluate(h.model, &s, nullptr, &r), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(r.error_message).find("state.yaw_rad"), std::string::npos) << r.error_message;
  char text[CONFORMA_ERROR_TEXT];
  conforma_model_last_error(h.model, text, sizeof text);
  EXPECT_STREQ(text, r.error_message);
  EXPECT_EQ(conforma_evaluate(h.model, nullptr, nullptr, &r), CONFORMA_ERROR_NULL);

  conforma_track_params track;
  conforma_contact_params contact;
  conforma_default_track_params(&track);
  conforma_default_contact_params(&contact);
  contact.model = "magic";
  conforma_model* m = nullptr;
  EXPECT_EQ(conforma_model_create(&track, &contact, &m, text, sizeof text), CONFORMA_ERROR_INPUT);
  EXPECT_EQ(m, nullptr);
  EXPECT_NE(std::string(text).find("magic"), std::string::npos) << text;
  contact.model = "hertz";
  track.rail_profile = "/nonexistent/rail.prr";
  EXPECT_EQ(conforma_model_create(&track, &contact, &m, text, sizeof text), CONFORMA_ERROR_INPUT);
  EXPECT_NE(std::string(text).find("/nonexistent/rail.prr"), std::string::npos) << text;
}

// The C API from profile FILES (Manchester wheel and rail) gives the forces of the C++ pipeline called
// directly with the same sequence (rigid equilibrium, then load control from there), to the last bit.

TEST(CApiThreads, ModelFromProfileFilesEqualsTheCppPipeline) {
  CApiMBenchModel mbench;
  ASSERT_NO_FATAL_FAILURE(mbench.Create());
  conforma_model* model = mbench.model;
  const conforma::WheelsetTrackGeometry& geometry = *mbench.geometry;
  conforma::WheelContactOptions options;
  options.model = conforma::ContactModel::Conformal;

  for (double y_mm : {0.0, 3.0, 6.0, 8.0}) {
    const conforma_wheelset_state s = CApiMBenchModel::State(y_mm);  // Manchester: yaw = 2.4 y mrad
    const conforma_evaluation_options o = CApiMBenchModel::RigidEquilibriumOptions();
    conforma_wheelset_result r;
    ASSERT_EQ(conforma_evaluate(model, &s, &o, &r), CONFORMA_OK) << r.error_message;

    const conforma::EquilibriumResult eq = geometry.SolveRigidEquilibrium(s.lateral_m, s.yaw_rad);
    const conforma::WheelsetVelocity v = CApiMBenchModel::Velocity();
    for (conforma::Side side : {conforma::Side::Left, conforma::Side::Right}) {
      const conforma::WheelContactReport ref = conforma::SolveWheelContact(geometry, side, eq.pose, v, options);
      const conforma_wheel_result& w = r.wheel[conforma::side_index(side)];
      ASSERT_EQ(w.patches_found, static_cast<int>(ref.patches.size())) << y_mm;
      for (int j = 0; j < w.patch_count; ++j) {
        EXPECT_EQ(w.patch[j].normal_force_N, ref.patches[j].fn_N) << y_mm;
        EXPECT_EQ(w.patch[j].longitudinal_force_N, ref.patches[j].fx_N) << y_mm;
        EXPECT_EQ(w.patch[j].lateral_force_N, ref.patches[j].fy_N) << y_mm;
        EXPECT_EQ(w.patch[j].spin_moment_Nm, ref.patches[j].mz_Nm) << y_mm;
        EXPECT_EQ(w.patch[j].pmax_Pa, ref.patches[j].pmax_Pa) << y_mm;
      }
      EXPECT_EQ(w.vertical_position_m, ref.pose.vertical_m);
    }
  }
}
