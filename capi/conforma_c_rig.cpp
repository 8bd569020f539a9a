// C API of the roller rig (conforma_c.h, "roller rig"): a thin shell over ProcessRigSample (roller_rig_sample.hpp).
// Every entry point catches every exception.
#include <cmath>
#include <cstring>
#include <exception>
#include <limits>
#include <memory>
#include <new>
#include <string>

#include "conforma/contact_model.hpp"
#include "conforma/error.hpp"
#include "conforma/roller_rig_sample.hpp"
#include "c_status.hpp"
#include "conforma_c.h"
#include "interop.hpp"

struct conforma_rig {
  conforma::RollerRigSampleOptions options;
  conforma::RollerRigState state;
};

namespace {

using conforma::interop::CopyText;

conforma::RollerRigSampleOptions OptionsOf(const conforma_rig_params& p) {
  if (!p.wheel_profile || !p.roller_profile || !p.model)
    throw conforma::InputError("conforma_rig_create: wheel_profile, roller_profile or model is NULL");
  conforma::RollerRigSetup setup;
  setup.wheel_profile = p.wheel_profile;
  setup.roller_profile = p.roller_profile;
  setup.roller_radius_m = p.roller_radius_m;
  setup.wheel_radius_m = p.wheel_radius_m;
  setup.length_factor = p.length_factor;
  setup.wheel_conicity_rad = p.wheel_conicity_rad;
  setup.longitudinal_stiffness_N_per_m = p.longitudinal_stiffness_N_per_m;
  setup.spring_half_spacing_m = p.spring_half_spacing_m;
  setup.validate();
  conforma::RollerRigSampleOptions o = conforma::RollerRigSampleOptions::Defaults(setup);
  o.kinematics.contact.model = conforma::ParseContactModel(p.model);
  o.kinematics.contact.friction_coefficient = p.friction_coefficient;
  o.kinematics.contact.fastsim_elements = p.fastsim_elements;
  if (p.wear_law != 0 && p.wear_law != 1) throw conforma::InputError("conforma_rig_params.wear_law must be 0 or 1");
  o.wear_law = p.wear_law == 0 ? conforma::RollerRigWearLaw::Archard : conforma::RollerRigWearLaw::WearIndex;
  if (p.update_profiles != 0 && p.update_profiles != 1)
    throw conforma::InputError("conforma_rig_params.update_profiles must be 0 or 1");
  o.update_profiles = p.update_profiles == 1;
  o.filter_every_steps = p.filter_every_steps;
  o.filter_window_m = p.filter_window_m;
  o.profile_update_every_steps = p.profile_update_every_steps;
  if (p.eq2_wheelset_speed != 0 && p.eq2_wheelset_speed != 1)
    throw conforma::InputError("conforma_rig_params.eq2_wheelset_speed must be 0 or 1");
  o.kinematics.eq2_wheelset_speed = p.eq2_wheelset_speed == 1;
  o.strip_mean_elements = p.strip_mean_elements;
  o.validate();
  return o;
}

void FillRigResult(const conforma::RollerRigSampleResult& r, conforma_rig_result* out) {
  out->status = static_cast<int>(r.status);
  out->kinematics_status = static_cast<int>(r.kinematics.status);
  out->wheelset_speed_rad_s = r.kinematics.wheelset_speed_rad_s;
  out->eq2_wheelset_speed_rad_s = r.kinematics.eq2_wheelset_speed_rad_s;
  out->axle_moment_residual_Nm = r.kinematics.axle_moment_residual_Nm;
  out->yaw_deflection_rad = r.kinematics.yaw_deflection_rad;
  out->profiles_updated = r.profiles_updated ? 1 : 0;
  out->filtered = r.filtered ? 1 : 0;
  out->step = r.step;
  for (int k = 0; k < 2; ++k) {
    const conforma::RollerRigContactResult& c = r.kinematics.contact[k];
    conforma_rig_contact_result& o = out->contact[k];
    o.patch_count = static_cast<int>(c.report.patches.size());
    o.normal_force_N = c.fn_N;
    o.longitudinal_force_N = c.fx_N;
    o.lateral_force_N = c.fy_N;
    o.creepage_longitudinal = c.xi;
    o.creepage_lateral = c.eta;
    o.creepage_spin_per_m = c.phi_per_m;
    o.roller_rolling_radius_m = c.roller_rolling_radius_m;
    o.wheel_rolling_radius_m = c.wheel_rolling_radius_m;
    o.roller_surface_speed_m_s = c.roller_surface_speed_m_s;
    o.wheel_wear_max_depth_m = r.wheel_wear_max_depth_m[k];
    o.wheel_wear_area_m2 = r.wheel_wear_area_m2[k];
    o.roller_wear_max_depth_m = r.roller_wear_max_depth_m[k];
    o.roller_wear_area_m2 = r.roller_wear_area_m2[k];
    o.spring_force_N = r.kinematics.spring_force_N[k];
  }
  CopyText(r.message, out->error_message, sizeof out->error_message);
}

}  // namespace

extern "C" {

void conforma_default_rig_params(conforma_rig_params* p) {
  if (!p) return;
  const conforma::RollerRigSetup s;
  const conforma::RollerRigSampleOptions o = conforma::RollerRigSampleOptions::Defaults(s);
  p->wheel_profile = "conical";
  p->roller_profile = "uic60_1in20";
  p->roller_radius_m = s.roller_radius_m;
  p->wheel_radius_m = s.wheel_radius_m;
  p->length_factor = s.length_factor;
  p->wheel_conicity_rad = s.wheel_conicity_rad;
  p->longitudinal_stiffness_N_per_m = s.longitudinal_stiffness_N_per_m;
  p->spring_half_spacing_m = s.spring_half_spacing_m;
  p->model = "hertz";
  p->friction_coefficient = o.kinematics.contact.friction_coefficient;
  p->fastsim_elements = o.kinematics.contact.fastsim_elements;
  p->wear_law = 0;
  p->update_profiles = 1;
  p->filter_every_steps = o.filter_every_steps;
  p->filter_window_m = o.filter_window_m;
  p->profile_update_every_steps = o.profile_update_every_steps;
  p->eq2_wheelset_speed = 0;
  p->strip_mean_elements = o.strip_mean_elements;
}

conforma_status conforma_rig_create(const conforma_rig_params* params, conforma_rig** rig, char* error_text,
                                    size_t error_text_size) {
  CopyText("", error_text, error_text_size);
  if (!rig) {
    CopyText("conforma_rig_create: rig (output pointer) is NULL", error_text, error_text_size);
    return CONFORMA_ERROR_NULL;
  }
  *rig = nullptr;
  if (!params) {
    CopyText("conforma_rig_create: params is NULL", error_text, error_text_size);
    return CONFORMA_ERROR_NULL;
  }
  try {
    auto r = std::make_unique<conforma_rig>();
    r->options = OptionsOf(*params);
    r->state = conforma::MakeRollerRigState(r->options);
    *rig = r.release();
    return CONFORMA_OK;
  } catch (...) {
    return conforma::capi::ReportCurrentException(error_text, error_text_size);
  }
}

conforma_status conforma_rig_process_sample(conforma_rig* rig, const conforma_rig_sample* sample,
                                            conforma_rig_result* result) {
  if (!result) return CONFORMA_ERROR_NULL;
  std::memset(result, 0, sizeof *result);
  if (!rig || !sample) {
    CopyText("conforma_rig_process_sample: rig or sample is NULL", result->error_message,
                sizeof result->error_message);
    return CONFORMA_ERROR_NULL;
  }
  try {
    conforma::RollerRigSample s;
    s.time_s = sample->time_s;
    s.duration_s = sample->duration_s;
    s.lateral_m = sample->lateral_m;
    s.yaw_rad = sample->yaw_rad;
    s.lateral_velocity_m_s = sample->lateral_velocity_m_s;
    s.roller_speed_rad_s = {sample->roller_speed_rad_s[0], sample->roller_speed_rad_s[1]};
    s.wheel_load_N = {sample->wheel_load_N[0], sample->wheel_load_N[1]};
    s.wheelset_speed_rad_s = sample->wheelset_speed_rad_s > 0.0 ? sample->wheelset_speed_rad_s
                                                                : std::numeric_limits<double>::quiet_NaN();
    FillRigResult(conforma::ProcessRigSample(rig->options, &rig->state, s), result);
    return CONFORMA_OK;
  } catch (...) {
    std::memset(result, 0, sizeof *result);
    return conforma::capi::ReportCurrentException(result->error_message, sizeof result->error_message);
  }
}

void conforma_rig_destroy(conforma_rig* rig) { delete rig; }

}  // extern "C"
