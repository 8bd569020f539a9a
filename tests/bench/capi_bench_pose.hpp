// The wheelset state and pose of the C API benchmarks (bench_capi.cpp, bench_capi_lut.cpp): y given, yaw 1 mrad,
// 20 m/s rolling freely, placed as a multibody code would pass it (rigid contact of both wheels, then lowered).
#pragma once

#include "conforma_c.h"

namespace conforma_bench {

inline conforma_wheelset_state CApiBenchState(double lateral_m) {
  conforma_wheelset_state s{};
  s.lateral_m = lateral_m;
  s.yaw_rad = 1e-3;
  s.forward_speed_m_s = 20.0;
  s.axle_angular_velocity_rad_s = 20.0 / 0.46;
  return s;
}

// The state's vertical position and roll: the rigid contact of both wheels (`model` solved with the options `o` in
// given-approach mode at approach 0), then `below_m` lower.
inline void SetRigidPose(const conforma_model* model, const conforma_evaluation_options& o, double below_m,
                         conforma_wheelset_state* s) {
  conforma_evaluation_options rigid = o;
  rigid.rigid_equilibrium = 1;
  rigid.normal_mode = CONFORMA_GIVEN_APPROACH;
  rigid.approach_m = 0.0;
  conforma_wheelset_result r;
  conforma_evaluate(model, s, &rigid, &r);
  s->roll_rad = r.roll_rad;
  s->vertical_m = r.wheel[0].vertical_position_m - below_m;
}

}  // namespace conforma_bench
