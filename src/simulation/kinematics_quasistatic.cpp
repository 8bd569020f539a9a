// Quasi-static curving of a bogie vehicle with the contact model in the loop (kinematics_quasistatic.hpp).
#include "conforma/kinematics_quasistatic.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

#include <ceres/ceres.h>

#include "conforma/axle_rolling_speed.hpp"
#include "conforma/error.hpp"

namespace conforma {

const char* to_string(QuasiStaticStatus status) {
  switch (status) {
    case QuasiStaticStatus::Converged: return "converged";
    case QuasiStaticStatus::NotConverged: return "not_converged";
    case QuasiStaticStatus::NoContact: return "no_contact";
  }
  return "?";
}

void QuasiStaticOptions::validate() const {
  require_positive(gravity_m_s2, "gravity_m_s2");
  require_positive(cant_base_m, "cant_base_m");
  require_non_negative(tangent_amplitude_m, "tangent_amplitude_m");
  require_finite(tangent_start_offset_m, "tangent_start_offset_m");
  require_finite(axle_torque_Nm, "axle_torque_Nm");
  if (tangent_phases < 1) throw InputError("option 'tangent_phases' must be >= 1");
  if (max_iterations < 1) throw InputError("option 'max_iterations' must be >= 1");
  require_positive(residual_tolerance, "residual_tolerance");
  if (continuation_steps < 0) throw InputError("option 'continuation_steps' must be >= 0");
  require_positive(flange_contact_angle_rad, "flange_contact_angle_rad");
  require_non_negative(derailment_margin_m, "derailment_margin_m");
  require_non_negative(climbing_slope, "climbing_slope");
  require_positive(difference_step, "difference_step");
}

double TrackClassCurvature(const TrackClass& c) {
  if (c.curve_radius_m == 0.0 || std::isinf(c.curve_radius_m)) return 0.0;
  return 1.0 / c.curve_radius_m;
}

double TrackClassUnbalancedAcceleration(const TrackClass& track_class, double gravity_m_s2, double cant_base_m) {
  const double c = TrackClassCurvature(track_class);
  const double sign_c = c > 0.0 ? 1.0 : c < 0.0 ? -1.0 : 0.0;
  return track_class.speed_m_s * track_class.speed_m_s * c - gravity_m_s2 * track_class.cant_m * sign_c / cant_base_m;
}

double WheelLoadTransferN(const VehicleParameters& vehicle, double unbalanced_acceleration_m_s2) {
  return vehicle.carried_mass_per_wheelset_kg() * unbalanced_acceleration_m_s2 * vehicle.load_transfer_height_m /
         (2.0 * vehicle.contact_half_distance_m);
}

namespace {

constexpr int kUnknowns = 8;  // y0 [mm], psi0 [mrad], w0 [1e-3], y1, psi1, w1, y_b [mm], psi_b [mrad]

// Everything a bogie solve needs; the counters are local to one solve (no shared mutable state).
struct BogieContext {
  const WheelsetTrackGeometry* geometry = nullptr;
  const WheelContactFunction* contact = nullptr;
  const QuasiStaticOptions* options = nullptr;
  WheelContactOptions contact_options;
  double V = 0.0, c = 0.0, a_nc = 0.0, r0 = 0.46, b0 = 0.75, Q0 = 1.0;
  std::array<double, 2> Q{{0.0, 0.0}};  // [Left, Right]
  double half_wheelbase = 1.25, kx = 0.0, ky = 0.0, bx = 1.0, k_sec_yaw = 0.0;
  double m_w = 0.0, m_b_plus_c = 0.0, carbody_yaw = 0.0;
  double axle_torque_Nm = 0.0;  // applied to every axle: options' + the class's (TrackClass::axle_torque_Nm)
  // Admissible wheelset shifts: up to derailment_margin_m beyond the flange-contact shift on either side.
  double y_min = -std::numeric_limits<double>::infinity(), y_max = std::numeric_limits<double>::infinity();
  int contact_evaluations = 0;
  int failed_contact_evaluations = 0;  // of those, wheel contacts without a solution (status not Ok)
};

using WheelsetForces = WheelsetContactForces;

// Contact forces on one wheelset at (y, psi, w) in its local track frame (wheelset_forces.hpp): forward V, lateral
// velocity 0, yaw rate V c, axle angular velocity V / r0 (1 + 1e-3 w).
WheelsetForces EvaluateWheelset(BogieContext& ctx, double y_m, double psi_rad, double w) {
  WheelsetVelocity velocity;
  velocity.forward_speed_m_s = ctx.V;
  velocity.lateral_velocity_m_s = 0.0;
  velocity.yaw_rate_rad_s = ctx.V * ctx.c;
  velocity.axle_angular_velocity_rad_s = ctx.V / ctx.r0 * (1.0 + 1e-3 * w);
  WheelsetForces f =
      EvaluateWheelsetContactForces(*ctx.geometry, *ctx.contact, ctx.contact_options, ctx.Q, y_m, psi_rad, velocity);
  ctx.contact_evaluations += f.contact_evaluations;
  ctx.failed_contact_evaluations += f.failed_contact_evaluations;
  return f;
}

struct Suspension {  // primary forces ON the wheelsets and the bogie residuals
  double lateral[2], yaw[2];
};

// Scaled residuals of a bogie from the unknowns and the wheelsets' contact forces (header comment equations).
void BogieResiduals(const BogieContext& ctx, const double* p, const WheelsetForces* f, double* r, Suspension* s) {
  const double yb = 1e-3 * p[6], psib = 1e-3 * p[7];
  double bogie_lateral = -ctx.m_b_plus_c * ctx.a_nc, bogie_yaw = -ctx.k_sec_yaw * (psib - ctx.carbody_yaw);
  for (int j = 0; j < 2; ++j) {
    const double x = j == 0 ? ctx.half_wheelbase : -ctx.half_wheelbase;
    const double y = 1e-3 * p[3 * j], psi = 1e-3 * p[3 * j + 1];
    const double dy = y - (yb + psib * x - 0.5 * ctx.c * x * x);
    const double dpsi = psi - (psib - ctx.c * x);
    const double Fy = -2.0 * ctx.ky * dy;                        // primary lateral force on the wheelset
    const double Mz = -2.0 * ctx.kx * ctx.bx * ctx.bx * dpsi;    // primary yaw moment on the wheelset
    if (s) s->lateral[j] = Fy, s->yaw[j] = Mz;
    r[3 * j] = (f[j].lateral_N + Fy - ctx.m_w * ctx.a_nc) / ctx.Q0;
    r[3 * j + 1] = (f[j].yaw_moment_Nm + Mz) / (ctx.Q0 * ctx.b0);
    r[3 * j + 2] = ctx.options->free_axle_rotation
                       ? (f[j].axle_torque_Nm - ctx.axle_torque_Nm) / (ctx.Q0 * ctx.r0)
                       : p[3 * j + 2];
    bogie_lateral -= Fy;
    bogie_yaw -= Mz + x * Fy;
  }
  r[6] = bogie_lateral / ctx.Q0;
  r[7] = bogie_yaw / (ctx.Q0 * ctx.b0);
}

// One bogie as a single residual block. Jacobian: forward differences of each wheelset's contact forces in its
// own three unknowns; the suspension part is linear, so its differences are exact.
class BogieCost : public ceres::SizedCostFunction<kUnknowns, kUnknowns> {
 public:
  explicit BogieCost(BogieContext* ctx) : ctx_(ctx) {}
  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    const double* p = parameters[0];
    WheelsetForces f[2];
    for (int j = 0; j < 2; ++j) {
      f[j] = EvaluateWheelset(*ctx_, 1e-3 * p[3 * j], 1e-3 * p[3 * j + 1], p[3 * j + 2]);
      if (!f[j].ok) return false;
    }
    BogieResiduals(*ctx_, p, f, residuals, nullptr);
    if (!jacobians || !jacobians[0]) return true;
    double* J = jacobians[0];  // row-major kUnknowns x kUnknowns
    const double h = ctx_->options->difference_step;
    for (int k = 0; k < kUnknowns; ++k) {
      double q[kUnknowns];
      std::copy(p, p + kUnknowns, q);
      q[k] += h;
      WheelsetForces g[2] = {f[0], f[1]};
      if (k < 6) {
        const int j = k / 3;
        // forward, then backward (e.g. a step across the edge of the contact); then both with steps 10 and 100
        // times smaller (a state next to a band where a wheel contact has no solution)
        for (const double step : {h, -h, 0.1 * h, -0.1 * h, 0.01 * h, -0.01 * h}) {
          q[k] = p[k] + step;
          g[j] = EvaluateWheelset(*ctx_, 1e-3 * q[3 * j], 1e-3 * q[3 * j + 1], q[3 * j + 2]);
          if (g[j].ok) break;
        }
        if (!g[j].ok) return false;
      }
      double rk[kUnknowns];
      BogieResiduals(*ctx_, q, g, rk, nullptr);
      const double step = q[k] - p[k];
      for (int i = 0; i < kUnknowns; ++i) J[i * kUnknowns + k] = (rk[i] - residuals[i]) / step;
    }
    return true;
  }

 private:
  BogieContext* ctx_;
};

struct AttemptResult {
  bool converged = false;      // residual reached at an admissible state
  bool beyond_margin = false;  // a wheelset outside [y_min, y_max]
  bool climbing = false;       // a flange-contact wheelset whose lateral contact force falls towards the flange
  double max_residual = std::numeric_limits<double>::infinity();
  int iterations = 0;
  // every wheelset within [y_min, y_max] and none climbing its flange
  bool admissible() const { return !beyond_margin && !climbing; }
};

// Stops the minimizer once every scaled residual is certainly 100 times below the tolerance (|r|_max <= |r|_2).
class SmallResidualStop : public ceres::IterationCallback {
 public:
  explicit SmallResidualStop(double residual) : cost_(0.5 * residual * residual) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override {
    return summary.cost <= cost_ ? ceres::SOLVER_TERMINATE_SUCCESSFULLY : ceres::SOLVER_CONTINUE;
  }

 private:
  double cost_;
};

// A start where a wheel contact has no solution (the load control stopped on a jump of the contact model's normal
// force in the push-down, seen with the conformal model on worn treads over bands of y up to ~1 mm wide) gives
// the minimizer nothing to start from: each such wheelset is moved towards the track centre line in steps of
// kStartNudge_mm until both of its wheels are solved (at most kStartNudges steps; the start is only a guess).
constexpr double kStartNudge_mm = 0.1;
constexpr int kStartNudges = 20;

void NudgeStart(BogieContext& ctx, double* p) {
  for (int j = 0; j < 2; ++j) {
    const double direction = p[3 * j] > 0.0 ? -1.0 : 1.0;
    for (int k = 0; k < kStartNudges; ++k) {
      if (EvaluateWheelset(ctx, 1e-3 * p[3 * j], 1e-3 * p[3 * j + 1], p[3 * j + 2]).ok) break;
      p[3 * j] += direction * kStartNudge_mm;
    }
  }
}

AttemptResult SolveBogie(BogieContext& ctx, double* p) {
  NudgeStart(ctx, p);
  ceres::Problem::Options problem_options;
  problem_options.cost_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  BogieCost cost(&ctx);
  problem.AddResidualBlock(&cost, nullptr, p);
  // The wheelsets' shifts stay in the admissible range [y_min, y_max] (flange-contact shift + derailment margin):
  // with the total-force balance the flange's lateral force is bounded by Nadal's limit, and an unbounded
  // trust-region step could jump over the flange onto the branch beyond it, where the wheel rides past its flange
  // and the equations have spurious solutions 10-40 mm out (issue 15: Aosta, default metro R 200 m); those were
  // rejected as derailed and the class fell back, while an admissible equilibrium existed.
  for (int j = 0; j < 2; ++j) {
    p[3 * j] = std::clamp(p[3 * j], 1e3 * ctx.y_min, 1e3 * ctx.y_max);
    problem.SetParameterLowerBound(p, 3 * j, 1e3 * ctx.y_min);
    problem.SetParameterUpperBound(p, 3 * j, 1e3 * ctx.y_max);
  }
  ceres::Solver::Options so;
  so.minimizer_type = ceres::TRUST_REGION;
  so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  so.linear_solver_type = ceres::DENSE_QR;
  so.max_num_iterations = ctx.options->max_iterations;
  so.function_tolerance = 1e-16;
  so.gradient_tolerance = 1e-20;
  so.parameter_tolerance = 1e-12;
  so.num_threads = 1;
  so.logging_type = ceres::SILENT;
  so.minimizer_progress_to_stdout = false;
  SmallResidualStop stop(1e-2 * ctx.options->residual_tolerance);
  so.callbacks.push_back(&stop);
  ceres::Solver::Summary summary;
  ceres::Solve(so, &problem, &summary);
  AttemptResult out;
  out.iterations = static_cast<int>(summary.iterations.size());
  // the wheelsets' forces at the solution: for the residual and the climbing check below
  WheelsetForces f[2];
  for (int j = 0; j < 2; ++j) f[j] = EvaluateWheelset(ctx, 1e-3 * p[3 * j], 1e-3 * p[3 * j + 1], p[3 * j + 2]);
  if (f[0].ok && f[1].ok) {
    double r[kUnknowns];
    BogieResiduals(ctx, p, f, r, nullptr);
    out.max_residual = 0.0;
    for (double v : r) out.max_residual = std::max(out.max_residual, std::fabs(v));
  }
  for (int j = 0; j < 2; ++j) {
    out.beyond_margin |= !(p[3 * j] * 1e-3 >= ctx.y_min && p[3 * j] * 1e-3 <= ctx.y_max);
    // Flange climbing: at a flange-contact state whose lateral contact force falls as the wheelset moves on
    // towards the flange (dY/dy > 0 in the track frame), the equilibrium is unstable: the wheel is riding up its
    // flange. The climbing_slope threshold is in Q0 per mm. Both one-sided differences must show it: a state
    // next to a jump of the contact forces (the patch of a conformal model switching its reference point between
    // the tread and the flange root within 0.01 mm) has a large one-sided difference across the jump while the
    // branch it lies on is stable; a central difference over the jump called such an equilibrium "climbing"
    // (issue 15: default metro R 200 m, conformal, total-force balance: slope +90 Q0/mm over the jump, -1500 on
    // the branch).
    if (!f[j].ok) continue;
    bool flange = false;
    for (const WheelContactReport& report : f[j].report)
      for (const PatchReport& patch : report.patches) flange |= patch.contact_angle_rad > ctx.options->flange_contact_angle_rad;
    if (!flange) continue;
    const double h = 0.02;  // mm
    const WheelsetForces plus = EvaluateWheelset(ctx, 1e-3 * (p[3 * j] + h), 1e-3 * p[3 * j + 1], p[3 * j + 2]);
    const WheelsetForces minus = EvaluateWheelset(ctx, 1e-3 * (p[3 * j] - h), 1e-3 * p[3 * j + 1], p[3 * j + 2]);
    if (!plus.ok || !minus.ok) continue;
    const double slope_plus = (plus.lateral_N - f[j].lateral_N) / (h * ctx.Q0);    // Q0 per mm
    const double slope_minus = (f[j].lateral_N - minus.lateral_N) / (h * ctx.Q0);  // Q0 per mm
    out.climbing |= std::min(slope_plus, slope_minus) > ctx.options->climbing_slope;
  }
  out.converged = out.admissible() && out.max_residual <= ctx.options->residual_tolerance;
  return out;
}

// An admissible attempt beats a derailed one; otherwise the smaller residual wins.
bool Better(const AttemptResult& x, const AttemptResult& y) {
  if (x.admissible() != y.admissible()) return x.admissible();
  return x.max_residual < y.max_residual;
}

// A start with the wheelsets at given lateral shifts (leading y0, trailing y1), parallel to the frame
// (no suspension deflection): psi_b = (y0 - y1) / (2 a), y_b = (y0 + y1) / 2 + c a^2 / 2, psi_j = psi_b - c x_j.
void WheelsetShiftGuess(const BogieContext& ctx, double y0, double y1, double* p) {
  std::fill(p, p + kUnknowns, 0.0);
  const double a = ctx.half_wheelbase;
  const double psib = (y0 - y1) / (2.0 * a);
  p[0] = 1e3 * y0;
  p[3] = 1e3 * y1;
  p[1] = 1e3 * (psib - ctx.c * a);
  p[4] = 1e3 * (psib + ctx.c * a);
  p[6] = 1e3 * (0.5 * (y0 + y1) + 0.5 * ctx.c * a * a);
  p[7] = 1e3 * psib;
}

// Radial-steering start: lateral shift towards the outer rail where the rigid rolling-radius difference gives
// pure rolling (outer minus inner = 2 b0 r0 |c|), clipped at the onset of flange contact; wheelsets parallel to
// the frame, frame on the chord (psi_b = 0).
void InitialGuess(const BogieContext& ctx, double* p) {
  std::fill(p, p + kUnknowns, 0.0);
  if (ctx.c == 0.0) return;
  const double out = ctx.c > 0.0 ? -1.0 : 1.0;  // towards the outer rail
  const Side outer = ctx.c > 0.0 ? Side::Right : Side::Left;
  const double required = 2.0 * ctx.b0 * ctx.r0 * std::fabs(ctx.c);
  double y_guess = 0.0, prev_dr = 0.0;
  WheelsetPose guess;
  for (int k = 1; k <= 60; ++k) {
    const double y = out * 0.25e-3 * k;
    const EquilibriumResult eq = ctx.geometry->SolveRigidEquilibrium(y, 0.0, guess);
    if (eq.status != EquilibriumStatus::Converged) break;
    guess = eq.pose;
    const double dr = out * eq.rolling_radius_difference_m;  // outer minus inner
    bool flange = false;
    for (const RigidContactPoint& cp : eq.contact.wheel[side_index(outer)].points)
      if (cp.gap_m < 1e-6 && cp.contact_angle_rad > ctx.options->flange_contact_angle_rad) flange = true;
    if (dr >= required) {
      const double t = (required - prev_dr) / (dr - prev_dr);
      y_guess = out * 0.25e-3 * (k - 1 + std::clamp(t, 0.0, 1.0));
      break;
    }
    y_guess = y;
    prev_dr = dr;
    if (flange) break;
  }
  WheelsetShiftGuess(ctx, y_guess, y_guess, p);
}


// One bogie's equilibrium at the carbody yaw (the residuals of BogieResiduals): a start from the kinematic guess,
// then (not converged) continuation in c = 1/R and further starts in the flange regimes; the best attempt and its
// unknowns.
std::pair<BogieQuasiStaticReport, std::array<double, kUnknowns>> SolveBogieCase(const BogieContext& base,
                                                                                double carbody_yaw, double y_right,
                                                                                double y_left,
                                                                                const QuasiStaticOptions& options) {
  const double c = base.c;
  BogieContext ctx = base;
  ctx.carbody_yaw = carbody_yaw;
  BogieQuasiStaticReport rep;
  rep.carbody_yaw_rad = carbody_yaw;
  std::array<double, kUnknowns> p{};
  InitialGuess(ctx, p.data());
  if (c == 0.0) p[0] = p[3] = p[6] = 1e3 * options.tangent_start_offset_m;
  AttemptResult a = SolveBogie(ctx, p.data());
  rep.iterations += a.iterations;
  if (!a.converged && options.continuation_steps > 0 && c != 0.0) {  // continuation in c = 1/R
    rep.continuation_used = true;
    const std::array<double, kUnknowns> direct = p;
    const AttemptResult direct_result = a;
    std::fill(p.begin(), p.end(), 0.0);
    for (int k = 1; k <= options.continuation_steps; ++k) {
      const double f = static_cast<double>(k) / options.continuation_steps;
      ctx.c = f * c;
      ctx.a_nc = f * base.a_nc;
      ctx.carbody_yaw = f * carbody_yaw;
      a = SolveBogie(ctx, p.data());
      rep.iterations += a.iterations;
    }
    if (Better(direct_result, a)) p = direct, a = direct_result;  // keep the better one
    ctx.c = c;
    ctx.a_nc = base.a_nc;
    ctx.carbody_yaw = carbody_yaw;
  }
  // Further starts in the flange regimes of a stiff bogie in a sharp curve, where the two starts above can
  // stall in a local minimum of the residual (the flange forces rise by ~2 Q0 within 0.05 mm): leading
  // wheelset at the outer flange with the trailing one at the inner flange, centred, or at the outer flange.
  if (!a.converged && options.multi_start && c != 0.0) {
    const double out = c > 0.0 ? -1.0 : 1.0;
    const double y_out = out < 0.0 ? y_right : y_left, y_in = out < 0.0 ? y_left : y_right;
    for (const double y1 : {y_in, 0.0, y_out}) {
      std::array<double, kUnknowns> q{};
      WheelsetShiftGuess(ctx, y_out, y1, q.data());
      const AttemptResult attempt = SolveBogie(ctx, q.data());
      rep.iterations += attempt.iterations;
      ++rep.extra_starts;
      if (Better(attempt, a)) p = q, a = attempt;
      if (a.converged) break;
    }
  }
  rep.max_residual = a.max_residual;
  rep.contact_evaluations = ctx.contact_evaluations;
  rep.failed_contact_evaluations = ctx.failed_contact_evaluations;
  rep.derailed = a.beyond_margin;
  rep.climbing = a.climbing;
  rep.status = a.converged ? QuasiStaticStatus::Converged
               : std::isfinite(a.max_residual) ? QuasiStaticStatus::NotConverged
                                                : QuasiStaticStatus::NoContact;
  rep.lateral_m = 1e-3 * p[6];
  rep.yaw_rad = 1e-3 * p[7];
  return std::make_pair(rep, p);
}

// The reports of bogie b's two wheelsets at its solution p (the contact re-evaluated there: the forces are
// deterministic), its residuals into the last bogie report.
void AppendWheelsetReports(const BogieContext& base, double carbody_yaw, int b, const std::array<double, kUnknowns>& p,
                           const QuasiStaticOptions& options, QuasiStaticResult* result) {
  BogieContext ctx = base;
  ctx.carbody_yaw = carbody_yaw;
  WheelsetForces f[2];
  for (int j = 0; j < 2; ++j) f[j] = EvaluateWheelset(ctx, 1e-3 * p[3 * j], 1e-3 * p[3 * j + 1], p[3 * j + 2]);
  double r[kUnknowns];
  Suspension s{};
  BogieResiduals(ctx, p.data(), f, r, &s);
  for (int k = 0; k < kUnknowns; ++k) result->bogies.back().residuals[k] = r[k];
  for (int j = 0; j < 2; ++j) {
    WheelsetQuasiStaticReport w;
    w.wheelset = 2 * b + j;
    w.bogie = b;
    w.pose = f[j].pose;
    w.pose.lateral_m = 1e-3 * p[3 * j];
    w.pose.yaw_rad = 1e-3 * p[3 * j + 1];
    w.velocity = f[j].velocity;
    w.primary_lateral_force_N = s.lateral[j];
    w.primary_yaw_moment_Nm = s.yaw[j];
    for (Side side : {Side::Left, Side::Right}) {
      const int i = side_index(side);
      WheelQuasiStaticReport& wr = w.wheel[i];
      const WheelContactReport& cr = f[j].report[i];
      wr.status = cr.status;
      wr.vertical_load_N = base.Q[i];
      wr.patch_count = static_cast<int>(cr.patches.size());
      for (const PatchReport& pr : cr.patches) {
        wr.longitudinal_force_N += pr.fx_N;
        wr.max_contact_angle_rad = std::max(wr.max_contact_angle_rad, pr.contact_angle_rad);
        if (pr.contact_angle_rad > options.flange_contact_angle_rad) wr.flange_contact = true;
      }
      wr.lateral_force_N = side_sign(side) * cr.lateral_force_N;
      wr.y_over_q = -cr.lateral_force_N / base.Q[i];  // towards the gauge side = -eta
      result->total_lateral_force_N += wr.lateral_force_N;
    }
    result->wheelsets.push_back(w);
  }
}

// Tangent track: the samples of the kinematic oscillation about the centred wheelset (header comment), every
// wheelset of the result at each phase.
void AppendTangentOscillationSamples(const WheelsetTrackGeometry& geometry, const BogieContext& base,
                                     const TrackClass& track_class, const QuasiStaticOptions& options,
                                     const WheelContactFunction& contact, QuasiStaticResult* result) {
  const double A = options.tangent_amplitude_m;
  const EquilibriumResult eq_amp = geometry.SolveRigidEquilibrium(-A, 0.0);
  double conicity = eq_amp.status == EquilibriumStatus::Converged ? -eq_amp.rolling_radius_difference_m / (2.0 * A) : 0.0;
  conicity = std::max(conicity, 1e-3);  // a (nearly) cylindrical tread: long wavelength, still finite
  const double k = 1.0 / std::sqrt(base.r0 * base.b0 / conicity);  // 2 pi / L_K (Klingel)
  const double V = track_class.speed_m_s;
  // Axle speed per phase from the torque balance (§12.3): every wheelset of the vehicle has the same pose,
  // velocities and loads at a given phase, so each phase is solved once.
  AxleRollingSpeedOptions rolling;
  rolling.applied_torque_Nm = base.axle_torque_Nm;
  rolling.torque_tolerance_Nm = options.residual_tolerance * base.Q0 * base.r0;
  std::map<int, double> axle_speed;  // phase -> Omega
  for (const WheelsetQuasiStaticReport& w : result->wheelsets) {
    WheelsetPose guess;
    for (int n = 0; n < options.tangent_phases; ++n) {
      const double theta = 2.0 * M_PI * n / options.tangent_phases;
      KinematicsSample s;
      s.wheelset = w.wheelset;
      s.time_s = theta / (k * V);
      s.weight = 1.0 / options.tangent_phases;
      const double y = A * std::sin(theta), psi = A * k * std::cos(theta);
      const EquilibriumResult eq = geometry.SolveRigidEquilibrium(y, psi, guess);
      if (eq.status == EquilibriumStatus::Converged) guess = eq.pose;
      s.pose = eq.pose;
      s.pose.lateral_m = y;
      s.pose.yaw_rad = psi;
      s.velocity.forward_speed_m_s = V;
      s.velocity.lateral_velocity_m_s = V * psi;
      s.velocity.yaw_rate_rad_s = -V * A * k * k * std::sin(theta);
      s.velocity.axle_angular_velocity_rad_s = V / base.r0;
      if (options.free_axle_rotation) {
        auto known = axle_speed.find(n);
        if (known == axle_speed.end()) {
          const AxleRollingSpeedResult roll = SolveAxleRollingSpeed(geometry, s.pose, s.velocity, base.Q,
                                                                    base.contact_options, contact, base.r0, rolling);
          if (roll.status != AxleRollingSpeedStatus::Converged) {
            ++result->tangent_rolling_failures;
            if (result->status == QuasiStaticStatus::Converged) result->status = QuasiStaticStatus::NotConverged;
          }
          known = axle_speed.emplace(n, roll.axle_angular_velocity_rad_s).first;
        }
        s.velocity.axle_angular_velocity_rad_s = known->second;
      }
      s.vertical_load_N[0] = base.Q[0];
      s.vertical_load_N[1] = base.Q[1];
      s.track_curvature_per_m = 0.0;
      result->series.samples.push_back(s);
    }
  }
}

}  // namespace

QuasiStaticResult SolveQuasiStaticCurving(const VehicleParameters& vehicle, const WheelsetTrackGeometry& geometry,
                                          const TrackClass& track_class, const QuasiStaticOptions& options,
                                          const WheelContactFunction& contact) {
  vehicle.validate();
  options.validate();
  if (!contact) throw InputError("quasi-static curving: no contact function given");
  require_positive(track_class.speed_m_s, "track class speed_m_s");
  require_finite(track_class.curve_radius_m, "track class curve_radius_m");
  require_non_negative(track_class.friction_coefficient, "track class friction_coefficient");
  require_finite(track_class.cant_m, "track class cant_m");
  require_finite(track_class.axle_torque_Nm, "track class axle_torque_Nm");
  if (track_class.curve_radius_m != 0.0 && std::fabs(track_class.curve_radius_m) < 5.0 * vehicle.wheelbase_m)
    throw InputError("track class '" + track_class.name + "': curve radius too small for the bogie wheelbase");

  for (double r : geometry.setup().nominal_radius_m)
    if (std::fabs(r - vehicle.nominal_wheel_radius_m) > 1e-6)
      throw InputError("vehicle field 'nominal_wheel_radius_m' (" + MessageNumber(vehicle.nominal_wheel_radius_m) +
                       " m) differs from the track set-up's nominal wheel radius (" + MessageNumber(r) + " m)");
  const double c = TrackClassCurvature(track_class);
  const double g = options.gravity_m_s2;
  QuasiStaticResult result;
  result.unbalanced_acceleration_m_s2 = TrackClassUnbalancedAcceleration(track_class, g, options.cant_base_m);

  BogieContext base;
  base.geometry = &geometry;
  base.contact = &contact;
  base.options = &options;
  base.contact_options = options.contact;
  base.contact_options.friction_coefficient = track_class.friction_coefficient;
  base.V = track_class.speed_m_s;
  base.c = c;
  base.a_nc = result.unbalanced_acceleration_m_s2;
  base.r0 = vehicle.nominal_wheel_radius_m;
  base.b0 = vehicle.contact_half_distance_m;
  base.Q0 = vehicle.static_wheel_load_N(g);
  base.axle_torque_Nm = options.axle_torque_Nm + track_class.axle_torque_Nm;
  // load transfer: the outer wheel (-y side for a_nc > 0) carries more
  const double dQ = WheelLoadTransferN(vehicle, result.unbalanced_acceleration_m_s2);
  base.Q = {base.Q0 - dQ, base.Q0 + dQ};
  if (base.Q[0] <= 0.0 || base.Q[1] <= 0.0) {
    result.status = QuasiStaticStatus::NoContact;  // a wheel is unloaded: overturning, not a steady curving case
    return result;
  }
  base.half_wheelbase = 0.5 * vehicle.wheelbase_m;
  base.kx = vehicle.primary_longitudinal_stiffness_N_m;
  base.ky = vehicle.primary_lateral_stiffness_N_m;
  base.bx = 0.5 * vehicle.lateral_axlebox_spacing_m;
  base.k_sec_yaw = vehicle.secondary_yaw_stiffness_Nm_rad;
  base.m_w = vehicle.wheelset_mass_kg;
  base.m_b_plus_c = vehicle.bogie_frame_mass_kg + vehicle.carbody_mass_per_bogie_kg;
  // flange-contact shifts towards the right (curvature > 0: outer) and the left rail (geometry.hpp)
  const double y_right = FlangeContactShift(geometry, 1.0, options.flange_contact_angle_rad);
  const double y_left = FlangeContactShift(geometry, -1.0, options.flange_contact_angle_rad);
  base.y_min = y_right - options.derailment_margin_m;
  base.y_max = y_left + options.derailment_margin_m;

  // Bogies with the same carbody yaw have the same equilibrium: solve each distinct case once.
  std::map<double, std::pair<BogieQuasiStaticReport, std::array<double, kUnknowns>>> solved;
  result.status = QuasiStaticStatus::Converged;
  for (int b = 0; b < vehicle.bogie_count; ++b) {
    const double half_chord = 0.5 * c * vehicle.bogie_centre_distance_m;
    double carbody_yaw = 0.0;
    if (vehicle.bogie_count > 1) {
      double sum = 0.0;
      int n = 0;
      if (b > 0) sum += half_chord, ++n;                        // chord to the bogie ahead
      if (b < vehicle.bogie_count - 1) sum -= half_chord, ++n;  // chord to the bogie behind
      carbody_yaw = sum / n;
    }
    auto it = solved.find(carbody_yaw);
    if (it == solved.end()) {
      const auto solution = SolveBogieCase(base, carbody_yaw, y_right, y_left, options);
      it = solved.emplace(carbody_yaw, solution).first;
    }
    BogieQuasiStaticReport rep = it->second.first;
    rep.bogie = b;
    if (vehicle.secondary_lateral_stiffness_N_m > 0.0)
      rep.secondary_lateral_deflection_m =
          vehicle.carbody_mass_per_bogie_kg * base.a_nc / vehicle.secondary_lateral_stiffness_N_m;
    const std::array<double, kUnknowns>& p = it->second.second;
    if (rep.status != QuasiStaticStatus::Converged && result.status == QuasiStaticStatus::Converged)
      result.status = rep.status;
    if (rep.status == QuasiStaticStatus::NoContact) result.status = QuasiStaticStatus::NoContact;
    result.bogies.push_back(rep);

    AppendWheelsetReports(base, carbody_yaw, b, p, options, &result);
  }

  // Samples.
  result.series.source = "quasi-static " + track_class.name + " R=" + std::to_string(track_class.curve_radius_m) +
                         " m V=" + std::to_string(track_class.speed_m_s) + " m/s";
  if (c != 0.0 || options.tangent_amplitude_m == 0.0) {
    for (const WheelsetQuasiStaticReport& w : result.wheelsets) {
      KinematicsSample s;
      s.wheelset = w.wheelset;
      s.pose = w.pose;
      s.velocity = w.velocity;
      s.vertical_load_N[0] = w.wheel[0].vertical_load_N;
      s.vertical_load_N[1] = w.wheel[1].vertical_load_N;
      s.track_curvature_per_m = c;
      result.series.samples.push_back(s);
    }
    return result;
  }
  AppendTangentOscillationSamples(geometry, base, track_class, options, contact, &result);
  return result;
}

}  // namespace conforma
