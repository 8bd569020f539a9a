// Accuracy check of a contact look-up table against the direct pipeline (contact_lut_check.hpp).
#include "conforma/contact_lut_check.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>

#include <omp.h>

#include "conforma/error.hpp"

namespace conforma {

namespace {

struct Sample {
  Side side = Side::Left;
  double y = 0.0, psi = 0.0, Q = 0.0;
  WheelsetVelocity velocity;
};

struct Outcome {
  bool lut_error = false, direct_ok = false, lut_ok = false, single = false, same = false, at_corner = false;
  std::vector<double> fn, fx, fy, rail_y;
  double lateral = 0.0;
  double direct_s = 0.0, lut_s = 0.0;
};

bool SameTopology(const std::vector<PatchReport>& a, const std::vector<PatchReport>& b, double match) {
  if (a.size() != b.size()) return false;
  for (size_t j = 0; j < a.size(); ++j)
    if (a[j].model != b[j].model || !(std::fabs(a[j].reference_s_on_rail_m - b[j].reference_s_on_rail_m) < match))
      return false;
  return true;
}

bool MatchesNode(const std::vector<PatchReport>& a, const LutNode& n, double match) {
  if (n.status != static_cast<int>(WheelContactStatus::Ok) || a.size() != n.patches.size()) return false;
  for (size_t j = 0; j < a.size(); ++j)
    if (static_cast<int>(a[j].model) != n.patches[j].model ||
        !(std::fabs(a[j].reference_s_on_rail_m - n.patches[j].rail_s_m) < match))
      return false;
  return true;
}

// v: (error, sample index) pairs
Percentiles Summarise(const std::vector<std::pair<double, long>>& e, const std::vector<Sample>& samples) {
  Percentiles p;
  p.count = static_cast<int>(e.size());
  if (e.empty()) return p;
  std::vector<double> v;
  long worst = e[0].second;
  double worst_value = -1.0;
  for (const auto& x : e) {
    v.push_back(x.first);
    if (x.first > worst_value) worst_value = x.first, worst = x.second;
  }
  const Sample& s = samples[worst];
  p.worst_side = side_index(s.side), p.worst_y_m = s.y, p.worst_yaw_rad = s.psi, p.worst_load_N = s.Q;
  std::sort(v.begin(), v.end());
  auto at = [&](double q) { return v[std::min(v.size() - 1, static_cast<size_t>(std::ceil(q * v.size())) - 1)]; };
  p.p50 = at(0.5), p.p90 = at(0.9), p.p95 = at(0.95), p.p99 = at(0.99), p.max = v.back();
  return p;
}

}  // namespace

void ContactLutCheckOptions::validate() const {
  if (samples < 1) throw InputError("lut check: samples must be >= 1");
  require_positive(speed_m_s, "lut check speed_m_s");
  require_non_negative(lateral_creep, "lut check lateral_creep");
  require_non_negative(curvature_per_m, "lut check curvature_per_m");
  require_non_negative(axle_creep, "lut check axle_creep");
  if (threads < 0) throw InputError("lut check: threads must be >= 0");
  contact.validate();
}

ContactLutCheckResult CheckContactLut(const ContactLut& lut, const WheelsetTrackGeometry& geometry,
                                      const ContactLutCheckOptions& options) {
  options.validate();
  const ContactLutGrid& g = lut.grid;
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  auto in = [&](const std::vector<double>& axis) { return axis.front() + unit(rng) * (axis.back() - axis.front()); };
  std::vector<Sample> samples(options.samples);
  const double V = options.speed_m_s;
  for (Sample& s : samples) {
    s.side = unit(rng) < 0.5 ? Side::Left : Side::Right;
    s.y = in(g.lateral_m);
    s.psi = in(g.yaw_rad);
    s.Q = in(g.load_N);
    s.velocity.forward_speed_m_s = V;
    s.velocity.lateral_velocity_m_s = V * options.lateral_creep * (2.0 * unit(rng) - 1.0);
    s.velocity.yaw_rate_rad_s = V * options.curvature_per_m * (2.0 * unit(rng) - 1.0);
    s.velocity.axle_angular_velocity_rad_s =
        V / geometry.setup().nominal_radius_m[0] * (1.0 + options.axle_creep * (2.0 * unit(rng) - 1.0));
  }
  const double match = lut.header.match_distance_m;
  const double mu = options.contact.effective_friction_law().static_value();
  std::vector<Outcome> out(samples.size());
  EquilibriumOptions eo;
  eo.max_touching_contact_angle_rad = options.contact.max_touching_contact_angle_rad;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  ProgressCounter progress(options.on_progress, static_cast<double>(samples.size()));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long k = 0; k < static_cast<long>(samples.size()); ++k) {
    const ProgressCounter::Unit counted(progress, "sample " + std::to_string(k));
    const Sample& s = samples[k];
    Outcome& o = out[k];
    WheelContactOptions c = options.contact;
    c.vertical_load_N = s.Q;
    const EquilibriumResult eq = geometry.SolveRigidEquilibrium(s.y, s.psi, WheelsetPose{}, eo);
    if (eq.status != EquilibriumStatus::Converged) continue;
    auto t0 = std::chrono::steady_clock::now();
    const WheelContactReport d = SolveWheelContact(geometry, s.side, eq.pose, s.velocity, c);
    auto t1 = std::chrono::steady_clock::now();
    LutCellInfo info;
    WheelContactReport l;
    try {  // e.g. the total balance's effective load leaving the table
      l = EvaluateContactLut(lut, geometry, s.side, eq.pose, s.velocity, c, &info, options.evaluation);
    } catch (const InputError&) {
      o.lut_error = true;
      l.status = WheelContactStatus::NotConverged;
    }
    auto t2 = std::chrono::steady_clock::now();
    o.direct_s = std::chrono::duration<double>(t1 - t0).count();
    o.lut_s = std::chrono::duration<double>(t2 - t1).count();
    o.direct_ok = d.status == WheelContactStatus::Ok;
    o.lut_ok = l.status == WheelContactStatus::Ok;
    o.single = info.single_topology;
    o.same = SameTopology(d.patches, l.patches, match);
    const std::vector<LutNode>& nodes = lut.nodes[side_index(s.side)];
    for (int cnr = 0; cnr < 8 && !o.at_corner; ++cnr)
      o.at_corner = MatchesNode(d.patches, nodes[g.index(info.iy + (cnr >> 2 & 1), info.ipsi + (cnr >> 1 & 1),
                                                         info.iq + (cnr & 1))], match);
    if (!(o.direct_ok && o.lut_ok && o.same)) continue;
    for (size_t j = 0; j < d.patches.size(); ++j) {
      const PatchReport &a = d.patches[j], &b = l.patches[j];
      o.fn.push_back(std::fabs(a.fn_N - b.fn_N) / s.Q);
      o.fx.push_back(std::fabs(a.fx_N - b.fx_N) / (mu * s.Q));
      o.fy.push_back(std::fabs(a.fy_N - b.fy_N) / (mu * s.Q));
      o.rail_y.push_back(std::fabs(a.y_contact_rail_m - b.y_contact_rail_m));
    }
    o.lateral = std::fabs(d.lateral_force_N - l.lateral_force_N) / s.Q;
  }
  ContactLutCheckResult r;
  r.samples = options.samples;
  std::vector<std::pair<double, long>> fn, fx, fy, ry, lat;
  auto add = [](std::vector<std::pair<double, long>>& to, const std::vector<double>& from, long k) {
    for (double x : from) to.emplace_back(x, k);
  };
  for (long k = 0; k < static_cast<long>(out.size()); ++k) {
    const Outcome& o = out[k];
    r.direct_cpu_s += o.direct_s;
    r.lut_cpu_s += o.lut_s;
    if (o.lut_error) ++r.lut_errors;
    if (!o.direct_ok && !o.lut_ok) { ++r.both_failed; continue; }
    if (o.direct_ok != o.lut_ok) { ++r.status_mismatch; continue; }
    if (o.single) {
      ++r.single_topology;
      if (!o.same) { ++r.single_topology_mismatch; continue; }
      add(fn, o.fn, k);
      add(fx, o.fx, k);
      add(fy, o.fy, k);
      add(ry, o.rail_y, k);
      lat.emplace_back(o.lateral, k);
    } else {
      ++r.jump_samples;
      if (o.same) ++r.jump_same_topology;
      else if (o.at_corner) ++r.jump_within_one_step;
      else ++r.jump_outside;
    }
  }
  r.normal_force_rel = Summarise(fn, samples);
  r.fx_rel = Summarise(fx, samples);
  r.fy_rel = Summarise(fy, samples);
  r.rail_y_m = Summarise(ry, samples);
  r.lateral_force_rel = Summarise(lat, samples);
  return r;
}

}  // namespace conforma
