// Accuracy check of a contact look-up table against the direct pipeline (contact_lut_check.hpp).
#include "conforma/contact_lut_check.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include <omp.h>

#include "conforma/error.hpp"
#include "conforma/parallel_error.hpp"

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
  bool solved = false;  // the pose had a rigid equilibrium
  int patches_direct = 0, patches_lut = 0;
  double direct_fn = 0.0, direct_fx = 0.0, direct_fy = 0.0, direct_candidate_load = 0.0;
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
  LowestIndexError error;  // of a direct solve (an exception may not leave the parallel loop)
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
    WheelContactReport d;
    try {
      d = SolveWheelContact(geometry, s.side, eq.pose, s.velocity, c);
    } catch (const std::exception& e) {
      error.Record(k, e);
      continue;
    }
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
    o.solved = true;
    o.patches_direct = static_cast<int>(d.patches.size()), o.patches_lut = static_cast<int>(l.patches.size());
    for (const PatchReport& p : d.patches) o.direct_fn += p.fn_N, o.direct_fx += p.fx_N, o.direct_fy += p.fy_N;
    o.direct_candidate_load = d.candidate_load_N;
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
  if (error.any()) throw InputError("contact LUT check, sample " + std::to_string(error.index()) + ": " + error.what());
  ContactLutCheckResult r;
  r.samples = options.samples;
  std::vector<std::pair<double, long>> fn, fx, fy, ry, lat;
  auto add = [](std::vector<std::pair<double, long>>& to, const std::vector<double>& from, long k) {
    for (double x : from) to.emplace_back(x, k);
  };
  auto largest = [](const std::vector<double>& v) {
    return v.empty() ? std::nan("") : *std::max_element(v.begin(), v.end());
  };
  r.sample_records.resize(out.size());
  for (long k = 0; k < static_cast<long>(out.size()); ++k) {
    const Outcome& o = out[k];
    ContactLutCheckSample& rec = r.sample_records[k];
    rec.side = side_index(samples[k].side), rec.y_m = samples[k].y, rec.yaw_rad = samples[k].psi;
    rec.load_N = samples[k].Q, rec.lut_error = o.lut_error;
    rec.patches_direct = o.patches_direct, rec.patches_lut = o.patches_lut;
    rec.direct_fn_N = o.direct_fn, rec.direct_fx_N = o.direct_fx, rec.direct_fy_N = o.direct_fy;
    rec.direct_candidate_load_N = o.direct_candidate_load;
    rec.fn_rel = rec.fx_rel = rec.fy_rel = rec.rail_y_m = rec.lateral_rel = std::nan("");
    if (!o.solved) continue;  // category no_equilibrium
    if (!o.direct_ok && !o.lut_ok) rec.category = "both_failed";
    else if (o.direct_ok != o.lut_ok) rec.category = "status_mismatch";
    else if (o.single) rec.category = o.same ? "single" : "single_mismatch";
    else rec.category = o.same ? "jump_same" : o.at_corner ? "jump_corner" : "jump_outside";
    if (o.direct_ok && o.lut_ok && o.single && o.same) {
      rec.fn_rel = largest(o.fn), rec.fx_rel = largest(o.fx), rec.fy_rel = largest(o.fy);
      rec.rail_y_m = largest(o.rail_y), rec.lateral_rel = o.lateral;
    }
  }
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

void WriteContactLutCheckSamplesCsv(std::ostream& out, const ContactLutCheckResult& result) {
  out << "side,y_mm,yaw_mrad,load_kN,category,lut_error,patches_direct,patches_lut,fn_rel_pct,fx_rel_pct,"
         "fy_rel_pct,rail_y_mm,lateral_rel_pct,direct_fn_kN,direct_fx_kN,direct_fy_kN,direct_candidate_load_kN\n";
  auto num = [](double v, double scale) {
    if (!std::isfinite(v)) return std::string();
    char b[32];
    std::snprintf(b, sizeof b, "%.9g", v * scale);
    return std::string(b);
  };
  for (const ContactLutCheckSample& s : result.sample_records)
    out << (s.side == 0 ? "left" : "right") << ',' << num(s.y_m, 1e3) << ',' << num(s.yaw_rad, 1e3) << ','
        << num(s.load_N, 1e-3) << ',' << s.category << ',' << (s.lut_error ? 1 : 0) << ',' << s.patches_direct << ','
        << s.patches_lut << ',' << num(s.fn_rel, 100.0) << ',' << num(s.fx_rel, 100.0) << ','
        << num(s.fy_rel, 100.0) << ',' << num(s.rail_y_m, 1e3) << ',' << num(s.lateral_rel, 100.0) << ','
        << num(s.direct_fn_N, 1e-3) << ',' << num(s.direct_fx_N, 1e-3) << ',' << num(s.direct_fy_N, 1e-3) << ','
        << num(s.direct_candidate_load_N, 1e-3) << '\n';
}

}  // namespace conforma
