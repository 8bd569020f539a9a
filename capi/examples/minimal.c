/* Minimal use of the Conforma C API: S1002 wheels on 60E1 rails (1:40), conformal model, one wheelset pose with
 * a lateral shift of 6 mm and a yaw of 2 mrad, 10 kN per wheel; prints the forces on both wheels and exits with a
 * non-zero code on any error. Built and run by the tests (ctest -R capi_minimal). */
#include <stdio.h>

#include "conforma_c.h"

int main(void) {
  conforma_track_params track;
  conforma_contact_params contact;
  conforma_model* model = NULL;
  char error[CONFORMA_ERROR_TEXT];
  conforma_default_track_params(&track); /* wheel "S1002", rail "60E1" */
  conforma_default_contact_params(&contact);
  contact.model = "conformal";
  if (conforma_model_create(&track, &contact, &model, error, sizeof error) != CONFORMA_OK) {
    fprintf(stderr, "model: %s\n", error);
    return 1;
  }

  conforma_wheelset_state state = {0};
  state.lateral_m = 0.006;
  state.yaw_rad = 0.002;
  state.forward_speed_m_s = 20.0;
  state.axle_angular_velocity_rad_s = 20.0 / track.nominal_radius_m;
  conforma_evaluation_options options;
  conforma_default_evaluation_options(&options); /* load control, 10 kN per wheel */
  options.rigid_equilibrium = 1;                 /* start from the rigid contact of both wheels */

  conforma_wheelset_result result;
  if (conforma_evaluate(model, &state, &options, &result) != CONFORMA_OK) {
    fprintf(stderr, "evaluate: %s\n", result.error_message);
    conforma_model_destroy(model);
    return 1;
  }
  const char* names[2] = {"left", "right"};
  int ok = 1;
  for (int w = 0; w < 2; ++w) {
    const conforma_wheel_result* r = &result.wheel[w];
    printf("%s wheel: status %d, %d patch(es), F_track = (%.1f, %.1f, %.1f) N, M_centre = (%.1f, %.1f, %.1f) N m\n",
           names[w], r->status, r->patches_found, r->force_track_N[0], r->force_track_N[1], r->force_track_N[2],
           r->moment_track_Nm[0], r->moment_track_Nm[1], r->moment_track_Nm[2]);
    for (int j = 0; j < r->patch_count; ++j) {
      const conforma_patch_result* p = &r->patch[j];
      printf("  patch %d: Fn %.1f N, Fx %.1f N, Fs %.1f N, Mz %.3f N m, angle %.4f rad, area %.2f mm2, pmax %.1f MPa,"
             " point (%.4f, %.4f, %.4f) m\n",
             j, p->normal_force_N, p->longitudinal_force_N, p->lateral_force_N, p->spin_moment_Nm,
             p->contact_angle_rad, p->area_m2 * 1e6, p->pmax_Pa * 1e-6, p->contact_point_track_m[0],
             p->contact_point_track_m[1], p->contact_point_track_m[2]);
    }
    if (r->status != CONFORMA_WHEEL_OK || r->patches_found < 1) ok = 0;
  }
  /* a bad input is reported, not thrown: negative speed */
  state.forward_speed_m_s = -1.0;
  if (conforma_evaluate(model, &state, &options, &result) != CONFORMA_ERROR_INPUT) ok = 0;
  conforma_model_last_error(model, error, sizeof error);
  printf("bad input reported: %s\n", error);
  conforma_model_destroy(model);
  return ok ? 0 : 1;
}
