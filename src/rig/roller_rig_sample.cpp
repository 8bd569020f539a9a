// One roller-rig sample: kinematics and contacts, wear of wheel and roller, profile update with the sliding-mean
// filter (roller_rig_sample.hpp; paper 000 §3.4 eqs. 7-17, §3.5 eqs. 18-21).
#include "conforma/roller_rig_sample.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/profile_update.hpp"
#include "conforma/wear_law.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {

namespace {
constexpr double kTwoPi = 6.283185307179586476925;
}

const char* to_string(RollerRigWearLaw law) { return law == RollerRigWearLaw::Archard ? "archard" : "wear_index"; }

RollerRigWearLaw RollerRigWearLawFromName(const std::string& name) {
  if (name == "archard") return RollerRigWearLaw::Archard;
  if (name == "wear_index" || name == "tgamma" || name == "usfd") return RollerRigWearLaw::WearIndex;
  throw InputError("unknown rig wear law '" + name + "' (archard, wear_index)");
}

const char* to_string(RollerRigSampleStatus status) {
  switch (status) {
    case RollerRigSampleStatus::Ok: return "ok";
    case RollerRigSampleStatus::ContactFailed: return "contact_failed";
    case RollerRigSampleStatus::ProfileUpdateFailed: return "profile_update_failed";
  }
  return "unknown";
}

void RollerRigSampleOptions::validate() const {
  setup.validate();
  kinematics.validate();
  require_positive(wear_grid_spacing_m, "RollerRigSampleOptions.wear_grid_spacing_m");
  if (filter_every_steps < 1) throw InputError("RollerRigSampleOptions.filter_every_steps must be >= 1");
  if (profile_update_every_steps < 1) throw InputError("RollerRigSampleOptions.profile_update_every_steps must be >= 1");
  require_non_negative(refit_depth_fraction, "RollerRigSampleOptions.refit_depth_fraction");
  require_non_negative(filter_window_m, "RollerRigSampleOptions.filter_window_m");
  require_positive(max_depth_per_approach, "RollerRigSampleOptions.max_depth_per_approach");
  if (!(strip_mean_elements >= 1.0) || !std::isfinite(strip_mean_elements))
    throw InputError("RollerRigSampleOptions.strip_mean_elements must be finite and >= 1 (paper 000 eq. 16: C)");
}

RollerRigSampleOptions RollerRigSampleOptions::Defaults(const RollerRigSetup& setup) {
  RollerRigSampleOptions o;
  o.setup = setup;
  o.kinematics.contact = RollerRigContactOptions(setup);
  o.wear_grid_spacing_m = 0.1e-3 * setup.length_factor;
  o.filter_window_m = 5.0e-3 * setup.length_factor;
  return o;
}

int RollerRigFilterSteps(double step_s) {
  require_positive(step_s, "rig step");
  return std::max(1, static_cast<int>(std::lround(0.2 / step_s)));  // paper 000 §3.5: every 10 steps of 20 ms
}

namespace {

// Real time (the profiles in contact take the raw wear between the filters, profile_update_every_steps <
// filter_every_steps): the geometry is updated where the wear moved the profiles (WheelsetTrackGeometry's update
// constructor). Otherwise (the test plan's 0.2 s steps, updates at the filters only) every update rebuilds it.
// In both, the uninclined rollers are mounted by an exact translation: a refit of the translated samples resamples the
// curve and changes the curvature of a worn band by up to ~0.3 %, which the Hertz model reads as new sharp contacts
// (with the refit the test plan lost contact in tests 4 and 5; docs/physics-reference.md §18.6).
bool RealTimeUpdates(const RollerRigSampleOptions& o) { return o.profile_update_every_steps < o.filter_every_steps; }

std::shared_ptr<const WheelsetTrackGeometry> BuildGeometry(const RollerRigSampleOptions& o, std::array<Profile, 2> w,
                                                           std::array<Profile, 2> r) {
  GeometryOptions g = RollerRigGeometryOptions(o.setup);
  g.refit_uninclined_rail = false;  // exact translation (above)
  return std::make_shared<const WheelsetTrackGeometry>(MakeRollerRigTrack(o.setup, std::move(w), std::move(r)), g);
}

WearModel RigWearModel(const RollerRigSampleOptions& o) {
  WearModel m;
  if (o.wear_law == RollerRigWearLaw::Archard) {
    m.wheel_law.kind = WearLawKind::Archard;
    m.wheel_law.archard = ArchardMap::Paper000Wheel();
    m.rail_law.kind = WearLawKind::Archard;
    m.rail_law.archard = ArchardMap::Paper000Roller();
  }  // else: the default WearLaw, the USFD wear-index table, for both bodies
  m.wheel_material = o.setup.wheel_material;
  m.rail_material = o.setup.roller_material;
  return m;
}

// Paper 000 eqs. 19-21 on the stored samples of the reference profile: each sample moved by the depth along its
// outward normal. The samples stay uniform in arc length up to the depth (nm to um per step, far below the 0.02 mm
// spacing), so they are taken as the new profile's nodes without a refit (Profile::FromArcLengthSamples): the
// refit of RemoveAlongNormal runs at the filter steps only.
Profile RemoveRaw(const Profile& reference, const WearDistribution& depth) {
  std::vector<Eigen::Vector2d> pts = reference.samples();
  const double h = reference.spacing();
  for (size_t i = 0; i < pts.size(); ++i) {
    const double si = std::min(h * static_cast<double>(i), reference.length());
    pts[i] -= depth.at(si) * reference.normal(si);
  }
  return Profile::FromArcLengthSamples(pts, reference.kind(), reference.source());
}

// The same removal for the real-time steps between filters: only the samples where the depth is not zero move (the
// others would move by 0), on the reference's arc-length grid with its splines re-solved around them
// (Profile::WithMovedSamples), so that the geometry is updated only there. *changed: the lateral interval outside
// which the result coincides with the reference bit for bit: the samples whose spline values were solved again (the
// moved ones and Profile::kMovedSplineMargin either side), one more either side, and a spacing more.
Profile RemoveRawLocal(const Profile& reference, const WearDistribution& depth, LateralInterval* changed) {
  *changed = LateralInterval{};
  const size_t nd = depth.size();
  size_t first = nd, last = 0;
  for (size_t i = 0; i < nd; ++i)
    if (depth.depth_m[i] != 0.0) {
      first = std::min(first, i);
      last = i;
    }
  if (first == nd) return reference;
  // depth.at(s) is zero outside (s_{first-1}, s_{last+1})
  const double h = reference.spacing();
  const long n = static_cast<long>(reference.sample_count());
  const long j0 = std::max(0L, static_cast<long>(std::floor(depth.s(first > 0 ? first - 1 : 0) / h)));
  const long j1 = std::min(n - 1, static_cast<long>(std::ceil(depth.s(std::min(last + 1, nd - 1)) / h)));
  std::vector<Eigen::Vector2d> moved(static_cast<size_t>(j1 - j0 + 1));
  for (long j = j0; j <= j1; ++j) {
    const double sj = std::min(h * static_cast<double>(j), reference.length());
    moved[j - j0] = reference.sample_at(j) - depth.at(sj) * reference.normal(sj);
  }
  Profile out = reference.WithMovedSamples(static_cast<size_t>(j0), moved);
  const long margin = Profile::kMovedSplineMargin + 1;
  for (long j = std::max(0L, j0 - margin); j <= std::min(n - 1, j1 + margin); ++j)
    for (const double y : {reference.sample_at(j).x(), out.sample_at(j).x()}) {
      changed->lo_m = changed->empty() ? y : std::min(changed->lo_m, y);
      changed->hi_m = changed->empty() ? y : std::max(changed->hi_m, y);
    }
  changed->lo_m -= h;
  changed->hi_m += h;
  return out;
}

// Arc length on a profile of a lateral position; the cells of one strip share it, so answers are kept per value.
class ArcLengthOf {
 public:
  explicit ArcLengthOf(const Profile& p) : p_(p) {}
  std::optional<double> operator()(double y) {
    const auto it = known_.find(y);
    if (it != known_.end()) return it->second;
    return known_[y] = p_.s_at(y);
  }

 private:
  const Profile& p_;
  std::unordered_map<double, std::optional<double>> known_;
};

}  // namespace

WearDistribution SlidingMean(const WearDistribution& depth, double window_m) {
  require_non_negative(window_m, "sliding-mean window");
  const long n = static_cast<long>(depth.size());
  const long m = depth.spacing_m > 0.0 ? static_cast<long>(std::floor(0.5 * window_m / depth.spacing_m + 1e-9)) : 0;
  if (m < 1 || n < 3) return depth;
  WearDistribution out = depth;
  std::vector<double> prefix(n + 1, 0.0);
  for (long i = 0; i < n; ++i) prefix[i + 1] = prefix[i] + depth.depth_m[i];
  for (long i = 0; i < n; ++i) {
    const long h = std::min({m, i, n - 1 - i});  // symmetric window, shrinking at the ends
    out.depth_m[i] = (prefix[i + h + 1] - prefix[i - h]) / static_cast<double>(2 * h + 1);
  }
  return out;
}

RollerRigState MakeRollerRigState(const RollerRigSampleOptions& options, const std::array<Profile, 2>& wheel,
                                  const std::array<Profile, 2>& roller) {
  options.validate();
  RollerRigState s;
  s.wheel = s.wheel_reference = wheel;
  s.roller = s.roller_reference = roller;
  for (int k = 0; k < 2; ++k) {
    s.wheel_pending[k] = WearDistribution::ForProfile(wheel[k], options.wear_grid_spacing_m);
    s.roller_pending[k] = WearDistribution::ForProfile(roller[k], options.wear_grid_spacing_m);
  }
  s.geometry = BuildGeometry(options, wheel, roller);
  return s;
}

RollerRigState MakeRollerRigState(const RollerRigSampleOptions& options) {
  const Profile w = MakeRollerRigWheelProfile(options.setup), r = MakeRollerRigRollerProfile(options.setup);
  return MakeRollerRigState(options, {w, w}, {r, r});
}

namespace {
constexpr double kMaxDepthPerSample_m = 1e-3;
}  // namespace

RollerRigSampleResult ProcessRigSample(const RollerRigSampleOptions& options, RollerRigState* state,
                                       const RollerRigSample& sample) {
  options.validate();
  if (state == nullptr || !state->geometry) throw InputError("ProcessRigSample: no rig state (MakeRollerRigState)");
  require_positive(sample.duration_s, "rig sample duration_s");
  require_finite(sample.time_s, "rig sample time_s");
  RollerRigSampleResult res;
  RollerRigKinematicsInput in;
  in.lateral_m = sample.lateral_m;
  in.yaw_rad = sample.yaw_rad;
  in.lateral_velocity_m_s = sample.lateral_velocity_m_s;
  in.roller_speed_rad_s = sample.roller_speed_rad_s;
  in.wheel_load_N = sample.wheel_load_N;
  in.wheelset_speed_rad_s = sample.wheelset_speed_rad_s;
  RollerRigKinematicsOptions ko = options.kinematics;
  ko.contact.keep_fields = true;
  ko.contact.solve_tangential = true;
  const WheelsetTrackGeometry& geometry = *state->geometry;
  res.kinematics = SolveRollerRigKinematics(geometry, options.setup, in, ko);
  res.step = state->step;
  if (res.kinematics.status != RollerRigKinematicsStatus::Converged &&
      res.kinematics.status != RollerRigKinematicsStatus::Measured) {
    res.status = RollerRigSampleStatus::ContactFailed;
    res.message = std::string("rig kinematics ") + to_string(res.kinematics.status) + ": " + res.kinematics.message;
    return res;
  }

  // ---- wear of this step (paper 000 eqs. 7-17)
  const WearModel model = RigWearModel(options);
  // eq. 16's C belongs to Table 3's calibration; the USFD law is calibrated on the integrated depth (paper 003)
  const double strip_c = options.wear_law == RollerRigWearLaw::Archard ? options.strip_mean_elements : 1.0;
  const double dt = sample.duration_s;
  const double w3 = res.kinematics.wheelset_speed_rad_s;
  std::array<WearDistribution, 2> wheel_add, roller_add;
  bool any_wear = false;
  for (Side side : {Side::Left, Side::Right}) {
    const int k = side_index(side);
    const RollerRigContactResult& c = res.kinematics.contact[k];
    const Profile& mounted = geometry.mounted_rail(side);
    // the mounted roller is the current profile translated (inclination 0): the same material point starts both
    const double mounted_to_profile_y = state->roller[k].position(0.0).x() - mounted.position(0.0).x();
    WearPatch patch;
    patch.rolling_speed_m_s = c.roller_surface_speed_m_s;
    patch.wheel_radius_m = c.wheel_rolling_radius_m;
    ArcLengthOf wheel_s(state->wheel_reference[k]), roller_s(state->roller_reference[k]);
    for (const PatchReport& p : c.report.patches) {
      for (const ContactCell& cell : p.cells) {
        if (cell.slip_x == 0.0 && cell.slip_s == 0.0) continue;  // adhesion: Archard and USFD remove nothing
        const double sv = std::hypot(cell.slip_x, cell.slip_s) * c.roller_surface_speed_m_s;
        res.max_slip_velocity_m_s[k] = std::max(res.max_slip_velocity_m_s[k], sv);
        const std::optional<double> s_w = wheel_s(cell.wheel_y_m);
        const std::optional<double> s_r = roller_s(mounted.position(cell.rail_s_m).x() + mounted_to_profile_y);
        if (!s_w || !s_r) continue;  // outside a profile (not expected on the tread); counted by none
        WearCell wc = WearCellOf(cell, *s_w);
        wc.rail_s_m = *s_r;  // on the roller's own profile (the cell's rail_s_m is on the mounted roller)
        patch.cells.push_back(wc);
      }
    }
    wheel_add[k] = WearDistribution::Zero(state->wheel_pending[k].length_m(), state->wheel_pending[k].spacing_m);
    roller_add[k] = WearDistribution::Zero(state->roller_pending[k].length_m(), state->roller_pending[k].spacing_m);
    if (patch.cells.empty()) continue;
    const PatchWear pw = ComputePatchWear(patch, model, state->wheel_pending[k], state->roller_pending[k]);
    // paper 000 eq. 17: passages in dt, omega dt / (2 pi), for the wheel ring and the roller ring
    // (Archard with Table 3: divided by C of eq. 16, options.strip_mean_elements)
    wheel_add[k].add(pw.wheel_depth_per_passage, w3 * dt / kTwoPi / strip_c);
    roller_add[k].add(pw.rail_depth_per_passage, sample.roller_speed_rad_s[k] * dt / kTwoPi / strip_c);
    res.wheel_wear_max_depth_m[k] = wheel_add[k].max_depth_m();
    res.roller_wear_max_depth_m[k] = roller_add[k].max_depth_m();
    res.wheel_wear_area_m2[k] = wheel_add[k].area_m2();
    res.roller_wear_area_m2[k] = roller_add[k].area_m2();
    res.wheel_wear_volume_m3[k] = res.wheel_wear_area_m2[k] * kTwoPi * c.wheel_rolling_radius_m;
    res.roller_wear_volume_m3[k] = res.roller_wear_area_m2[k] * kTwoPi * c.roller_rolling_radius_m;
    any_wear = any_wear || res.wheel_wear_area_m2[k] > 0.0 || res.roller_wear_area_m2[k] > 0.0;
  }
  // stability rule of the explicit update (options.max_depth_per_approach): depth added per step against the
  // elastic approach of the side's most loaded patch
  for (int k = 0; k < 2; ++k) {
    if (const PatchReport* p = MainPatch(res.kinematics.contact[k].report)) res.elastic_approach_m[k] = p->approach_m;
    const double added = res.wheel_wear_max_depth_m[k] + res.roller_wear_max_depth_m[k];
    if (added <= 0.0) continue;
    const double ratio =
        res.elastic_approach_m[k] > 0.0 ? added / res.elastic_approach_m[k] : std::numeric_limits<double>::infinity();
    res.depth_per_approach = std::max(res.depth_per_approach, ratio);
  }
  res.stability_rule_violated = res.depth_per_approach > options.max_depth_per_approach;
  // a sample that removes more than a millimetre at once is no rig time step (duration_s = 1e300 removed 2e289 m and
  // destroyed the rig's profiles, fuzzing, session 25): refused before the state changes
  for (int k = 0; k < 2; ++k)
    if (!(res.wheel_wear_max_depth_m[k] + res.roller_wear_max_depth_m[k] <= kMaxDepthPerSample_m)) {
      char text[260];
      std::snprintf(text, sizeof text, "rig sample duration_s = %g s removes %g m at once (wheel and roller, %s side), "
                    "more than %g m: not a rig time step (the rig's profiles are left as they were)",
                    sample.duration_s, res.wheel_wear_max_depth_m[k] + res.roller_wear_max_depth_m[k],
                    k == 0 ? "left" : "right", kMaxDepthPerSample_m);
      throw InputError(text);
    }

  // ---- profile update (paper 000 §3.5). The new values are built aside and committed together, so that a failed
  // update leaves the state as it was; profiles are copied only where they change (not the whole state every step).
  std::array<WearDistribution, 2> wheel_pending = state->wheel_pending, roller_pending = state->roller_pending;
  for (int k = 0; k < 2; ++k) {
    wheel_pending[k].add(wheel_add[k], 1.0);
    roller_pending[k].add(roller_add[k], 1.0);
  }
  const long step = state->step + 1;
  std::array<double, 2> wheel_unrefit = state->wheel_unrefit_m, roller_unrefit = state->roller_unrefit_m;
  std::array<std::optional<Profile>, 2> wheel_reference, roller_reference, wheel_now, roller_now;
  std::array<LateralInterval, 2> wheel_changed, roller_changed;  // where the raw removal changed the profiles
  std::shared_ptr<const WheelsetTrackGeometry> next_geometry = state->geometry;
  if (options.update_profiles) {
    try {
      const bool filter_now = step % options.filter_every_steps == 0;
      const bool raw_now = !filter_now && any_wear && step % options.profile_update_every_steps == 0;
      // Real time (RealTimeUpdates): a filter without refit, too, moves only the worn samples on the reference's
      // grid, and the geometry is solved again only where they moved; a refit changes a whole profile and rebuilds
      // the geometry. Otherwise every filter rebuilds it.
      const bool local_updates = RealTimeUpdates(options);
      bool rebuild = !local_updates;
      for (int k = 0; k < 2; ++k) {
        if (filter_now) {
          // sliding mean of the wear since the last filter, removed from the reference profiles for good
          const WearDistribution fw = SlidingMean(wheel_pending[k], options.filter_window_m);
          const WearDistribution fr = SlidingMean(roller_pending[k], options.filter_window_m);
          // removal without refit while the depth moved since the last refit stays below refit_depth_fraction of
          // the sample spacing; then RemoveAlongNormal (refit, arc-length reparametrisation, validity checks)
          auto remove = [&](const Profile& ref, const WearDistribution& d, double* unrefit, LateralInterval* changed,
                            const char* what) {
            if (*unrefit + d.max_depth_m() < options.refit_depth_fraction * ref.spacing()) {
              *unrefit += d.max_depth_m();
              return local_updates ? RemoveRawLocal(ref, d, changed) : RemoveRaw(ref, d);
            }
            *unrefit = 0.0;
            rebuild = true;
            return RemoveAlongNormal(ref, d, 0.0, what);
          };
          if (fw.max_depth_m() > 0.0)
            wheel_reference[k] =
                remove(state->wheel_reference[k], fw, &wheel_unrefit[k], &wheel_changed[k], "rig wheel filter");
          if (fr.max_depth_m() > 0.0)
            roller_reference[k] =
                remove(state->roller_reference[k], fr, &roller_unrefit[k], &roller_changed[k], "rig roller filter");
          const Profile& w = wheel_reference[k] ? *wheel_reference[k] : state->wheel_reference[k];
          const Profile& r = roller_reference[k] ? *roller_reference[k] : state->roller_reference[k];
          wheel_now[k] = w;
          roller_now[k] = r;
          wheel_pending[k] = WearDistribution::ForProfile(w, options.wear_grid_spacing_m);
          roller_pending[k] = WearDistribution::ForProfile(r, options.wear_grid_spacing_m);
        } else if (raw_now) {
          // eqs. 19-21: the raw depth since the last filter along the normal of the reference profile; only the
          // samples under the worn band move, and only the geometry there is solved again (below)
          if (wheel_pending[k].max_depth_m() > 0.0)
            wheel_now[k] = RemoveRawLocal(state->wheel_reference[k], wheel_pending[k], &wheel_changed[k]);
          if (roller_pending[k].max_depth_m() > 0.0)
            roller_now[k] = RemoveRawLocal(state->roller_reference[k], roller_pending[k], &roller_changed[k]);
        }
      }
      res.filtered = filter_now;
      res.profiles_updated = filter_now || raw_now;
      if (res.profiles_updated) {
        auto now = [](const std::optional<Profile>& p, const Profile& old) -> const Profile& { return p ? *p : old; };
        std::array<Profile, 2> w{now(wheel_now[0], state->wheel[0]), now(wheel_now[1], state->wheel[1])};
        std::array<Profile, 2> r{now(roller_now[0], state->roller[0]), now(roller_now[1], state->roller[1])};
        if (rebuild)
          next_geometry = BuildGeometry(options, std::move(w), std::move(r));
        else  // the profiles differ from the last geometry's within the changed intervals only
          next_geometry = std::make_shared<const WheelsetTrackGeometry>(
              *state->geometry, MakeRollerRigTrack(options.setup, std::move(w), std::move(r)), wheel_changed,
              roller_changed);
      }
    } catch (const InputError& e) {
      res.status = RollerRigSampleStatus::ProfileUpdateFailed;
      res.message = e.what();
      res.profiles_updated = res.filtered = false;
      return res;  // the state keeps its previous profiles
    }
  }
  for (int k = 0; k < 2; ++k) {
    if (wheel_reference[k]) state->wheel_reference[k] = std::move(*wheel_reference[k]);
    if (roller_reference[k]) state->roller_reference[k] = std::move(*roller_reference[k]);
    if (wheel_now[k]) state->wheel[k] = std::move(*wheel_now[k]);
    if (roller_now[k]) state->roller[k] = std::move(*roller_now[k]);
    state->roller_distance_m[k] +=
        sample.roller_speed_rad_s[k] * dt * res.kinematics.contact[k].roller_rolling_radius_m;
  }
  state->wheel_pending = std::move(wheel_pending);
  state->roller_pending = std::move(roller_pending);
  state->wheel_unrefit_m = wheel_unrefit;
  state->roller_unrefit_m = roller_unrefit;
  state->geometry = std::move(next_geometry);
  state->step = step;
  state->time_s += dt;
  res.step = state->step;
  return res;
}

}  // namespace conforma
