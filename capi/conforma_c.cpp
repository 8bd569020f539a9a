// C API implementation (conforma_c.h): a thin shell over the C++ pipeline (wheel_contact.hpp). Every entry point
// catches every exception; the handle is immutable after creation except for its mutex-guarded last-error text.
#include "conforma_c.h"
#include "c_patch_fields.hpp"
#include "c_status.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <string>

#include <Eigen/Geometry>

#include "conforma/contact_lut.hpp"
#include "conforma/contact_lut_io.hpp"
#include "conforma/error.hpp"
#include "interop.hpp"

struct conforma_model {
  std::unique_ptr<conforma::WheelsetTrackGeometry> geometry;
  conforma::WheelContactOptions contact;  // model, material, friction, discretisation (load set per call)
  std::shared_ptr<const conforma::ContactLut> lut;  // conforma_model_create_with_lut: contacts from this table
  mutable std::mutex error_mutex;
  mutable std::string last_error;
};

namespace {

using conforma::Side;

using conforma::interop::CopyText;

void Store(double out[3], const Eigen::Vector3d& v) {
  for (int i = 0; i < 3; ++i) out[i] = v[i];
}

void FillWheel(const conforma::WheelsetTrackGeometry& geometry, Side side, const conforma::WheelContactReport& r,
               conforma_wheel_result* w) {
  using conforma::WheelContactStatus;
  w->status = r.status == WheelContactStatus::Ok          ? CONFORMA_WHEEL_OK
              : r.status == WheelContactStatus::NoContact ? CONFORMA_WHEEL_NO_CONTACT
                                                          : CONFORMA_WHEEL_NOT_CONVERGED;
  w->patches_found = static_cast<int>(r.patches.size());
  w->vertical_position_m = r.pose.vertical_m;
  w->load_iterations = r.load_iterations;
  w->warning_count = static_cast<int>(r.warnings.size());
  std::string warnings;
  for (const std::string& text : r.warnings) warnings += (warnings.empty() ? "" : "\n") + text;
  CopyText(warnings, w->warnings, sizeof w->warnings);
  const Eigen::Vector3d centre = conforma::interop::WheelCentre(geometry, side, r.pose);
  Store(w->wheel_centre_track_m, centre);
  Eigen::Vector3d force = Eigen::Vector3d::Zero(), moment = Eigen::Vector3d::Zero();
  for (size_t j = 0; j < r.patches.size(); ++j) {
    const conforma::PatchReport& p = r.patches[j];
    const conforma::interop::TrackFramePatch t = conforma::interop::ToTrackFrame(geometry, side, p);
    force += t.force_N;
    moment += (t.point_m - centre).cross(t.force_N) + t.spin_moment_Nm;
    if (j >= static_cast<size_t>(CONFORMA_MAX_PATCHES)) continue;
    conforma_patch_result& o = w->patch[w->patch_count++];
    conforma::capi::FillCPatchScalars(p, &o);  // the one field table (c_patch_fields.hpp)
    Store(o.force_track_N, t.force_N);
    Store(o.spin_moment_track_Nm, t.spin_moment_Nm);
    Store(o.contact_point_track_m, t.point_m);
    Store(o.normal_track, t.normal);
  }
  Store(w->force_track_N, force);
  Store(w->moment_track_Nm, moment);
}

void Evaluate(const conforma_model& model, const conforma_wheelset_state& s, const conforma_evaluation_options& e,
              conforma_wheelset_result* result) {
  using conforma::InputError;
  conforma::require_finite(s.lateral_m, "state.lateral_m");
  conforma::require_finite(s.vertical_m, "state.vertical_m");
  conforma::require_finite(s.roll_rad, "state.roll_rad");
  conforma::RequireWheelsetYaw(s.yaw_rad, "state.yaw_rad");
  const conforma::WheelsetVelocity velocity{s.forward_speed_m_s, s.lateral_velocity_m_s, s.yaw_rate_rad_s,
                                            s.axle_angular_velocity_rad_s};
  conforma::RequireRollingVelocity(velocity, model.geometry->setup().nominal_radius_m[0], "state");
  if (e.normal_mode != CONFORMA_LOAD_CONTROL && e.normal_mode != CONFORMA_GIVEN_APPROACH)
    throw InputError("options.normal_mode must be CONFORMA_LOAD_CONTROL (0) or CONFORMA_GIVEN_APPROACH (1), not " +
                     std::to_string(e.normal_mode));
  if (e.rigid_equilibrium != 0 && e.rigid_equilibrium != 1)
    throw InputError("options.rigid_equilibrium must be 0 (the state's vertical_m and roll_rad) or 1 (rigid contact "
                     "of both wheels), not " + std::to_string(e.rigid_equilibrium));
  if (e.parallel_wheels != 0 && e.parallel_wheels != 1)
    throw InputError("options.parallel_wheels must be 0 (both wheels on the calling thread) or 1 (the two wheels on "
                     "two threads), not " + std::to_string(e.parallel_wheels));
  if (e.table_creep_force != 0 && e.table_creep_force != 1)
    throw InputError("options.table_creep_force must be 0 (FASTSIM) or 1 (Polach), not " +
                     std::to_string(e.table_creep_force));
  const bool load_control = e.normal_mode == CONFORMA_LOAD_CONTROL;
  if (load_control) {
    conforma::require_non_negative(e.vertical_load_N[0], "options.vertical_load_N[0] (left)");
    conforma::require_non_negative(e.vertical_load_N[1], "options.vertical_load_N[1] (right)");
  }
  conforma::WheelsetPose pose{s.lateral_m, s.vertical_m, s.roll_rad, s.yaw_rad};
  if (e.rigid_equilibrium) {
    conforma::RequireApproach(e.approach_m, "options.approach_m");
    const conforma::EquilibriumResult eq = model.geometry->SolveRigidEquilibrium(s.lateral_m, s.yaw_rad, pose);
    if (eq.status == conforma::EquilibriumStatus::NoContact) {
      char text[200];
      std::snprintf(text, sizeof text, "no rigid contact at state.lateral_m = %g m, state.yaw_rad = %g rad: the wheels "
                    "do not reach the rails", s.lateral_m, s.yaw_rad);
      throw InputError(text);
    }
    pose = eq.pose;
    if (!load_control) pose.vertical_m -= e.approach_m;
  }
  result->roll_rad = pose.roll_rad;
  const conforma::WheelContactOptions& contact = model.contact;
  conforma::LutEvaluationOptions table;  // (with a table only)
  table.creep_force = e.table_creep_force == 1 ? conforma::LutCreepForce::Polach : conforma::LutCreepForce::Fastsim;
  auto solve = [&](Side side) {
    conforma::WheelContactOptions options = contact;  // per-call copy: the handle stays untouched
    options.load_tolerance = e.load_tolerance;
    options.vertical_load_N = load_control ? e.vertical_load_N[conforma::side_index(side)] : -1.0;
    return model.lut
               ? conforma::EvaluateContactLut(*model.lut, *model.geometry, side, pose, velocity, options, nullptr, table)
               : SolveWheelContact(*model.geometry, side, pose, velocity, options);
  };
  // The two wheels are independent (each its own candidates, load control and tangential problem, on the immutable
  // handle): with parallel_wheels they are two sections of an OpenMP region of two threads, the same arithmetic
  // either way. OpenMP keeps the second thread between calls (std::async started one per call: ~100 us of the
  // 300 us); inside a caller's own parallel region (nested parallelism off) or with OMP_NUM_THREADS=1 both run here.
  // An exception cannot leave the region: each section keeps its own, the left wheel's rethrown first (as in
  // the serial order).
  conforma::WheelContactReport left, right;
  if (e.parallel_wheels == 1 && !model.lut) {  // (a table look-up is far cheaper than waking a thread)
    std::exception_ptr failure[2];
#pragma omp parallel sections num_threads(2)
    {
#pragma omp section
      {
        try {
          left = solve(Side::Left);
        } catch (...) {
          failure[0] = std::current_exception();
        }
      }
#pragma omp section
      {
        try {
          right = solve(Side::Right);
        } catch (...) {
          failure[1] = std::current_exception();
        }
      }
    }
    for (const std::exception_ptr& f : failure)
      if (f) std::rethrow_exception(f);
  } else {
    left = solve(Side::Left);
    right = solve(Side::Right);
  }
  FillWheel(*model.geometry, Side::Left, left, &result->wheel[conforma::side_index(Side::Left)]);
  FillWheel(*model.geometry, Side::Right, right, &result->wheel[conforma::side_index(Side::Right)]);
}

}  // namespace

extern "C" {

void conforma_default_track_params(conforma_track_params* t) {
  if (!t) return;
  t->wheel_profile = "S1002";
  t->rail_profile = "60E1";
  t->rail_inclination_rad = -1.0;
  t->gauge_m = 1.435;
  t->gauge_height_m = 0.014;
  t->flange_back_distance_m = 1.360;
  t->flange_back_position_m = -0.070;
  t->nominal_radius_m = 0.46;
}

void conforma_default_contact_params(conforma_contact_params* c) {
  if (!c) return;
  const conforma::WheelContactOptions d;
  c->model = "conformal";
  c->shear_modulus_Pa = d.material.shear_modulus_Pa;
  c->poisson_ratio = d.material.poisson_ratio;
  c->friction_coefficient = d.friction_coefficient;
  c->fastsim_elements = d.fastsim_elements;
  c->kp_strips = d.kp_strips;
}

void conforma_default_evaluation_options(conforma_evaluation_options* o) {
  if (!o) return;
  o->normal_mode = CONFORMA_LOAD_CONTROL;
  o->vertical_load_N[0] = o->vertical_load_N[1] = 10e3;
  o->rigid_equilibrium = 0;
  o->approach_m = 0.05e-3;
  o->load_tolerance = conforma::WheelContactOptions().load_tolerance;
  o->parallel_wheels = 0;
  o->table_creep_force = 0;
}

conforma_status conforma_model_create(const conforma_track_params* track, const conforma_contact_params* contact,
                                      conforma_model** model, char* error_text, size_t error_text_size) {
  CopyText("", error_text, error_text_size);
  if (!model) {
    CopyText("conforma_model_create: model (output pointer) is NULL", error_text, error_text_size);
    return CONFORMA_ERROR_NULL;
  }
  *model = nullptr;
  if (!track || !contact || !track->wheel_profile || !track->rail_profile || !contact->model) {
    CopyText("conforma_model_create: track, contact, a profile name or the model name is NULL", error_text,
             error_text_size);
    return CONFORMA_ERROR_NULL;
  }
  try {
    conforma::interop::TrackSpec spec;
    spec.wheel = track->wheel_profile;
    spec.rail = track->rail_profile;
    if (std::isnan(track->rail_inclination_rad))  // (NaN was taken as "the default")
      throw conforma::InputError("track.rail_inclination_rad is NaN (negative: the default)");
    if (track->rail_inclination_rad >= 0.0) spec.inclination_rad = track->rail_inclination_rad;
    spec.gauge_m = track->gauge_m;
    spec.gauge_height_m = track->gauge_height_m;
    spec.flange_back_distance_m = track->flange_back_distance_m;
    spec.flange_back_position_m = track->flange_back_position_m;
    spec.nominal_radius_m = track->nominal_radius_m;
    auto m = std::make_unique<conforma_model>();
    m->contact.model = conforma::ParseContactModel(contact->model);
    m->contact.material.shear_modulus_Pa = contact->shear_modulus_Pa;
    m->contact.material.poisson_ratio = contact->poisson_ratio;
    m->contact.friction_coefficient = contact->friction_coefficient;
    m->contact.fastsim_elements = contact->fastsim_elements;
    m->contact.kp_strips = contact->kp_strips;
    m->contact.validate();
    m->geometry = conforma::interop::MakeTrackGeometry(spec);
    *model = m.release();
    return CONFORMA_OK;
  } catch (...) {
    return conforma::capi::ReportCurrentException(error_text, error_text_size);
  }
}

conforma_status conforma_model_create_with_lut(const conforma_track_params* track,
                                               const conforma_contact_params* contact, const char* lut_path,
                                               conforma_model** model, char* error_text, size_t error_text_size) {
  if (!lut_path) {
    if (model) *model = nullptr;
    CopyText("conforma_model_create_with_lut: lut_path is NULL", error_text, error_text_size);
    return CONFORMA_ERROR_NULL;
  }
  const conforma_status status = conforma_model_create(track, contact, model, error_text, error_text_size);
  if (status != CONFORMA_OK) return status;
  try {
    auto lut = std::make_shared<const conforma::ContactLut>(conforma::LoadContactLut(lut_path));
    conforma::CheckContactLutGeometry(*lut, *(*model)->geometry);
    // the table's elastic-flange rule (not a parameter of conforma_contact_params); the model, material and track
    // must be the table's (checked here once, and by every evaluation)
    (*model)->contact.max_touching_contact_angle_rad = lut->header.max_touching_contact_angle_rad;
    conforma::WheelContactOptions probe = (*model)->contact;
    probe.vertical_load_N = 0.0;  // an unloaded wheel: only the compatibility checks run
    conforma::EvaluateContactLut(*lut, *(*model)->geometry, Side::Left, conforma::WheelsetPose{},
                                 conforma::WheelsetVelocity{1.0, 0.0, 0.0, 0.0}, probe);
    (*model)->lut = std::move(lut);
    return CONFORMA_OK;
  } catch (...) {
    conforma_model_destroy(*model);
    *model = nullptr;
    return conforma::capi::ReportCurrentException(error_text, error_text_size);
  }
}

void conforma_model_destroy(conforma_model* model) { delete model; }

conforma_status conforma_evaluate(const conforma_model* model, const conforma_wheelset_state* state,
                                  const conforma_evaluation_options* options, conforma_wheelset_result* result) {
  if (!result) {
    if (model) {  // (the handle's last error said nothing, or the previous call's: fuzzing, session 25)
      try {
        std::lock_guard<std::mutex> lock(model->error_mutex);
        model->last_error = "conforma_evaluate: result is NULL";
      } catch (...) {
      }
    }
    return CONFORMA_ERROR_NULL;
  }
  std::memset(result, 0, sizeof *result);
  if (!model || !state) {
    CopyText("conforma_evaluate: model or state is NULL", result->error_message, sizeof result->error_message);
    return CONFORMA_ERROR_NULL;
  }
  conforma_evaluation_options defaults;
  conforma_default_evaluation_options(&defaults);
  conforma_status status = CONFORMA_OK;
  std::string message;
  try {
    Evaluate(*model, *state, options ? *options : defaults, result);
  } catch (...) {
    status = conforma::capi::CurrentExceptionStatus(&message);
  }
  if (status != CONFORMA_OK) {
    std::memset(result, 0, sizeof *result);
    CopyText(message, result->error_message, sizeof result->error_message);
    try {
      std::lock_guard<std::mutex> lock(model->error_mutex);
      model->last_error = message;
    } catch (...) {
    }
  }
  return status;
}

size_t conforma_model_last_error(const conforma_model* model, char* buffer, size_t buffer_size) {
  if (!model) {
    CopyText("", buffer, buffer_size);
    return 0;
  }
  try {
    std::lock_guard<std::mutex> lock(model->error_mutex);
    CopyText(model->last_error, buffer, buffer_size);
    return model->last_error.size();
  } catch (...) {
    CopyText("", buffer, buffer_size);
    return 0;
  }
}

int conforma_api_version(void) { return CONFORMA_C_API_VERSION; }

}  // extern "C"
