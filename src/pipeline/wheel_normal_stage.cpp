// Stage 1 of one wheel's contact: candidates, model per patch, normal problem, load control
// (wheel_contact_stages.hpp).
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "conforma/error.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/model_selection.hpp"
#include "conforma/root_finding.hpp"
#include "wheel_contact_stages.hpp"
#include "wheel_motion.hpp"

namespace conforma {
namespace wheel_contact_detail {

namespace {

// Wheel on roller (docs/physics-reference.md §1.7): the contact lies at the angle phi about the roller axis, so its
// frame is the rail's turned by phi about the eta axis (z -> the roller's radial direction (sin, 0, cos phi), x -> its
// circumferential direction (cos, 0, -sin phi)). phi = 0 (a rail) leaves the frame as it is.
PatchFrame TiltedByRollerAngle(PatchFrame f, double phi) {
  if (phi == 0.0) return f;
  const double c = std::cos(phi), s = std::sin(phi);
  auto turn = [&](const Eigen::Vector3d& v) {
    return Eigen::Vector3d(c * v.x() + s * v.z(), v.y(), -s * v.x() + c * v.z());
  };
  return {turn(f.normal), turn(f.tangent), turn(f.longitudinal)};
}

PatchFrame FrameOf(const PatchGeometry& patch) {
  const Eigen::Vector2d n = patch.reference_normal.normalized();
  // t0 = n turned by -90 deg in the rail-profile plane: +eta (field side) for a vertical normal (curved_fastsim.hpp)
  return {Eigen::Vector3d(0.0, n.x(), n.y()), Eigen::Vector3d(0.0, n.y(), -n.x())};
}

// Frame of a Hertz patch at a rigid contact point: rail normal (-sin delta, cos delta) in (eta, z).
PatchFrame FrameOfContactAngle(double contact_angle_rad) {
  const double sd = std::sin(contact_angle_rad), cd = std::cos(contact_angle_rad);
  return {Eigen::Vector3d(0.0, -sd, cd), Eigen::Vector3d(0.0, cd, sd)};
}

// The rigid contact points of the hertz and auto models (stage.hertz_points): hertz, one per rigid gap minimum at
// first touch, each patch taking its region's bookkeeping (stage.hertz_region); auto, one per region (its deepest
// minimum, else the region's reference point). Other models: empty points, one per candidate.
void AssignRigidContactPoints(NormalStage& stage, const WheelsetTrackGeometry& geometry, Side side,
                              const WheelsetPose& pose, const WheelContactOptions& options) {
  CandidateResult& candidates = stage.candidates;
  std::vector<RigidContactPoint>& hertz_points = stage.hertz_points;
  if (options.model == ContactModel::Hertz || options.model == ContactModel::Auto) {
    // Multi-Hertz (docs/physics-reference.md §1): one ellipse per rigid gap minimum of the wheel at first touch, each
    // with its own approach; the interpenetration regions only bracket the push-down. Taking one point per
    // region at the pushed pose instead made the wheel's forces jump whenever two regions merged (flange face
    // and flange root, tread and flange) or a pushed minimum slid into the conformal flange root, which
    // stalled the quasi-static curving solve. A minimum enters (RigidContact's 2 mm window) with a positive gap,
    // i.e. without force, so the forces stay continuous in the pose. `auto` keeps one patch per region and
    // takes the region's deepest of these points when it chooses Hertz.
    // first touch: from the load-given candidate search, or found here (approach mode)
    WheelsetPose touching = candidates.touching_pose;
    WheelContactResult touching_contact;
    if (!candidates.has_touching) {
      touching = pose;
      double touch_gap = 0.0, touch_y = 0.0;
      if (geometry.MinimumVerticalGap(side, pose, &touch_gap, &touch_y, options.max_touching_contact_angle_rad))
        touching.vertical_m -= touch_gap;
      touching_contact = geometry.RigidContact(side, touching);
    }
    const WheelContactResult& at_touch = candidates.has_touching ? candidates.touching_contact : touching_contact;
    const double push = touching.vertical_m - candidates.pose.vertical_m;  // candidates' pose below first touch
    std::vector<RigidContactPoint> points;  // gaps along the normal at the candidates' pose
    for (const RigidContactPoint& p : at_touch.points) {  // smallest gap first
      bool duplicate = false;  // two coarse minima refined to the same point
      for (const RigidContactPoint& q : points) duplicate |= std::fabs(q.rail_s_m - p.rail_s_m) < 0.05e-3;
      if (duplicate) continue;
      points.push_back(p);
      points.back().gap_m = p.gap_m - push * NormalVerticalCosine(p);
    }
    // the region holding a point, or the nearest one
    auto region_of = [&](const RigidContactPoint& p) {
      size_t best = 0;
      double best_distance = 1e300;
      for (size_t j = 0; j < candidates.candidates.size(); ++j) {
        const ContactCandidate& c = candidates.candidates[j];
        const double d = std::max({0.0, c.region_start_s_m - p.rail_s_m, p.rail_s_m - c.region_end_s_m});
        if (d < best_distance) best_distance = d, best = j;
      }
      return best;
    };
    // along the rail (gauge side first), as the regions
    std::sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.rail_s_m < y.rail_s_m; });
    if (options.model == ContactModel::Hertz && !points.empty()) {
      std::vector<ContactCandidate> split;  // only the region's bookkeeping is used for a Hertz patch
      for (const RigidContactPoint& p : points) {
        split.push_back(candidates.candidates[region_of(p)]);
        stage.hertz_region.push_back(region_of(p));
      }
      candidates.candidates = std::move(split);
      hertz_points = points;
    } else {
      for (const ContactCandidate& c : candidates.candidates) hertz_points.push_back(c.reference);
      std::vector<double> deepest(candidates.candidates.size(), 1e300);
      for (const RigidContactPoint& p : points) {
        const size_t j = region_of(p);
        if (p.gap_m < deepest[j]) hertz_points[j] = p, deepest[j] = p.gap_m;
      }
    }
  } else {
    hertz_points.resize(candidates.candidates.size());
  }
}

// The model of each patch: the chosen one, or per patch from the undeformed geometry at the candidates' pose
// (auto, model_selection.hpp; the approach there is the Hertz push-down in load control); and each patch's frame.
void ChoosePatchModelsAndFrames(NormalStage& stage, const WheelContactOptions& options) {
  const CandidateResult& candidates = stage.candidates;
  const std::vector<RigidContactPoint>& hertz_points = stage.hertz_points;
  const size_t n = candidates.candidates.size();
  std::vector<ContactModel>& patch_model = stage.patch_model;
  std::vector<double>& auto_alpha_c_deg = stage.auto_alpha_c_deg;
  patch_model.assign(n, options.model);
  auto_alpha_c_deg.assign(n, 0.0);
  if (options.model == ContactModel::Auto) {
    for (size_t j = 0; j < n; ++j) {
      const PatchGeometry& patch = candidates.candidates[j].patch;
      const ModelSelection choice = ChoosePatchModel(ContactModel::Auto, PatchInput{&patch, &hertz_points[j]},
                                                     patch.rigid_approach_m, options.auto_selection);
      patch_model[j] = choice.model;
      auto_alpha_c_deg[j] = choice.alpha_c_deg;
    }
  }
  std::vector<PatchFrame>& frames = stage.frames;
  frames.resize(n);
  for (size_t j = 0; j < n; ++j)
    frames[j] = patch_model[j] == ContactModel::Hertz
                    ? TiltedByRollerAngle(FrameOfContactAngle(hertz_points[j].contact_angle_rad),
                                          hertz_points[j].roller_angle_rad)
                    : TiltedByRollerAngle(FrameOf(candidates.candidates[j].patch),
                                          candidates.candidates[j].reference.roller_angle_rad);
}

// Stage 1: candidates, model per patch, normal problem (load control); with total-force load control also the
// tangential problem at every push-down (NormalStage::coupled). In load control the candidates are found for
// candidate_load_N (the wheel load, or the fixed point's load of LoadBalance::TotalConsistent, SolveNormalStage);
// the load control balances options.vertical_load_N. start_vertical_m (total-force balance only): the wheel's vertical
// position where the direct total-force balance (step 0 of §3.6.1) starts; NaN: the candidates' Hertz push-down.
// Options validated by the caller.
NormalStage SolveNormalStageFor(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                                const WheelsetVelocity& velocity, const WheelContactOptions& options,
                                double candidate_load_N, double start_vertical_m = std::nan("")) {
  NormalStage stage;
  WheelContactReport& report = stage.report;
  report.side = side;
  report.model = options.model;
  report.pose = pose;

  // 1. Candidates: at the Hertz push-down for the load (load control) or at the given pose.
  CandidateOptions candidate_options;
  candidate_options.strip_width_m = options.candidate_strip_width_m;
  candidate_options.combine_distance_m = options.patch_combine_distance_m;
  candidate_options.max_touching_contact_angle_rad = options.max_touching_contact_angle_rad;
  const bool load_control = options.vertical_load_N >= 0.0;
  // The hertz model reads only the regions and the rigid contact points (§1); their strip geometry is wanted only by
  // the pressure balance's bracket (phase 1 below), found again there when it is needed.
  candidate_options.strip_geometry =
      !(options.model == ContactModel::Hertz && (!load_control || BalancesTotalVerticalForce(options)));
  stage.finished = true;
  if (load_control && options.vertical_load_N == 0.0) return stage;  // unloaded wheel: no contact
  CandidateResult& candidates = stage.candidates;
  if (load_control) report.candidate_load_N = candidate_load_N, report.candidate_searches = 1;
  candidates = load_control ? FindContactCandidatesForLoad(geometry, side, pose, candidate_load_N,
                                                           options.material, candidate_options)
                            : FindContactCandidates(geometry, side, pose, candidate_options);
  if (candidates.status != CandidateStatus::Ok || candidates.candidates.empty()) return stage;
  report.pose = candidates.pose;
  // Hertz (and auto, which may choose Hertz): the rigid contact points (gap minima) inside each region.
  AssignRigidContactPoints(stage, geometry, side, pose, options);
  const std::vector<RigidContactPoint>& hertz_points = stage.hertz_points;
  const size_t n = candidates.candidates.size();
  ChoosePatchModelsAndFrames(stage, options);
  const std::vector<ContactModel>& patch_model = stage.patch_model;
  const std::vector<PatchFrame>& frames = stage.frames;

  // 2. Normal problem for a vertical push `dz` beyond the candidates' pose: patch j's approach along its own
  // reference normal grows by dz n0_z.
  auto solve_all = [&](double dz, std::vector<PatchNormalSolution>* out) {
    double vertical = 0.0;
    for (size_t j = 0; j < n; ++j) {
      const ContactCandidate& c = candidates.candidates[j];
      PatchNormalSolution& s = (*out)[j];
      if (patch_model[j] == ContactModel::Hertz) {
        const double approach = -hertz_points[j].gap_m + dz * frames[j].normal.z();  // cos(delta) (cos(phi))
        s = SolvePatchNormal(ContactModel::Hertz, PatchInput{nullptr, &hertz_points[j]}, approach, options);
        vertical += s.fn_N * frames[j].normal.z();
        continue;
      }
      const double approach = c.patch.rigid_approach_m + dz * frames[j].normal.z();
      s = SolvePatchNormal(patch_model[j], PatchInput{&c.patch, nullptr}, approach, options);
      vertical += s.fn_N * frames[j].normal.z() + s.fs_N * frames[j].tangent.z();
    }
    return vertical;
  };
  std::vector<PatchNormalSolution>& normal = stage.normal;
  normal.resize(n);
  if (load_control) {
    const WheelsetPose candidates_pose = report.pose;
    // Total-force balance (docs/physics-reference.md §3.6.1): the wheel's vertical force with the creep forces,
    // F_z(dz) = sum_j (fn_j n0_j,z + (fs_j + fy_j) t0_j,z), each evaluation solving the normal problem and then the
    // tangential one on its pressure (the traction bound mu p follows the push). total_at(push) evaluates it at
    // dz = base_push + push; `last` is the report of its last evaluation.
    std::shared_ptr<const WheelContactReport> last;
    double base_push = 0.0;
    bool normal_at_base = false;                 // `normal` already holds the normal solution at base_push
    double best_push = 0.0, best_error = 1e300;  // the evaluation nearest to the load
    auto total_at = [&](double push) {
      const double dz = base_push + push;
      if (!(normal_at_base && push == 0.0)) solve_all(dz, &normal);
      normal_at_base = false;
      stage.report.pose.vertical_m = candidates_pose.vertical_m - dz;
      last = std::make_shared<const WheelContactReport>(SolveTangentialStage(stage, geometry, side, velocity, options));
      const double error = std::fabs(last->vertical_force_N - options.vertical_load_N);
      if (error < best_error) best_error = error, best_push = push;
      return last->vertical_force_N;
    };
    // The first step from (base_push, F_z there): with F_z / pressure about constant in the push and a Hertzian
    // approach ~ N^(2/3), the root is at approach (ratio^(-2/3) - 1) from base_push, ratio = F_z / load there (exact
    // for a Hertzian patch), approach = the wheel's vertical push from first touch: each patch's normal approach
    // over its n0_z (a flange patch at 60-70 deg needs 2-3x its approach vertically); doubled until F_z crosses
    // the load, within 8 approaches.
    auto solve_total_from_base = [&](double total_at_base) {
      const double ratio = total_at_base / options.vertical_load_N;
      double approach = std::fabs(base_push);
      for (size_t j = 0; j < n; ++j) {
        const bool hertz = patch_model[j] == ContactModel::Hertz;
        const double rigid = hertz ? -hertz_points[j].gap_m : candidates.candidates[j].patch.rigid_approach_m;
        const double nz = frames[j].normal.z();
        if (nz > 0.1 && rigid > 0.0) approach = std::max(approach, rigid / nz + base_push);
      }
      approach = std::max(approach, 1e-7);
      return SolveLoadControlFrom(total_at, total_at_base, options.vertical_load_N,
                                  (std::pow(ratio, -2.0 / 3.0) - 1.0) * approach, 8.0 * approach,
                                  options.load_tolerance);
    };
    int direct_evaluations = 0;
    if (BalancesTotalVerticalForce(options)) {
      // Direct total-force balance from the candidates' Hertz push-down (dz = 0), without the pressure balance
      // first: accepted when it converges (Ok); otherwise (F_z <= 0 there, no rising bracket, a jump over the
      // load) the two phases below decide, from the pressure-balanced push.
      stage.finished = false;
      // (TotalConsistent's later candidate searches start at the last solution: §3.6.1 step 4)
      if (std::isfinite(start_vertical_m)) base_push = candidates_pose.vertical_m - start_vertical_m;
      const double total_at_hertz = total_at(0.0);
      LoadControlResult direct;
      if (total_at_hertz > 0.0) direct = solve_total_from_base(total_at_hertz);
      direct_evaluations = 1 + direct.iterations;
      if (direct.status == LoadControlStatus::Ok) {
        WheelContactReport coupled = *last;
        coupled.load_iterations = direct_evaluations;
        report.load_iterations = coupled.load_iterations;
        report.pose = coupled.pose;
        stage.coupled = std::make_shared<const WheelContactReport>(std::move(coupled));
        return stage;
      }
      report.pose = candidates_pose;
      base_push = 0.0, best_push = 0.0, best_error = 1e300;
    }
    // Phase 1, the one load control (load_control.hpp) on the pressure forces alone (monotone in the push: every
    // patch's approach grows with it): the Hertz push-down of the candidates is close, so the first bracket is the
    // size of the largest rigid approach; its last evaluation is at the solution (no re-solve).
    if (!candidate_options.strip_geometry) {
      // (hertz: each patch gets its region's strips, from the same search again; each point's region as above)
      candidate_options.strip_geometry = true;
      const CandidateResult full = FindContactCandidatesForLoad(geometry, side, pose, candidate_load_N,
                                                                options.material, candidate_options);
      for (size_t j = 0; j < n; ++j)
        candidates.candidates[j].patch = full.candidates.at(stage.hertz_region.empty() ? j : stage.hertz_region[j]).patch;
    }
    double scale = 0.0;
    for (const ContactCandidate& c : candidates.candidates) scale = std::max(scale, c.patch.rigid_approach_m);
    scale = std::max(scale, 1e-6);
    // (with the total-force balance to follow, phase 1 only starts phase 2: a 1e-3 tolerance is enough)
    const double pressure_tolerance =
        BalancesTotalVerticalForce(options) ? std::max(options.load_tolerance, 1e-3) : options.load_tolerance;
    const LoadControlResult load = SolveLoadControl([&](double dz) { return solve_all(dz, &normal); },
                                                    options.vertical_load_N, scale, pressure_tolerance);
    if (load.status == LoadControlStatus::NoBracket) {
      report.status = WheelContactStatus::NotConverged;
      stage.coupled.reset();
      stage.finished = true;
      return stage;
    }
    report.load_iterations = direct_evaluations + load.iterations;
    if (load.status == LoadControlStatus::NotConverged) report.status = WheelContactStatus::NotConverged;
    report.pose.vertical_m = candidates_pose.vertical_m - load.push_m;
    if (BalancesTotalVerticalForce(options) && load.status == LoadControlStatus::Ok) {
      // Phase 2: the total-force balance started at phase 1's push (bracketed, SolveLoadControlFrom, Illinois false
      // position). F_z is not monotone by construction: a creep force along t0 pulling the wheel down
      // (mu tan(delta) > 1 at a flange with the wheel sliding down it) can outweigh the pressure; then F_z <= 0 at
      // phase 1's push and no push-down carries the load: NotConverged, the pressure-balanced solution reported.
      stage.finished = false;
      base_push = load.push_m;
      normal_at_base = true;  // phase 1's last evaluation is at its push (SolveLoadControl): not solved again
      const double total_at_pressure_balance = total_at(0.0);
      if (!(total_at_pressure_balance > 0.0)) {
        report.status = WheelContactStatus::NotConverged;
        WheelContactReport failed = *last;
        failed.status = WheelContactStatus::NotConverged;
        stage.coupled = std::make_shared<const WheelContactReport>(std::move(failed));
        return stage;
      }
      const LoadControlResult total = solve_total_from_base(total_at_pressure_balance);
      if (total.status != LoadControlStatus::Ok && total.status != LoadControlStatus::NotConverged) {
        report.status = WheelContactStatus::NotConverged;  // no bracket: the pressure-balanced solution
        total_at(0.0);
      } else if (total.status == LoadControlStatus::NotConverged && best_push != total.push_m) {
        // F_z jumps over the load (a discontinuity of a model's normal solution in the push, seen with the
        // conformal model on worn profiles): the bracket closes on the jump; report the evaluation nearest to it
        total_at(best_push);
      }
      WheelContactReport coupled = *last;
      coupled.load_iterations = report.load_iterations + 1 + total.iterations;
      if (total.status == LoadControlStatus::NotConverged || report.status == WheelContactStatus::NotConverged)
        coupled.status = WheelContactStatus::NotConverged;
      report.load_iterations = coupled.load_iterations;
      report.pose = coupled.pose;
      stage.coupled = std::make_shared<const WheelContactReport>(std::move(coupled));
    } else {
      stage.coupled.reset();  // (a failed direct attempt's report is not the answer)
    }
  } else {
    solve_all(0.0, &normal);
  }
  stage.finished = false;
  return stage;
}

// LoadBalance::TotalConsistent (docs/physics-reference.md §3.6.1 step 4, §17.4): the total balance of
// SolveNormalStageFor with its candidates found for the load L that the pressure forces carry at its own solution.
// P(L) = pressure_vertical_force_N of the total balance to Q with the candidates for L; the fixed point
// g(L) = P(L) - L = 0 is the pressure-balanced solve at L (candidates for L, pushed until the pressure carries L: the
// push is unique, the pressure force rising with it) that carries Q in total. The hertz model's patches (one per
// rigid gap minimum at first touch, §1) do not depend on the candidates' load: solved as with Total.
bool SeeksConsistentCandidates(const WheelContactOptions& options) {
  return options.load_balance == LoadBalance::TotalConsistent && BalancesTotalVerticalForce(options) &&
         options.model != ContactModel::Hertz;
}

// The fixed point's budget of candidate searches (each one candidate search and one total balance,
// SolveNormalStageFor), §3.6.1 step 4: 2.2 on average on the lut check samples of §17.5, 13 at most.
constexpr int kMaxCandidateSearches = 16;

}  // namespace

NormalStage SolveNormalStage(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                             const WheelsetVelocity& velocity, const WheelContactOptions& options) {
  const double Q = options.vertical_load_N;
  if (!SeeksConsistentCandidates(options)) return SolveNormalStageFor(geometry, side, pose, velocity, options, Q);
  auto balanced = [](const NormalStage& s) { return s.coupled && s.coupled->status == WheelContactStatus::Ok; };
  auto residual = [](const NormalStage& s) { return s.coupled->pressure_vertical_force_N - s.report.candidate_load_N; };
  NormalStage best = SolveNormalStageFor(geometry, side, pose, velocity, options, Q);
  // the total balance with the candidates for Q failed (or no contact): reported as with Total
  if (!balanced(best)) return best;
  const double tolerance = std::max(options.load_tolerance, kCandidateLoadTolerance) * Q;
  int searches = 1, evaluations = best.report.load_iterations;
  double load = Q, g = residual(best), best_g = g;  // the last load whose total balance succeeded, and its g
  double previous_load = 0.0, previous_g = 0.0;
  bool has_previous = false, converged = std::fabs(g) <= tolerance;
  double failed_load = 0.0;  // > 0: the last trial load, whose total balance failed
  // where the next total balance starts: the last balanced solution (the push changes little with the candidates)
  double start_vertical_m = best.coupled->pose.vertical_m;
  bool bisect = false;       // the last bracketed step shrank the bracket by less than half
  std::optional<IllinoisBracket> bracket;  // root_finding.hpp: a sign change of g
  while (!converged && searches < kMaxCandidateSearches) {
    // The next load: the fixed-point step L = P first (P = Q - the creep forces' vertical part depends weakly on L),
    // then the secant on g, and once a sign change brackets the root Illinois false position, bisecting where a step
    // shrank the bracket by less than half. A load whose total balance fails (the balance's own not_converged: a
    // jump of the forces in the push, or no bracket) is backed off from by halving the step.
    double next = load + g;
    if (failed_load > 0.0) {
      next = 0.5 * (load + failed_load);
    } else if (bracket) {
      next = bisect ? 0.5 * (bracket->low() + bracket->high()) : bracket->FalsePosition();
    } else if (has_previous) {
      const double slope = (g - previous_g) / (load - previous_load);
      if (std::isfinite(slope) && slope < 0.0) next = load - g / slope;
    }
    if (!(next > 0.0 && std::isfinite(next))) break;  // no positive load for the candidates: not converged
    NormalStage trial = SolveNormalStageFor(geometry, side, pose, velocity, options, next, start_vertical_m);
    ++searches;
    evaluations += trial.report.load_iterations;
    if (!balanced(trial)) {
      failed_load = next;
      continue;
    }
    failed_load = 0.0;
    start_vertical_m = trial.coupled->pose.vertical_m;
    const double g_next = residual(trial);
    if (bracket) {
      const double width = std::fabs(bracket->high() - bracket->low());
      bracket->Replace(next, g_next, (g_next > 0.0) == (bracket->f_low() > 0.0));
      bisect = std::fabs(bracket->high() - bracket->low()) > 0.5 * width;
    } else if ((g_next > 0.0) != (g > 0.0)) {
      bracket.emplace(load, g, next, g_next);
    }
    previous_load = load, previous_g = g, has_previous = true;
    load = next, g = g_next;
    converged = std::fabs(g) <= tolerance;
    if (std::fabs(g) < std::fabs(best_g)) best = std::move(trial), best_g = g;
    // the candidates' load pinned within the tolerance by a sign change of g without |g| within it: P jumps over L
    // (a patch appears, merges or leaves with the candidates' load): no fixed point
    if (!converged && bracket && std::fabs(bracket->high() - bracket->low()) <= tolerance) break;
  }
  best.report.load_iterations = evaluations;
  best.report.candidate_searches = searches;
  WheelContactReport coupled = *best.coupled;
  coupled.load_iterations = evaluations;
  coupled.candidate_searches = searches;
  if (!converged) best.report.status = coupled.status = WheelContactStatus::NotConverged;
  best.coupled = std::make_shared<const WheelContactReport>(std::move(coupled));
  return best;
}

}  // namespace wheel_contact_detail
}  // namespace conforma
