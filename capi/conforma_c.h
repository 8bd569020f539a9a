/* Conforma C API: one wheelset contact evaluation per call, for multibody co-simulation.
 *
 * A multibody code (Simpack, GENSYS, Universal Mechanism, VAMPIRE, an own integrator) creates ONE model handle
 * per wheelset/track combination at start-up and then, at every time step, calls conforma_evaluate() with the
 * wheelset pose and velocities. The call returns, per wheel, the forces and moments on the wheel and the
 * contact state (patches, contact points, areas, maximum pressure). Everything crosses the boundary as plain C
 * structs and arrays; no C++ exception ever leaves the library; every function returns a conforma_status.
 *
 * UNITS: SI throughout (m, rad, N, N m, Pa, s). Profile FILES are in mm as the field writes them.
 *
 * FRAMES (as include/conforma/geometry.hpp; the C++ side is tested against the Manchester reference):
 *   Track frame, right-handed: x along the track in the rolling direction, y lateral positive towards the LEFT
 *   rail, z up; the top of the rails is at z = 0.
 *   Wheelset pose: lateral shift y (+ towards the left rail), vertical position z of the axle centre above
 *   (rail-top level + mean nominal radius), roll (about +x, + raises the LEFT wheel), yaw (about +z, + turns
 *   the heading towards the left rail).
 *   Wheel index 0 = LEFT, 1 = RIGHT (CONFORMA_LEFT, CONFORMA_RIGHT).
 *   Per patch the forces are also given in the patch's contact frame (Kalker / CONTACT convention, the right
 *   wheel reported as the mirror image of a left wheel): longitudinal along the track, lateral along the rail
 *   profile towards the FIELD side, normal along the outward rail normal; contact angle + towards the gauge side.
 *   All forces and moments are those exerted BY THE RAIL ON THE WHEEL.
 *
 * NORMAL PROBLEM: either load control (each wheel pushed down until the vertical components of its patch
 * forces carry the given vertical load; the pose's vertical_m and roll_rad are then only the starting point)
 * or given approach (the pose is used as it stands: the multibody code owns the vertical dynamics). Optionally
 * (rigid_equilibrium = 1) the vertical position and roll are first set to the rigid contact of both wheels at
 * the given y and yaw, exactly as the command line `conforma contact` does; in approach mode the wheelset is
 * then lowered by approach_m below that rigid position.
 *
 * COST (tests/bench/bench_capi.cpp, conforma_bench --benchmark_filter=CApiWheelset, both wheels, CPU time): the
 * conformal model takes about 0.2 ms per wheelset pose in approach mode and about 0.3-0.35 ms in load control (three
 * Kik-Piotrowski and FASTSIM solves per wheel); the Hertz model about 0.1 ms in load control. parallel_wheels = 1
 * solves the two wheels as two sections of an OpenMP region of two threads (OpenMP keeps the second thread between
 * calls): where a second core is free the wall time drops towards the slower wheel's, at some CPU more (the waiting
 * thread spins a while after each call; OMP_WAIT_POLICY=passive stops that). Measured on 2 idle cores, load control:
 * 178 / 159 us wall against 313 / 255 us on one thread (tread y = 3 mm / flange y = 7 mm; a thread started per
 * call, as before, gave 326 / 239 us). With a table of the conformal model (conforma_model_create_with_lut,
 * tests/bench/bench_capi_lut.cpp) load control with the creep forces takes about 0.07-0.09 ms with FASTSIM and
 * 5 us with table_creep_force = 1 (Polach), against the direct solve's 0.25-0.3 ms.
 *
 * THREAD SAFETY: a model handle is immutable after conforma_model_create(). conforma_evaluate() on the SAME
 * handle may be called from any number of threads at once; each call uses only its own stack/heap workspace.
 * The only shared mutable datum is the handle's last-error text, which is guarded by a mutex and copied out by
 * conforma_model_last_error(); each call's own error text is also returned in its result struct.
 *
 * Minimal use (capi/examples/minimal.c is built and run by the tests):
 *     conforma_track_params track; conforma_contact_params contact; conforma_model* model;
 *     char err[256];
 *     conforma_default_track_params(&track);            // S1002 on 60E1 at 1:40, standard gauge
 *     conforma_default_contact_params(&contact);        // conformal model, G = 82 GPa, nu = 0.28, mu = 0.3
 *     if (conforma_model_create(&track, &contact, &model, err, sizeof err) != CONFORMA_OK) { puts(err); ... }
 *     conforma_wheelset_state state = {0};  state.lateral_m = 0.003;  state.forward_speed_m_s = 20.0;
 *     state.axle_angular_velocity_rad_s = 20.0 / 0.46;
 *     conforma_evaluation_options eval;  conforma_default_evaluation_options(&eval);
 *     conforma_wheelset_result result;
 *     if (conforma_evaluate(model, &state, &eval, &result) == CONFORMA_OK) ... result.wheel[0].force_track_N ...
 *     conforma_model_destroy(model);
 */
#ifndef CONFORMA_C_H
#define CONFORMA_C_H

#include <stddef.h>

#if defined(_WIN32)
#define CONFORMA_C_EXPORT __declspec(dllexport)
#elif defined(__GNUC__)
#define CONFORMA_C_EXPORT __attribute__((visibility("default")))
#else
#define CONFORMA_C_EXPORT
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* Version of this interface; bumped on any incompatible change of a struct or function below. */
#define CONFORMA_C_API_VERSION 4  /* 2: conforma_wheel_result gained warning_count and warnings;
                                     3: conforma_evaluation_options gained parallel_wheels;
                                     4: conforma_evaluation_options gained table_creep_force */
#define CONFORMA_MAX_PATCHES 4    /* patches stored per wheel (more are counted in patches_found) */
#define CONFORMA_ERROR_TEXT 256   /* size of the error texts, including the terminating 0 */
#define CONFORMA_WARNING_TEXT 1024 /* size of a wheel's warnings text, including the terminating 0 */
#define CONFORMA_LEFT 0
#define CONFORMA_RIGHT 1

typedef enum conforma_status {
  CONFORMA_OK = 0,              /* success: the outputs are filled */
  CONFORMA_ERROR_INPUT = 1,     /* bad input: the error text names the parameter, file and line */
  CONFORMA_ERROR_NULL = 2,      /* a required pointer argument was NULL */
  CONFORMA_ERROR_INTERNAL = 3   /* unexpected failure inside the library (out of memory, ...) */
} conforma_status;

typedef enum conforma_wheel_status {
  CONFORMA_WHEEL_OK = 0,             /* contact found (and, in load control, the load reached) */
  CONFORMA_WHEEL_NO_CONTACT = 1,     /* no interpenetration (wheel lifted or load 0): all forces 0 */
  CONFORMA_WHEEL_NOT_CONVERGED = 2   /* load control did not reach the load within 10x its tolerance (patches of the
                                        last iterate reported), or found no bracket (no patches) */
} conforma_wheel_status;

typedef enum conforma_normal_mode {
  CONFORMA_LOAD_CONTROL = 0,   /* vertical load per wheel given (vertical_load_N) */
  CONFORMA_GIVEN_APPROACH = 1  /* pose used as given (multibody coupling) */
} conforma_normal_mode;

/* Track and profiles. Profile strings: a built-in name ("S1002" wheel; "60E1", "54E1", "50E6", "50E4" rail) or a
 * file path (.prw/.prr Simpack, .whl/.ban MiniProf, .txt/.csv/.dat two columns y z in mm). Both wheels share the
 * wheel profile, both rails the rail profile. */
typedef struct conforma_track_params {
  const char* wheel_profile;       /* default "S1002" */
  const char* rail_profile;        /* default "60E1" */
  double rail_inclination_rad;     /* < 0: default (1:40 for built-in rails, 0 for files, which are canted); NaN is
                                      CONFORMA_ERROR_INPUT */
  double gauge_m;                  /* 1.435, measured gauge_height_m below the rail top; 0.1 ... 1.8 m */
  double gauge_height_m;           /* 0.014 */
  double flange_back_distance_m;   /* 1.360; 0.1 ... 1.8 m */
  double flange_back_position_m;   /* -0.070: wheel-profile y of the flange back */
  double nominal_radius_m;         /* 0.46: taping-line radius of both wheels; 0.02 ... 2 m */
} conforma_track_params;

/* Contact model and material. */
typedef struct conforma_contact_params {
  const char* model;               /* "hertz", "kp", "kpec", "conformal" (default), "auto", "exact" (slow: BEM +
                                      Kalker's exact tangential theory; "reference" is accepted for it) */
  double shear_modulus_Pa;         /* 82e9: G of both bodies, 1e8 ... 1e12 Pa */
  double poisson_ratio;            /* 0.28: nu of both bodies */
  double friction_coefficient;     /* 0.3: mu, >= 0 */
  int fastsim_elements;            /* 30: FASTSIM elements per strip, 2 ... 10000 */
  int kp_strips;                   /* 31: strips across the contact (KP models), 3 ... 100000 */
} conforma_contact_params;

/* Wheelset pose and velocities in the track frame. */
typedef struct conforma_wheelset_state {
  double lateral_m, vertical_m, roll_rad, yaw_rad;  /* the wheelset pose (FRAMES above): m, m, rad, rad; finite,
                                                       |yaw_rad| <= 0.2 */
  double forward_speed_m_s;            /* V > 0 along +x (CONFORMA_ERROR_INPUT otherwise) */
  double lateral_velocity_m_s;         /* dy/dt */
  double yaw_rate_rad_s;               /* d(yaw)/dt */
  double axle_angular_velocity_rad_s;  /* about the axle, + rolling forwards (V / r0 for pure rolling) */
  /* the rigid creepages these imply, |dy/dt / V|, |omega r0 / V - 1| and |yaw rate / V| (1/m), must be within 1e3
     (CONFORMA_ERROR_INPUT beyond: the creep forces would overflow to NaN) */
} conforma_wheelset_state;

typedef struct conforma_evaluation_options {
  int normal_mode;                 /* conforma_normal_mode; default CONFORMA_LOAD_CONTROL */
  double vertical_load_N[2];       /* load control: per wheel [left, right], N, >= 0 (0: no contact); default 10e3 */
  int rigid_equilibrium;           /* 1: vertical_m and roll_rad from the rigid contact of both wheels at the given
                                      lateral_m and yaw_rad (as `conforma contact`; the state's vertical_m and
                                      roll_rad are the starting guess); 0 (default): as given; any other
                                      value is CONFORMA_ERROR_INPUT */
  double approach_m;               /* rigid_equilibrium with CONFORMA_GIVEN_APPROACH: push-down below rigid contact,
                                      default 5e-5 m, |.| <= 0.01 m */
  double load_tolerance;           /* relative tolerance of load control, > 0; default 1e-6 */
  int parallel_wheels;             /* 0 (default): both wheels on the calling thread; 1: the two wheels on two
                                      threads of an OpenMP region (the wheels are independent: results bit-identical
                                      to 0; pays only with a free core, see COST; inside the caller's own parallel
                                      region, nested parallelism off, both run on the calling thread); any other
                                      value is CONFORMA_ERROR_INPUT */
  int table_creep_force;           /* with a table (conforma_model_create_with_lut) only: 0 (default) FASTSIM, as the
                                      solve; 1: Polach's closed form on each patch's ellipse (no spin moment, adhesion
                                      and slip areas 0; several times cheaper: the dynamic wear provider's default,
                                      docs/physics-reference.md §16.7, §17.3); ignored without a table; any other
                                      value is CONFORMA_ERROR_INPUT */
} conforma_evaluation_options;

typedef struct conforma_patch_result {
  /* contact frame of the patch (Kalker's convention, right wheel mirrored) */
  double normal_force_N;           /* along the outward rail normal */
  double longitudinal_force_N;     /* creep force along the track */
  double lateral_force_N;          /* creep force along the rail profile, + towards the field side */
  double spin_moment_Nm;           /* creep moment about the normal */
  /* track frame */
  double force_track_N[3];         /* resultant of pressure and creep forces */
  double spin_moment_track_Nm[3];  /* the spin moment as a vector along the normal */
  double contact_point_track_m[3]; /* reference point of the patch on the rail surface */
  double normal_track[3];          /* outward rail normal (unit) */
  double contact_angle_rad;        /* + towards the gauge side (flange contact about +1.1 rad) */
  double rolling_radius_m;
  double approach_m;               /* approach of the patch along its reference normal (as PatchReport::approach_m) */
  /* contact state */
  double area_m2, pmax_Pa, adhesion_area_m2, slip_area_m2, frictional_power_W;
  double creepage_longitudinal, creepage_lateral, creepage_spin_per_m;  /* at the reference point */
  double conformity_index_deg;     /* alpha_c (paper 003 eq. 13); 0 for the Hertz model */
  int is_conformal;                /* 1 when alpha_c > 18 deg (KP and exact models; a flag only) */
} conforma_patch_result;

typedef struct conforma_wheel_result {
  int status;                      /* conforma_wheel_status */
  int patch_count;                 /* patches stored in patch[] (<= CONFORMA_MAX_PATCHES) */
  int patches_found;               /* all patches (their forces are in the totals even beyond the stored ones) */
  conforma_patch_result patch[CONFORMA_MAX_PATCHES];  /* along the rail, gauge side first */
  double force_track_N[3];         /* sum over the patches */
  double moment_track_Nm[3];       /* about the wheel centre (axle point in the taping-line plane), track frame */
  double wheel_centre_track_m[3];  /* the wheel centre (axle point in the taping-line plane), track frame, m */
  double vertical_position_m;      /* the pose's vertical_m the wheel was solved at (pushed down in load control) */
  int load_iterations;             /* root-finder evaluations of load control; 0 in approach mode */
  /* Plausibility warnings of the solve (docs/physics-reference.md section 13: nominal radius far from the
   * profile's, mu outside 0.05-1, p_max above 5 GPa, load not reached), as `conforma contact --json` lists them:
   * one "code: message" line each, joined by '\n', truncated to CONFORMA_WARNING_TEXT; "" when none. */
  int warning_count;
  char warnings[CONFORMA_WARNING_TEXT];
} conforma_wheel_result;

typedef struct conforma_wheelset_result {
  conforma_wheel_result wheel[2];  /* [CONFORMA_LEFT, CONFORMA_RIGHT] */
  double roll_rad;                 /* roll used: the state's, or solved with rigid_equilibrium */
  char error_message[CONFORMA_ERROR_TEXT];  /* "" on success */
} conforma_wheelset_result;

typedef struct conforma_model conforma_model;  /* opaque handle */

/* Defaults (the values in the comments above). */
CONFORMA_C_EXPORT void conforma_default_track_params(conforma_track_params* track);
CONFORMA_C_EXPORT void conforma_default_contact_params(conforma_contact_params* contact);
CONFORMA_C_EXPORT void conforma_default_evaluation_options(conforma_evaluation_options* options);

/* Builds the model: loads/generates the profiles, mounts the rails, prepares the geometry tables. On failure
 * *model is NULL and error_text (if not NULL) receives the message, truncated to error_text_size. */
CONFORMA_C_EXPORT conforma_status conforma_model_create(const conforma_track_params* track,
                                                        const conforma_contact_params* contact,
                                                        conforma_model** model, char* error_text,
                                                        size_t error_text_size);
/* The same handle, but every load-control evaluation reads the contact look-up table in lut_path (an HDF5 file of
 * `conforma lut build`, include/conforma/contact_lut.hpp) instead of solving. Load control balances the total force,
 * so a table read still solves the creep forces (FASTSIM) at each of its 2-4 effective loads: about 2 times faster
 * than the solve (tests/bench/bench_capi_lut.cpp, CPU per wheelset pose: conformal 0.15-0.18 ms against 0.3, hertz
 * 0.07 ms against 0.15; docs/physics-reference.md §17.5). track and contact
 * must be those the table was made for (model, material, profiles, gauge, radius: CONFORMA_ERROR_INPUT otherwise);
 * the table's elastic-flange rule is taken over. With the table the pose's vertical_m and roll_rad are not used (the
 * table's are those of the rigid equilibrium at lateral_m, yaw_rad), CONFORMA_GIVEN_APPROACH is CONFORMA_ERROR_INPUT,
 * and a pose or load outside the table is CONFORMA_ERROR_INPUT naming the axis (never extrapolated). */
CONFORMA_C_EXPORT conforma_status conforma_model_create_with_lut(const conforma_track_params* track,
                                                                 const conforma_contact_params* contact,
                                                                 const char* lut_path, conforma_model** model,
                                                                 char* error_text, size_t error_text_size);
/* Frees the model (NULL is ignored). No evaluation may be running on it. */
CONFORMA_C_EXPORT void conforma_model_destroy(conforma_model* model);

/* One wheelset evaluation (both wheels). `options` may be NULL (defaults). On error the result's error_message and
 * the handle's last error carry the text; the result is zeroed otherwise. */
CONFORMA_C_EXPORT conforma_status conforma_evaluate(const conforma_model* model, const conforma_wheelset_state* state,
                                                    const conforma_evaluation_options* options,
                                                    conforma_wheelset_result* result);

/* Copies the most recent error text of any call on this handle ("" if none) into buffer; returns its full length. */
CONFORMA_C_EXPORT size_t conforma_model_last_error(const conforma_model* model, char* buffer, size_t buffer_size);

/* ---------------------------------------------------------------- roller rig (issue 18, paper 000)
 * One 20 ms sample of a wheelset on two driven rollers (include/conforma/roller_rig_sample.hpp): measured y, yaw,
 * roller speeds (optionally the wheelset speed) and wheel loads -> both contacts' forces and creepages (Hertz +
 * FASTSIM by default), the Archard wear of wheel and roller (paper 000 Table 3) and the profile update with the
 * sliding-mean filter every filter_every_steps samples. The handle HOLDS THE RIG STATE (the worn profiles): one
 * handle per rig, used by one thread at a time (not thread-safe on the same handle; separate handles are
 * independent). Cost: tests/bench/bench_rig_sample.cpp (conforma_bench --benchmark_filter=RigSample). */
typedef struct conforma_rig_params {
  const char* wheel_profile;       /* "conical" (default: 0.036 rad cone, paper 000 §4), "s1002" (scaled) or a file */
  const char* roller_profile;      /* "uic60_1in20" (default: 60E1 canted 1:20, scaled) or a file (rig scale) */
  double roller_radius_m;          /* 0.185 (Table 1); <= 10 m */
  double wheel_radius_m;           /* 0.0944 (Table 1) */
  double length_factor;            /* 0.2: 1:5 rig (profiles and track dimensions scaled) */
  double wheel_conicity_rad;       /* 0.036: the "conical" wheel */
  double longitudinal_stiffness_N_per_m;  /* 2e6 per axle box (an assumption; roller_rig.hpp) */
  double spring_half_spacing_m;    /* 0.2 (an assumption) */
  const char* model;               /* "hertz" (default), "kp", "kpec", "conformal", "auto" */
  double friction_coefficient;     /* 0.3 */
  int fastsim_elements;            /* 20 (paper 000 §3.4) */
  int wear_law;                    /* 0: Archard, paper 000 Table 3 (default); 1: USFD T-gamma wear index */
  int update_profiles;             /* 1 (default): remove the wear from the profiles every sample; 0: report only */
  int filter_every_steps;          /* 10: sliding-mean filter every N samples (paper 000 §3.5) */
  double filter_window_m;          /* 1e-3: width of the sliding mean, m */
  int profile_update_every_steps;  /* 1 (default): the profiles in contact take the wear every sample; N: every N */
  int eq2_wheelset_speed;          /* 0 (default): wheelset speed from the moment balance; 1: eq. 2 (opposite creepages) */
  double strip_mean_elements;      /* 1 (default): integrated strip depth; 20: paper 000 eq. 16, its Table 3's calibration */
} conforma_rig_params;

typedef struct conforma_rig_sample {
  double time_s;                   /* time stamp, s (reported only) */
  double duration_s;               /* step the sample stands for, s, > 0 (0.02 on the rig); a sample that would
                                      remove more than 1 mm is CONFORMA_ERROR_INPUT, the rig left as it was */
  double lateral_m, yaw_rad;       /* measured wheelset lateral shift (m, + towards roller 1 / left) and yaw (rad) */
  double lateral_velocity_m_s;     /* dy/dt, m/s, |.| <= 10 */
  double roller_speed_rad_s[2];    /* omega_1 (left wheel's roller), omega_2, rad/s, > 0 */
  double wheel_load_N[2];          /* vertical load per wheel [left, right], N, > 0 */
  double wheelset_speed_rad_s;     /* measured omega_3, rad/s; <= 0: solved (moment balance or eq. 2) */
} conforma_rig_sample;

typedef struct conforma_rig_contact_result {
  int patch_count;                 /* contact patches of this wheel */
  double normal_force_N;           /* sum over the patches */
  double longitudinal_force_N;     /* creep force on the wheel along the rolling direction, N */
  double lateral_force_N;          /* creep force on the wheel along the roller profile (+ field side), N */
  double creepage_longitudinal;    /* xi of the largest patch (paper 000 eq. 2 at the loaded radii) */
  double creepage_lateral;         /* eta of the largest patch */
  double creepage_spin_per_m;      /* phi of the largest patch, 1/m */
  double roller_rolling_radius_m;  /* R_i at the contact */
  double wheel_rolling_radius_m;   /* effective r_i (r - approach) */
  double roller_surface_speed_m_s; /* V_i = omega_i R_i */
  double wheel_wear_max_depth_m;   /* depth added to the wheel in this sample, m */
  double wheel_wear_area_m2;       /* its integral over the arc length, m^2 */
  double roller_wear_max_depth_m;  /* depth added to the roller, m */
  double roller_wear_area_m2;      /* m^2 */
  double spring_force_N;           /* longitudinal spring force of this side's axle box on the wheelset, N */
} conforma_rig_contact_result;

typedef struct conforma_rig_result {
  int status;                      /* 0 ok, 1 contact failed (kinematics_status says why), 2 profile update failed */
  int kinematics_status;           /* 0 converged, 1 measured/eq. 2, 2 not converged, 3 no contact, 4 contact error */
  double wheelset_speed_rad_s;     /* omega_3 used */
  double eq2_wheelset_speed_rad_s; /* eq. 2 first approximation */
  double axle_moment_residual_Nm;  /* r_1 F_x1 + r_2 F_x2 at the result */
  double yaw_deflection_rad;       /* of the longitudinal springs */
  int profiles_updated;            /* 1 when the profiles changed in this sample */
  int filtered;                    /* 1 when the sliding-mean filter ran */
  long step;                       /* samples processed so far by this handle */
  conforma_rig_contact_result contact[2];  /* [left wheel / roller 1, right wheel / roller 2] */
  char error_message[CONFORMA_ERROR_TEXT];  /* "" on success; the reason of a non-ok status or an error */
} conforma_rig_result;

typedef struct conforma_rig conforma_rig;  /* opaque handle: rig options and the evolving profiles */

CONFORMA_C_EXPORT void conforma_default_rig_params(conforma_rig_params* params);
/* Builds the rig (profiles, geometry). On failure *rig is NULL and error_text receives the message. */
CONFORMA_C_EXPORT conforma_status conforma_rig_create(const conforma_rig_params* params, conforma_rig** rig,
                                                      char* error_text, size_t error_text_size);
/* Processes one sample on the rig's state (ProcessRigSample). CONFORMA_OK also when result->status is not 0 (a
 * failed contact or profile update is a status, with its message); CONFORMA_ERROR_INPUT for bad sample values. */
CONFORMA_C_EXPORT conforma_status conforma_rig_process_sample(conforma_rig* rig, const conforma_rig_sample* sample,
                                                              conforma_rig_result* result);
/* Frees the rig (NULL is ignored). */
CONFORMA_C_EXPORT void conforma_rig_destroy(conforma_rig* rig);

CONFORMA_C_EXPORT int conforma_api_version(void);

#ifdef __cplusplus
}
#endif

#endif /* CONFORMA_C_H */
