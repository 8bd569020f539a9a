// The wear loop over wheel steps and rail steps (wear_simulation.hpp; paper 003 §6 and Fig. 11).
#include "conforma/wear_simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(WearSimulationStatus status) {
  switch (status) {
    case WearSimulationStatus::Completed: return "completed";
    case WearSimulationStatus::InvalidProfile: return "invalid_profile";
    case WearSimulationStatus::NoWear: return "no_wear";
  }
  return "?";
}

namespace {

// Local maxima of `depth` whose topographic prominence is at least `min_prominence` (WheelWearDepths::tread_hollows).
int CountProminentMaxima(const std::vector<double>& depth, double min_prominence) {
  int count = 0;
  const size_t n = depth.size();
  for (size_t i = 0; i < n; ++i) {
    const bool left_lower = i == 0 || depth[i - 1] < depth[i];
    const bool right_not_higher = i + 1 == n || depth[i + 1] <= depth[i];
    if (!left_lower || !right_not_higher) continue;  // a plateau counts once, at its left end
    // lowest depth on each side before a deeper point (or the end)
    double low_left = depth[i], low_right = depth[i];
    for (size_t j = i; j-- > 0 && depth[j] <= depth[i];) low_left = std::min(low_left, depth[j]);
    for (size_t j = i + 1; j < n && depth[j] <= depth[i]; ++j) low_right = std::min(low_right, depth[j]);
    // a plateau's twin (equal depth further on) is the same hollow: it is not deeper, so the right scan passes it
    if (depth[i] - std::max(low_left, low_right) >= min_prominence) ++count;
  }
  return count;
}

}  // namespace

WheelWearDepths MeasureWheelWear(const Profile& initial, const Profile& worn, double flange_root_y_m) {
  WheelWearDepths d;
  std::vector<double> tread_depth;  // across the tread, in arc-length order
  const double h = 0.1e-3;
  const std::vector<Eigen::Vector2d> w = worn.sample(h);
  const int n = static_cast<int>(std::floor(initial.length() / h));
  size_t guess = 0;
  for (int i = 0; i <= n; ++i) {
    const double s = i * h;
    const Eigen::Vector2d q = initial.position(s);
    const Eigen::Vector2d normal = initial.normal(s);
    // nearest sample of the worn profile (both curves are ordered the same way: search forward from the last hit,
    // then a full scan if the distance is not small)
    size_t best = guess;
    double best_d2 = (w[guess] - q).squaredNorm();
    for (size_t k = 0; k < w.size(); ++k) {
      const double d2 = (w[k] - q).squaredNorm();
      if (d2 < best_d2) best_d2 = d2, best = k;
    }
    guess = best;
    // refine on the chord to the better neighbour, then take the depth along the initial outward normal
    Eigen::Vector2d p = w[best];
    for (int nb : {-1, 1}) {
      const long j = static_cast<long>(best) + nb;
      if (j < 0 || j >= static_cast<long>(w.size())) continue;
      const Eigen::Vector2d e = w[j] - w[best];
      const double t = std::clamp((q - w[best]).dot(e) / e.squaredNorm(), 0.0, 1.0);
      const Eigen::Vector2d c = w[best] + t * e;
      if ((c - q).squaredNorm() < (p - q).squaredNorm()) p = c;
    }
    const double depth = (q - p).dot(normal);  // > 0: the worn surface lies inside (material removed)
    if (q[0] > flange_root_y_m) {
      d.tread_m = std::max(d.tread_m, depth);
      tread_depth.push_back(std::max(depth, 0.0));
    } else {
      d.flange_m = std::max(d.flange_m, depth);
    }
  }
  if (d.tread_m > 0.0) d.tread_hollows = CountProminentMaxima(tread_depth, std::max(20e-6, 0.1 * d.tread_m));
  return d;
}

bool IsWearContactModel(ContactModel model) { return model != ContactModel::Exact; }

std::string WearContactModelNames() {
  std::string names;
  for (int i = 0; i < kContactModelCount; ++i) {  // the order of contact_model.hpp's table
    const ContactModel m = static_cast<ContactModel>(i);
    if (IsWearContactModel(m)) names += (names.empty() ? "" : ", ") + std::string(to_string(m));
  }
  return names;
}

int LostContacts(const WearSimulationResult& result) {
  int lost = 0;
  for (const WearStepRecord& s : result.steps) lost += s.failed_contacts;
  return lost;
}

std::string IncompleteReason(const WearSimulationResult& result) {
  std::string reason;
  if (result.status != WearSimulationStatus::Completed)
    reason = std::string("status ") + to_string(result.status) + " after " + std::to_string(result.steps.size()) +
             " step(s)" + (result.message.empty() ? "" : ": " + result.message);
  const int lost = LostContacts(result);
  if (lost > 0) {
    std::string steps;
    for (const WearStepRecord& s : result.steps)
      if (s.failed_contacts > 0)
        steps += (steps.empty() ? "" : ", ") + std::to_string(s.step) + " (" + std::to_string(s.failed_contacts) +
                 " of " + std::to_string(s.failed_contacts + s.samples) + ")";
    reason += (reason.empty() ? "" : "; ") + std::to_string(lost) +
              " wheel contact(s) failed (no wear taken from them) in step(s) " + steps;
  }
  return reason;
}

namespace {

TrackSetup SetupWith(const Scenario& sc, const Profile& wheel, const std::array<Profile, 2>& mounted_rails) {
  TrackSetup s = sc.MakeTrackSetup();
  s.wheel = {wheel, wheel};
  s.rail = mounted_rails;
  s.rail_inclination_rad = 0.0;  // the rails are already mounted (inclined, origin at the top)
  return s;
}

// into := (w_into into + w_from from) / (w_into + w_from) on into's grid, `from` interpolated by arc length (the
// sub-steps of a wheel step, §8.12, each have the grid of their own profile)
void MeanResampled(WearDistribution* into, double w_into, const WearDistribution& from, double w_from) {
  for (size_t i = 0; i < into->size(); ++i)
    into->depth_m[i] = (w_into * into->depth_m[i] + w_from * from.at(into->s(i))) / (w_into + w_from);
}

// Every class's kinematics on one geometry, in parallel (one class per thread); a class that throws is an InputError
// naming the wheel step and the class.
std::vector<KinematicsSeries> ClassKinematics(const WheelsetTrackGeometry& geometry, const Scenario& scenario,
                                              const KinematicsFunction& kinematics, int step) {
  const int nc = static_cast<int>(scenario.classes.size());
  std::vector<KinematicsSeries> series(nc);
  std::vector<std::string> errors(nc);
#pragma omp parallel for schedule(dynamic, 1)
  for (int c = 0; c < nc; ++c) {
    try {
      series[c] = kinematics(geometry, scenario.classes[c], c);
    } catch (const std::exception& e) {
      errors[c] = e.what();
    }
  }
  for (int c = 0; c < nc; ++c)
    if (!errors[c].empty())
      throw InputError("wear step " + std::to_string(step) + ": kinematics of class " + scenario.classes[c].name +
                       ": " + errors[c]);
  return series;
}

// Half-cosine taper of the depth over `taper` at both ends of the profile (WearSimulationOptions::edge_taper_m).
void TaperEdges(WearDistribution* depth, double taper) {
  if (!(taper > 0.0)) return;
  const double L = depth->length_m();
  for (size_t i = 0; i < depth->size(); ++i) {
    const double e = std::min(depth->s(i), L - depth->s(i));
    if (e < taper) depth->depth_m[i] *= 0.5 - 0.5 * std::cos(M_PI * e / taper);
  }
}

}  // namespace

WearSimulationResult RunWearSimulation(const Scenario& scenario, const WearSimulationOptions& options,
                                       const WearContactFunction& contact, const KinematicsFunction& kinematics_in) {
  scenario.validate();
  const int steps = options.steps >= 0 ? options.steps : scenario.update.steps;
  const double total_km = options.total_km >= 0.0 ? options.total_km : scenario.update.total_km;
  if (steps < 1) throw InputError("wear simulation: steps must be >= 1");
  if (!IsWearContactModel(options.contact.model))
    throw InputError(std::string("contact model '") + to_string(options.contact.model) +
                     "' solves the normal problem only (no creep forces, no wear); the wear loop needs one of " +
                     WearContactModelNames());
  // A depth smoothing wavelength longer than the wheel profile flattens the whole distribution and makes the
  // smoothing spline's matrix singular (seen at 10 m): an input error, not an internal one.
  if (scenario.update.smoothing_cutoff_m > scenario.wheel.length())
    throw InputError("scenario " + scenario.source + ": update.smoothing_mm = " +
                     MessageNumber(scenario.update.smoothing_cutoff_m * 1e3) +
                     " mm is longer than the wheel profile (arc length " + MessageNumber(scenario.wheel.length() * 1e3) +
                     " mm); use 0 (no smoothing) up to that length, typically 1.5-7.5 mm");
  auto fallbacks = std::make_shared<KinematicsFallbackLog>();
  const KinematicsFunction kinematics =
      kinematics_in ? kinematics_in
      : options.kinematics_factory
          ? options.kinematics_factory(scenario, CurvingContactModel(scenario, options.contact.model), contact, fallbacks)
          : MakeScenarioKinematics(scenario, CurvingContactModel(scenario, options.contact.model), contact, fallbacks);

  StepWearOptions step_options;
  step_options.contact = options.contact;
  ApplyScenarioContact(scenario, &step_options.contact);
  step_options.load_acceptance = scenario.load_acceptance;
  step_options.wear = scenario.wear;
  step_options.grid_spacing_m = options.grid_spacing_m;

  WearSimulationResult result;
  result.initial_wheel = scenario.wheel;
  result.initial_dimensions = MeasureWheelDimensions(scenario.wheel);
  {
    const WheelsetTrackGeometry g0(scenario.MakeTrackSetup());
    result.initial_rail = {g0.mounted_rail(Side::Left), g0.mounted_rail(Side::Right)};
  }
  std::array<Profile, 2> rails = result.initial_rail;
  const int rail_steps = scenario.rail_steps.fixed ? 1 : scenario.rail_steps.steps;

  for (int k = 0; k < rail_steps; ++k) {
    Profile wheel = scenario.wheel;
    double km = 0.0;
    std::array<std::vector<WearDistribution>, 2> rail_wear;
    std::vector<double> rail_weights;
    for (int j = 1; j <= steps; ++j) {
      if (total_km > 0.0 && km >= total_km * (1.0 - 1e-12)) break;
      const auto t0 = std::chrono::steady_clock::now();
      const size_t fallbacks_before = fallbacks->size();
      const Profile step_start = wheel;
      const int substeps = scenario.update.substeps;
      WearStepRecord rec;
      rec.rail_step = k;
      rec.step = j;
      rec.depth_cap_m = 0.0;
      // update.substeps (docs/physics-reference.md §8.12): the step's wear in `substeps` sub-steps of cap / substeps,
      // each with its own kinematics and wear on the profile the previous one left
      for (int m = 0; m < substeps; ++m) {
        if (m > 0 && total_km > 0.0 && km >= total_km * (1.0 - 1e-12)) break;
        const WheelsetTrackGeometry geometry(SetupWith(scenario, wheel, rails));
        const std::vector<KinematicsSeries> series = ClassKinematics(geometry, scenario, kinematics, j);
        const StepWear wear = ComputeStepWear(geometry, scenario.classes, series, step_options, contact);

        ProfileUpdateOptions uo;
        uo.max_depth_per_step_m = scenario.update.cap_m / substeps;  // (exact for one sub-step)
        uo.smoothing.cutoff_wavelength_m = scenario.update.smoothing_cutoff_m;
        uo.validity.max_curvature_1_m = scenario.update.max_curvature_1_m;
        uo.cut_conserves_area = scenario.update.overhang_cut_conserves_area;
        uo.step_index = j;
        if (total_km > 0.0) uo.max_distance_step_m = (total_km - km) * 1e3;
        WearDistribution depth = wear.wheel.wheel_depth_per_metre;
        TaperEdges(&depth, options.edge_taper_m);
        ProfileUpdateResult up = UpdateProfile(wheel, depth, 1.0, uo);
        for (int h = 0; h < options.invalid_step_halvings && up.status == ProfileUpdateStatus::InvalidProfile; ++h) {
          uo.max_depth_per_step_m *= 0.5;
          up = UpdateProfile(wheel, depth, 1.0, uo);
        }

        rec.samples += wear.samples;
        rec.failed_contacts += wear.failed_contacts;
        rec.approximate_contacts += wear.approximate_contacts;
        rec.hertz_fallback_contacts += wear.hertz_fallback_contacts;
        for (int i = 0; i < kContactModelCount; ++i) rec.patches_by_model[i] += wear.patches_by_model[i];
        rec.validity = up.validity;
        rec.depth_cap_m += uo.max_depth_per_step_m;
        rec.overhang_cut_area_m2 += up.overhang_cut_area_m2;
        rec.cut_area_scale = m == 0 ? up.cut_area_scale : std::min(rec.cut_area_scale, up.cut_area_scale);
        rec.cut_area_conserved = rec.cut_area_conserved && up.cut_area_conserved;
        if (m == 0) {
          rec.wheel_depth_per_metre = wear.wheel.wheel_depth_per_metre;
          rec.rail_depth_per_passage = {wear.side[0].rail_depth_per_passage, wear.side[1].rail_depth_per_passage};
          rec.removed_depth = up.removed_depth;
        }
        if (up.status != ProfileUpdateStatus::Updated) {
          result.status = up.status == ProfileUpdateStatus::NoWear ? WearSimulationStatus::NoWear
                                                                     : WearSimulationStatus::InvalidProfile;
          result.message = "rail step " + std::to_string(k) + ", wheel step " + std::to_string(j) +
                           (substeps > 1 ? ", sub-step " + std::to_string(m + 1) : std::string()) + ": " + up.message;
          return result;
        }
        rail_wear[0].push_back(wear.side[0].rail_depth_per_passage);
        rail_wear[1].push_back(wear.side[1].rail_depth_per_passage);
        rail_weights.push_back(up.distance_step_m);
        if (m > 0) {
          // the step's wear rate: distance-weighted mean of the sub-steps'; its removed depth: their sum (each on the
          // grid of the step's first profile, by arc length)
          const double w_old = rec.step_km * 1e3, w_new = up.distance_step_m;
          MeanResampled(&rec.wheel_depth_per_metre, w_old, wear.wheel.wheel_depth_per_metre, w_new);
          for (int side = 0; side < 2; ++side)
            MeanResampled(&rec.rail_depth_per_passage[side], w_old, wear.side[side].rail_depth_per_passage, w_new);
          for (size_t i = 0; i < rec.removed_depth.size(); ++i)
            rec.removed_depth.depth_m[i] += up.removed_depth.at(rec.removed_depth.s(i));
        }
        wheel = up.profile;
        km += up.distance_step_m * 1e-3;
        rec.step_km += up.distance_step_m * 1e-3;
        if (substeps == 1) rec.max_depth_m = up.max_depth_m;
      }
      for (const KinematicsFallbackLog::Entry& e : fallbacks->since(fallbacks_before))
        rec.kinematics_fallback_reasons.push_back(KinematicsFallbackLog::describe(e));
      rec.kinematics_fallbacks = static_cast<int>(rec.kinematics_fallback_reasons.size());
      rec.km = km;
      if (substeps > 1) {
        const WheelWearDepths step_depth = MeasureWheelWear(step_start, wheel);
        rec.max_depth_m = std::max(step_depth.tread_m, step_depth.flange_m);
      }
      rec.wheel = wheel;
      rec.dimensions = MeasureWheelDimensions(wheel);
      const WheelWearDepths wd = MeasureWheelWear(scenario.wheel, wheel);
      rec.tread_wear_m = wd.tread_m;
      rec.tread_hollows = wd.tread_hollows;
      rec.flange_wear_m = wd.flange_m;
      rec.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      result.steps.push_back(rec);
      if (options.on_step) options.on_step(result.steps.back());
    }
    if (!scenario.rail_steps.fixed) {
      double wsum = 0.0;
      for (double w : rail_weights) wsum += w;
      std::vector<double> weights;
      for (double w : rail_weights) weights.push_back(w / wsum);
      RailStepOptions ro;
      ro.max_depth_per_step_m = scenario.rail_steps.cap_m;
      ro.smoothing.cutoff_wavelength_m = scenario.update.smoothing_cutoff_m;
      ro.validity.max_curvature_1_m = scenario.update.max_curvature_1_m;
      ro.output_spacing_m = scenario.rail_steps.output_spacing_m;
      ro.step_index = k;
      std::array<Profile, 2> next = rails;
      for (int side = 0; side < 2; ++side) {
        const RailStepResult rr = UpdateRail(rails[side], rail_wear[side], weights, 1.0, ro);
        if (rr.status == ProfileUpdateStatus::InvalidProfile) {
          result.status = WearSimulationStatus::InvalidProfile;
          result.message = "rail step " + std::to_string(k) + ": " + rr.message;
          return result;
        }
        next[side] = rr.rail;
        result.rail_results.push_back(rr);
      }
      rails = next;
      result.rails.push_back(rails);
    }
  }
  return result;
}

}  // namespace conforma
