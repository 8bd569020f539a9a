// One step of the wear loop: kinematics samples -> wheel contacts with fields -> wear cells -> class integration
// -> combination of the classes (wear_simulation.hpp; paper 001 eqs. 24-27, paper 003 §6 steps 1-3).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <mutex>
#include <string>
#include <utility>

#include "conforma/error.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {

WearCell WearCellOf(const ContactCell& c, double wheel_s_m) {
  WearCell w;
  w.traction_Pa = Eigen::Vector2d(c.traction_x_Pa, c.traction_s_Pa);
  w.slip = Eigen::Vector2d(c.slip_x, c.slip_s);
  w.pressure_Pa = c.pressure_Pa;
  w.area_m2 = c.area_m2;
  w.length_x_m = c.length_x_m;
  w.wheel_s_m = wheel_s_m;
  w.rail_s_m = c.rail_s_m;
  return w;
}

namespace {

// Wear samples of the two wheels of one kinematics sample.
struct SampleSlot {
  std::array<WearSample, 2> wheel;
  std::array<bool, 2> used{false, false};
  int failed = 0, approximate = 0, hertz_fallbacks = 0, patches = 0, slipping_cells = 0;
  std::array<int, kContactModelCount> patches_by_model{};
  double off_grid_m2 = 0.0;
  std::string error;
};

// Whether a wear law removes exactly nothing from a cell, known without evaluating it (so that leaving the cell
// out gives bit-identical wear: ComputePatchWear deposits only depths > 0). The wear-index laws depend on
// I_w = |p_t . s| alone (paper 003 eq. 14) and give K_w(0) at I_w = 0: nothing for every table whose first rate is
// 0 (USFD, ...); Archard's k p |s| / H (paper 000 eq. 8) is exactly 0 at s = 0, whatever the traction.
bool RemovesNothing(const WearLaw& law, bool zero_slip, bool zero_traction) {
  if (law.kind == WearLawKind::WearIndex) return (zero_slip || zero_traction) && law.wear_index.rate(0.0) == 0.0;
  return zero_slip;
}

void EvaluateSample(const WheelsetTrackGeometry& geometry, const TrackClass& track_class, const KinematicsSample& sample,
                    const StepWearOptions& options, const WearContactFunction& contact, SampleSlot* slot) {
  for (Side side : {Side::Left, Side::Right}) {
    const int k = side_index(side);
    const double load = sample.vertical_load_N[k];
    if (!(load > 0.0)) continue;  // unloaded wheel: no contact, no wear
    WheelContactOptions o = options.contact;
    o.keep_fields = true;
    o.solve_tangential = true;
    o.vertical_load_N = load;
    o.friction_coefficient = track_class.friction_coefficient;
    WheelContactReport report = contact(geometry, side, sample.pose, sample.velocity, o);
    // A wheel where the chosen model's load control fails outright (no bracket: no patch carries the load) is
    // solved with the Hertz model when options.hertz_fallback is set, and counted.
    if (report.status == WheelContactStatus::NotConverged && report.patches.empty() && options.hertz_fallback &&
        o.model != ContactModel::Hertz) {
      WheelContactOptions h = o;
      h.model = ContactModel::Hertz;
      report = contact(geometry, side, sample.pose, sample.velocity, h);
      if (report.status == WheelContactStatus::Ok) ++slot->hertz_fallbacks;
    }
    // Load control that stopped short (NotConverged: the contact-point set jumps between candidates on worn
    // profiles) is accepted when the carried load, the balanced force (WheelContactOptions::load_balance: the total
    // vertical force by default), is within load_acceptance of the target; otherwise the wheel contributes no wear
    // and is counted as failed. (The pressure part alone accepted a flange contact whose creep forces pull the
    // wheel down, total -7.5 kN under a 60 kN load, issue 15.)
    const double carried = BalancedVerticalForce(report, o);
    const bool near_load = report.status == WheelContactStatus::NotConverged &&
                           std::abs(carried - load) <= options.load_acceptance * load;
    if (report.status != WheelContactStatus::Ok && !near_load) {
      ++slot->failed;
      continue;
    }
    if (near_load) ++slot->approximate;
    const Profile& wheel = geometry.setup().wheel[k];
    WearSample ws;
    ws.distance_m = sample.weight;
    for (const PatchReport& p : report.patches) {
      WearPatch patch;
      patch.rolling_speed_m_s = sample.velocity.forward_speed_m_s;
      patch.wheel_radius_m = p.rolling_radius_m;
      for (const ContactCell& c : p.cells) {
        // Skip the cells where nothing slips (adhesion) or nothing is transmitted, when both laws remove exactly
        // nothing there (RemovesNothing): identical wear, less work.
        const bool zero_slip = c.slip_x == 0.0 && c.slip_s == 0.0;
        const bool zero_traction = c.traction_x_Pa == 0.0 && c.traction_s_Pa == 0.0;
        if ((zero_slip || zero_traction) && RemovesNothing(options.wear.wheel_law, zero_slip, zero_traction) &&
            RemovesNothing(options.wear.rail_law, zero_slip, zero_traction))
          continue;
        const std::optional<double> s_w = wheel.s_at(c.wheel_y_m);
        if (!s_w) {
          slot->off_grid_m2 += c.area_m2;
          continue;
        }
        patch.cells.push_back(WearCellOf(c, *s_w));
      }
      ++slot->patches;
      ++slot->patches_by_model[static_cast<int>(p.model)];
      slot->slipping_cells += static_cast<int>(patch.cells.size());
      if (!patch.cells.empty()) ws.patches.push_back(std::move(patch));
    }
    slot->wheel[k] = std::move(ws);
    slot->used[k] = true;
  }
}

// For each (class, sample) item: the index of the first earlier item of the same class whose sample has the same
// pose, velocity and wheel loads (exact equality), or -1.
std::vector<int> FirstEqualSample(const std::vector<KinematicsSeries>& series,
                                  const std::vector<std::pair<int, int>>& items) {
  using Key = std::array<std::uint64_t, 10>;  // bit patterns: -0.0 is not 0.0 here, NaN is ordered
  std::map<std::pair<int, Key>, int> first;
  std::vector<int> same_as(items.size(), -1);
  for (size_t it = 0; it < items.size(); ++it) {
    const KinematicsSample& s = series[items[it].first].samples[items[it].second];
    const std::array<double, 10> values = {s.pose.lateral_m, s.pose.vertical_m, s.pose.roll_rad, s.pose.yaw_rad,
                     s.velocity.forward_speed_m_s, s.velocity.lateral_velocity_m_s, s.velocity.yaw_rate_rad_s,
                     s.velocity.axle_angular_velocity_rad_s, s.vertical_load_N[0], s.vertical_load_N[1]};
    Key key;
    std::memcpy(key.data(), values.data(), sizeof key);
    const auto inserted = first.emplace(std::make_pair(items[it].first, key), static_cast<int>(it));
    if (!inserted.second) same_as[it] = inserted.first->second;
  }
  return same_as;
}

TrackClassWear ZeroWear(const WearDistribution& wheel_grid, const WearDistribution& rail_grid) {
  TrackClassWear t;
  t.wheel_depth_per_metre = wheel_grid;
  t.rail_depth_per_passage = rail_grid;
  std::fill(t.wheel_depth_per_metre.depth_m.begin(), t.wheel_depth_per_metre.depth_m.end(), 0.0);
  std::fill(t.rail_depth_per_passage.depth_m.begin(), t.rail_depth_per_passage.depth_m.end(), 0.0);
  return t;
}

}  // namespace

StepWear ComputeStepWear(const WheelsetTrackGeometry& geometry, const std::vector<TrackClass>& classes,
                         const std::vector<KinematicsSeries>& series, const StepWearOptions& options,
                         const WearContactFunction& contact) {
  if (series.size() != classes.size()) throw InputError("wear step: one kinematics series per track class needed");
  const WearDistribution wheel_grid = WearDistribution::ForProfile(geometry.setup().wheel[0], options.grid_spacing_m);
  if (!WearDistribution::ForProfile(geometry.setup().wheel[1], options.grid_spacing_m).same_grid(wheel_grid))
    throw InputError("wear step: left and right wheel profiles must have the same arc length");
  std::array<WearDistribution, 2> rail_grid;
  for (Side side : {Side::Left, Side::Right})
    rail_grid[side_index(side)] = WearDistribution::ForProfile(geometry.mounted_rail(side), options.grid_spacing_m);

  // flat list of (class, sample), evaluated in parallel into fixed slots
  std::vector<std::pair<int, int>> items;
  for (size_t c = 0; c < classes.size(); ++c)
    for (size_t i = 0; i < series[c].samples.size(); ++i) {
      const KinematicsSample& s = series[c].samples[i];
      if (!(s.weight >= 0.0) || !std::isfinite(s.weight))
        throw InputError("wear step: class " + classes[c].name + " sample " + std::to_string(i) + ": bad weight");
      items.emplace_back(static_cast<int>(c), static_cast<int>(i));
    }
  // Samples of one class with the same pose, velocity and wheel loads give the same contact (the contact function
  // sees nothing else; it is deterministic): on tangent track every wheelset of the vehicle runs the same
  // oscillation, so the quasi-static provider repeats each phase once per wheelset. Each distinct sample is solved
  // once and its slot copied (bit-identical wear; its weight stays the sample's own).
  const std::vector<int> same_as = FirstEqualSample(series, items);
  std::vector<SampleSlot> slots(items.size());
  const int n = static_cast<int>(items.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (int it = 0; it < n; ++it) {
    if (same_as[it] >= 0) continue;
    try {
      EvaluateSample(geometry, classes[items[it].first], series[items[it].first].samples[items[it].second], options,
                     contact, &slots[it]);
    } catch (const std::exception& e) {
      slots[it].error = e.what();
    }
  }
  for (int it = 0; it < n; ++it) {
    if (same_as[it] < 0) continue;
    slots[it] = slots[same_as[it]];
    const double weight = series[items[it].first].samples[items[it].second].weight;
    for (WearSample& w : slots[it].wheel) w.distance_m = weight;
  }
  for (size_t it = 0; it < slots.size(); ++it)
    if (!slots[it].error.empty())
      throw InputError("wear step: class " + classes[items[it].first].name + ": " + slots[it].error);

  StepWear out;
  out.per_class.resize(classes.size());
  std::vector<TrackClassWear> left, right;
  std::vector<double> shares;
  size_t it = 0;
  for (size_t c = 0; c < classes.size(); ++c) {
    std::array<WearAccumulator, 2> acc = {WearAccumulator(wheel_grid, rail_grid[0], options.wear),
                                          WearAccumulator(wheel_grid, rail_grid[1], options.wear)};
    std::array<double, 2> distance{0.0, 0.0};
    for (; it < items.size() && items[it].first == static_cast<int>(c); ++it) {
      const SampleSlot& s = slots[it];
      out.failed_contacts += s.failed;
      out.approximate_contacts += s.approximate;
      out.hertz_fallback_contacts += s.hertz_fallbacks;
      out.patches += s.patches;
      for (int m = 0; m < kContactModelCount; ++m) out.patches_by_model[m] += s.patches_by_model[m];
      out.slipping_cells += s.slipping_cells;
      out.wheel_area_off_grid_m2 += s.off_grid_m2;
      for (int k = 0; k < 2; ++k) {
        if (!s.used[k]) continue;
        ++out.samples;
        acc[k].add(s.wheel[k]);
        distance[k] += s.wheel[k].distance_m;
      }
    }
    for (int k = 0; k < 2; ++k)
      out.per_class[c][k] = distance[k] > 0.0 ? acc[k].result() : ZeroWear(wheel_grid, rail_grid[k]);
    left.push_back(out.per_class[c][0]);
    right.push_back(out.per_class[c][1]);
    shares.push_back(classes[c].share);
  }
  out.side[0] = CombineTrackClasses(left, shares);
  out.side[1] = CombineTrackClasses(right, shares);
  // "the" wheel: the mean of the left and right wheels (both carry the same profile)
  out.wheel = ZeroWear(wheel_grid, rail_grid[0]);
  out.wheel.wheel_depth_per_metre.add(out.side[0].wheel_depth_per_metre, 0.5);
  out.wheel.wheel_depth_per_metre.add(out.side[1].wheel_depth_per_metre, 0.5);
  out.wheel.rail_depth_per_passage = out.side[0].rail_depth_per_passage;
  out.wheel.distance_m = out.side[0].distance_m + out.side[1].distance_m;
  out.wheel.area_outside_m2 = out.side[0].area_outside_m2 + out.side[1].area_outside_m2;
  return out;
}

KinematicsSeries CentredKinematics(const Scenario& scenario, const WheelsetTrackGeometry& geometry,
                                   const TrackClass& track_class) {
  // One representative wheelset (all wheelsets of the vehicle are identical in this provider).
  const double c = TrackClassCurvature(track_class);
  const double V = track_class.speed_m_s;
  const EquilibriumResult eq = geometry.SolveRigidEquilibrium(0.0, 0.0);
  KinematicsSeries s;
  s.source = "centred " + track_class.name;
  KinematicsSample k;
  k.wheelset = 0;
  k.weight = 1.0;
  if (eq.status != EquilibriumStatus::NoContact) k.pose = eq.pose;
  k.velocity.forward_speed_m_s = V;
  k.velocity.yaw_rate_rad_s = V * c;
  k.velocity.axle_angular_velocity_rad_s = V / scenario.vehicle.nominal_wheel_radius_m;
  k.vertical_load_N[0] = k.vertical_load_N[1] = scenario.vehicle.static_wheel_load_N();
  k.track_curvature_per_m = c;
  s.samples.push_back(k);
  return s;
}

QuasiStaticOptions ScenarioQuasiStaticOptions(const Scenario& scenario, ContactModel model) {
  QuasiStaticOptions qo;
  qo.contact.model = model;
  ApplyScenarioContact(scenario, &qo.contact);
  qo.tangent_amplitude_m = scenario.kinematics.tangent_amplitude_m;
  qo.tangent_phases = scenario.kinematics.tangent_phases;
  qo.cant_base_m = scenario.kinematics.cant_base_m;
  qo.free_axle_rotation = scenario.kinematics.free_axle_rotation;
  qo.axle_torque_Nm = scenario.kinematics.axle_torque_Nm;
  return qo;
}

std::string QuasiStaticRejection(const QuasiStaticResult& r) {
  static const char* const kResidualNames[8] = {"ws0 lateral", "ws0 yaw",         "ws0 axle torque", "ws1 lateral",
                                                "ws1 yaw",     "ws1 axle torque", "frame lateral",   "frame yaw"};
  std::string why;
  auto add = [&why](const std::string& s) { why += (why.empty() ? "" : "; ") + s; };
  char b[200];
  if (r.status == QuasiStaticStatus::NoContact && r.bogies.empty()) return "a wheel unloaded by the load transfer";
  if (r.series.samples.empty()) add("no kinematics samples");
  if (r.tangent_rolling_failures > 0)
    add(std::to_string(r.tangent_rolling_failures) + " tangent-track sample(s) without axle torque balance");
  for (const BogieQuasiStaticReport& bogie : r.bogies) {
    const std::string name = "bogie " + std::to_string(bogie.bogie);
    if (bogie.status == QuasiStaticStatus::NoContact) {
      add(name + ": a wheel without contact");
      continue;
    }
    if (bogie.derailed) add(name + ": a wheelset beyond its flange-contact shift + margin (derailed)");
    if (bogie.climbing) add(name + ": a wheelset climbing its flange (lateral force falls towards the flange)");
    if (!(bogie.max_residual <= kAcceptedCurvingResidual)) {
      int worst = 0;
      for (int k = 1; k < 8; ++k)
        if (std::fabs(bogie.residuals[k]) > std::fabs(bogie.residuals[worst])) worst = k;
      std::snprintf(b, sizeof b, "%s %s: max residual %.3g (%s) > %g", name.c_str(), to_string(bogie.status),
                    bogie.max_residual, kResidualNames[worst], kAcceptedCurvingResidual);
      add(b);
      if (bogie.failed_contact_evaluations > 0)
        why += ", " + std::to_string(bogie.failed_contact_evaluations) + " of " +
               std::to_string(bogie.contact_evaluations) + " wheel contact solves failed on the way";
    }
  }
  return why;
}

void KinematicsFallbackLog::add(Entry entry) {
  std::lock_guard<std::mutex> lock(mutex_);
  entries_.push_back(std::move(entry));
}

size_t KinematicsFallbackLog::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return entries_.size();
}

std::vector<KinematicsFallbackLog::Entry> KinematicsFallbackLog::since(size_t first) const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<Entry> out(entries_.begin() + static_cast<std::ptrdiff_t>(std::min(first, entries_.size())),
                         entries_.end());
  std::stable_sort(out.begin(), out.end(), [](const Entry& a, const Entry& b) { return a.class_index < b.class_index; });
  return out;
}

std::string KinematicsFallbackLog::describe(const Entry& e) {
  return e.class_name + ": " + e.reason + "; used the " + e.replacement;
}

KinematicsFunction MakeScenarioKinematics(const Scenario& scenario, ContactModel model, const WearContactFunction& contact,
                                          std::shared_ptr<KinematicsFallbackLog> fallbacks) {
  if (scenario.kinematics.provider == KinematicsProvider::Centred) {
    return [scenario](const WheelsetTrackGeometry& g, const TrackClass& tc, int) { return CentredKinematics(scenario, g, tc); };
  }
  if (scenario.kinematics.provider == KinematicsProvider::Dynamic)
    throw InputError("scenario " + scenario.source + ": kinematics.provider dynamic runs in the dynamics layer; "
                     "make the provider with MakeWearKinematics (dynamic_kinematics.hpp), e.g. through "
                     "WearSimulationOptions::kinematics_factory");
  if (scenario.kinematics.provider == KinematicsProvider::Kinematic) {
    return [scenario](const WheelsetTrackGeometry& g, const TrackClass& tc, int) {
      return KinematicCurvingEstimate(scenario, g, tc);
    };
  }
  const QuasiStaticOptions qo = ScenarioQuasiStaticOptions(scenario, model);
  // The standard pipeline goes through a WheelContactCache, one per class solve (one geometry, profiles fixed): the
  // equilibrium solver's forward differences in the axle speed repeat poses and its trust-region steps repeat whole
  // evaluations (42 % and 25 % of the calls on the default scenario); the cache returns bit-identical results.
  using PipelineFunction = WheelContactReport (*)(const WheelsetTrackGeometry&, Side, const WheelsetPose&,
                                                  const WheelsetVelocity&, const WheelContactOptions&);
  const PipelineFunction* target = contact.target<PipelineFunction>();
  const bool pipeline = target != nullptr && *target == &SolveWheelContact;
  struct AcceptedSolutions {  // last accepted series per class index (each entry written by its class only)
    std::mutex mutex;
    std::map<int, KinematicsSeries> series;
  };
  auto accepted = std::make_shared<AcceptedSolutions>();
  return [qo, scenario, contact, fallbacks, pipeline, accepted](const WheelsetTrackGeometry& g, const TrackClass& tc,
                                                                int class_index) {
    WheelContactCache cache;
    const WheelContactFunction f = [&contact, &cache, pipeline](const WheelsetTrackGeometry& gg, Side sd,
                                                                const WheelsetPose& p, const WheelsetVelocity& v,
                                                                const WheelContactOptions& o) {
      return pipeline ? SolveWheelContactCached(gg, sd, p, v, o, cache) : contact(gg, sd, p, v, o);
    };
    QuasiStaticResult r = SolveQuasiStaticCurving(scenario.vehicle, g, tc, qo, f);
    const std::string rejection = QuasiStaticRejection(r);
    std::lock_guard<std::mutex> lock(accepted->mutex);
    if (rejection.empty()) {
      accepted->series[class_index] = r.series;
      return r.series;
    }
    const auto previous = accepted->series.find(class_index);
    const bool has_previous = previous != accepted->series.end();
    if (fallbacks)
      fallbacks->add({class_index, tc.name, rejection, has_previous ? "previous solution" : "kinematic estimate"});
    if (has_previous) return previous->second;
    return KinematicCurvingEstimate(scenario, g, tc);
  };
}

}  // namespace conforma
