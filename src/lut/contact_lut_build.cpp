// Generation of a contact look-up table (contact_lut.hpp): every node solved independently with the pipeline.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include <omp.h>

#include <Eigen/Dense>

#include "conforma/contact_lut.hpp"
#include "conforma/error.hpp"
#include "conforma/parallel_error.hpp"

#ifndef CONFORMA_VERSION_STRING
#define CONFORMA_VERSION_STRING "unknown"
#endif
#ifndef CONFORMA_GIT_COMMIT
#define CONFORMA_GIT_COMMIT "unknown"
#endif

namespace conforma {

namespace {

void ValidateAxis(const std::vector<double>& axis, const char* name) {
  if (axis.size() < 2) throw InputError(std::string("contact LUT grid axis '") + name + "' needs at least 2 values");
  for (size_t k = 0; k < axis.size(); ++k) {
    if (!std::isfinite(axis[k]))
      throw InputError(std::string("contact LUT grid axis '") + name + "': value " + std::to_string(k) + " is not finite");
    if (k > 0 && !(axis[k] > axis[k - 1]))
      throw InputError(std::string("contact LUT grid axis '") + name + "' must be strictly increasing (value " +
                       std::to_string(k) + ")");
  }
}

// The four velocities (forward speed 1) whose creepages give the affine creepage map (LutPatch::creepage_map).
constexpr int kMapVelocities = 4;
WheelsetVelocity MapVelocity(int k) {
  WheelsetVelocity v;
  v.forward_speed_m_s = 1.0;
  if (k == 1) v.lateral_velocity_m_s = 1.0;
  if (k == 2) v.yaw_rate_rad_s = 1.0;
  if (k == 3) v.axle_angular_velocity_rad_s = 1.0;
  return v;
}

// Least-squares fit of the rigid slip field of a KP patch's FASTSIM from its cells (friction 0: every element
// slips with zero traction, so its slip is the rigid slip; fastsim_core.cpp: s_x = xi - phi y L1/L3 over the
// element, s_y = eta + phi x_mid L2/L3 at the middle x_mid of the marching step). Basis: LutPatch::slip_map.
std::array<double, 8> FitRigidSlip(const PatchReport& p, double xc, double sc, FastsimMarching marching) {
  const size_t n = p.cells.size();
  Eigen::MatrixXd Ax = Eigen::MatrixXd::Zero(n, 3), Ay = Eigen::MatrixXd::Zero(n, 5);
  Eigen::VectorXd bx(n), by(n);
  for (size_t e = 0; e < n; ++e) {
    const ContactCell& c = p.cells[e];
    const bool first = e == 0 || p.cells[e - 1].s_m != c.s_m;  // first element of its strip (leading edge)
    const double x_mid = marching == FastsimMarching::ClassicFullStep ? c.x_m
                         : first ? c.x_m + 0.25 * c.length_x_m : c.x_m + 0.5 * c.length_x_m;
    const double w = std::sqrt(c.area_m2), sg = c.s_m - sc, x = x_mid - xc;
    Ax.row(e) << w, w * sg, w * sg * sg;
    Ay.row(e) << w, w * sg, w * sg * sg, w * x, w * sg * x;
    bx(e) = w * c.slip_x;
    by(e) = w * c.slip_s;
  }
  std::array<double, 8> out{};
  if (n == 0) return out;
  const Eigen::VectorXd cx = Ax.colPivHouseholderQr().solve(bx), cy = Ay.colPivHouseholderQr().solve(by);
  for (int i = 0; i < 3; ++i) out[i] = std::isfinite(cx(i)) ? cx(i) : 0.0;
  for (int i = 0; i < 5; ++i) out[3 + i] = std::isfinite(cy(i)) ? cy(i) : 0.0;
  return out;
}

// One KP strip as the cells of its FASTSIM show it (friction 0, 2 elements per strip).
struct CellStrip {
  double s = 0.0, ds = 0.0, c = 0.0, xm = 0.0, p = 0.0, alpha = 0.0;
  double w[3] = {0.0, 0.0, 0.0};  // w_x, w_s at x = 0, dw_s/dx
};

std::vector<CellStrip> StripsOf(const PatchReport& p, const WheelsetTrackGeometry& geometry, Side side,
                                FastsimMarching marching) {
  std::vector<CellStrip> out;
  double z, slope;
  geometry.RailHeight(side, geometry.RailEtaAtArcLength(side, p.reference_s_on_rail_m), &z, &slope);
  const double delta_ref = std::atan(slope);
  for (size_t e = 0; e < p.cells.size();) {
    size_t f = e;
    while (f < p.cells.size() && p.cells[f].s_m == p.cells[e].s_m) ++f;  // cells e .. f-1: one strip
    const ContactCell& a = p.cells[e];
    const ContactCell& b = p.cells[f - 1];
    CellStrip st;
    st.s = a.s_m;
    st.ds = a.length_x_m > 0.0 ? a.area_m2 / a.length_x_m : 0.0;
    const double lead = a.x_m + 0.5 * a.length_x_m, trail = b.x_m - 0.5 * b.length_x_m;
    st.c = 0.5 * (lead - trail);
    st.xm = 0.5 * (lead + trail);
    // the KP pressure is a semi-ellipse along x on each strip: p(x) = p_peak sqrt(1 - ((x - xm) / c)^2)
    const double t = st.c > 0.0 ? (a.x_m - st.xm) / st.c : 0.0;
    st.p = t * t < 1.0 ? a.pressure_Pa / std::sqrt(1.0 - t * t) : 0.0;
    geometry.RailHeight(side, geometry.RailEtaAtArcLength(side, a.rail_s_m), &z, &slope);
    st.alpha = std::atan(slope) - delta_ref;
    // rigid slip (FitRigidSlip): s_x constant along the strip, s_y at the marching steps' middles
    auto x_mid = [&](size_t k) {
      const ContactCell& c = p.cells[k];
      return marching == FastsimMarching::ClassicFullStep ? c.x_m
             : k == e ? c.x_m + 0.25 * c.length_x_m : c.x_m + 0.5 * c.length_x_m;
    };
    st.w[0] = a.slip_x;
    if (f - e >= 2) {
      const double x0 = x_mid(e), x1 = x_mid(f - 1);
      st.w[2] = (b.slip_s - a.slip_s) / (x1 - x0);
      st.w[1] = a.slip_s - st.w[2] * x0;
    } else {
      st.w[1] = a.slip_s;
    }
    out.push_back(st);
    e = f;
  }
  return out;
}

// The strips of the four velocities resampled on the stations (LutPatch::stations); linear in s between strip
// centres, no contact in a gap between strips (two lobes of one patch).
void FillStations(const std::vector<CellStrip> (&strips)[4], LutPatch* q) {
  const std::vector<CellStrip>& s0 = strips[0];
  if (s0.empty()) return;
  for (int k = 1; k < 4; ++k)
    if (strips[k].size() != s0.size()) return;  // one normal solution: cannot happen; kept as a guard
  q->station_s_min_m = s0.front().s - 0.5 * s0.front().ds;
  q->station_s_max_m = s0.back().s + 0.5 * s0.back().ds;
  const double w = (q->station_s_max_m - q->station_s_min_m) / kLutStations;
  for (int st = 0; st < kLutStations; ++st) {
    double* f = &q->stations[st * kLutStationFields];
    const double s = q->station_s_min_m + (st + 0.5) * w;
    // the strips around s: i with s_i <= s < s_{i+1} (clamped at the ends)
    size_t i = 0;
    while (i + 1 < s0.size() && s0[i + 1].s <= s) ++i;
    size_t j = std::min(i + 1, s0.size() - 1);
    double t = 0.0;
    if (s < s0.front().s) j = i = 0;
    else if (j != i) t = (s - s0[i].s) / (s0[j].s - s0[i].s);
    if (j != i && s0[j].s - s0[i].s > 1.5 * std::max(s0[i].ds, s0[j].ds)) {
      const double gap_i = s - (s0[i].s + 0.5 * s0[i].ds), gap_j = (s0[j].s - 0.5 * s0[j].ds) - s;
      if (gap_i > 0.0 && gap_j > 0.0) continue;  // in the gap: c = 0, no contact
      t = gap_i > 0.0 ? 1.0 : 0.0;               // within a strip width of one side: that strip
    }
    auto lerp = [&](double a, double b) { return a + t * (b - a); };
    f[0] = lerp(s0[i].c, s0[j].c);
    f[1] = lerp(s0[i].xm, s0[j].xm);
    f[2] = lerp(s0[i].p, s0[j].p);
    f[3] = lerp(s0[i].alpha, s0[j].alpha);
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 4; ++k) {
        const double v = lerp(strips[k][i].w[r], strips[k][j].w[r]), v0 = lerp(s0[i].w[r], s0[j].w[r]);
        f[4 + 4 * r + k] = k == 0 ? v0 : v - v0;
      }
  }
}

LutNode SolveNode(const WheelsetTrackGeometry& geometry, Side side, const EquilibriumResult& eq, double load_N,
                  const WheelContactOptions& base) {
  LutNode node;
  if (eq.status != EquilibriumStatus::Converged) {
    node.status = kLutNoEquilibrium;
    return node;
  }
  WheelContactOptions o = base;
  o.vertical_load_N = load_N;
  o.load_balance = LoadBalance::Pressure;  // the normal solution independent of the velocity
  o.solve_tangential = true;               // the SDEC of the KP models comes with the tangential solve
  o.creepages_given = false;
  o.keep_fields = true;     // the cells give the KP patch's centroid and rigid slip
  o.friction_coefficient = 0.0;  // zero traction: the cells' slip is the rigid slip (FitRigidSlip)
  o.friction_law = FrictionLaw{};
  o.fastsim_elements = 2;  // only the creepages and the ellipse are kept: neither depends on the FASTSIM mesh
  WheelContactCache cache(8);  // the normal stage solved once, reused for the four velocities
  WheelContactReport r[kMapVelocities];
  for (int k = 0; k < kMapVelocities; ++k) r[k] = SolveWheelContactCached(geometry, side, eq.pose, MapVelocity(k), o, cache);
  node.status = static_cast<int>(r[0].status);
  node.vertical_m = r[0].pose.vertical_m;
  node.roll_rad = r[0].pose.roll_rad;
  for (int k = 1; k < kMapVelocities; ++k)
    if (r[k].patches.size() != r[0].patches.size()) {  // cannot happen with one normal stage; kept as a guard
      node.status = static_cast<int>(WheelContactStatus::NotConverged);
      return node;
    }
  for (size_t j = 0; j < r[0].patches.size(); ++j) {
    const PatchReport& p = r[0].patches[j];
    LutPatch q;
    q.model = static_cast<int>(p.model);
    q.y_contact_rail_m = p.y_contact_rail_m;
    q.z_contact_rail_m = p.z_contact_rail_m;
    q.rail_s_m = p.reference_s_on_rail_m;
    q.y_contact_wheel_m = p.y_contact_wheel_m;
    q.lead_m = p.lead_m;
    q.contact_angle_rad = p.contact_angle_rad;
    q.rolling_radius_m = p.rolling_radius_m;
    q.fn_N = p.fn_N;
    // the resultant without the creep force along t0 = (cos delta, sin delta) (eta, z)
    q.pressure_vertical_N = p.vertical_force_N - p.fy_N * std::sin(p.contact_angle_rad);
    q.pressure_lateral_N = p.lateral_force_N - p.fy_N * std::cos(p.contact_angle_rad);
    q.pmax_Pa = p.pmax_Pa;
    q.area_m2 = p.area_m2;
    q.approach_m = p.approach_m;
    q.width_m = p.width_m;
    q.length_m = p.length_m;
    q.a_m = p.a_m;
    q.b_m = p.b_m;
    q.alpha_c_deg = p.alpha_c_deg;
    if (p.model != ContactModel::Hertz) {
      double area = 0.0, sx = 0.0, ss = 0.0;
      for (const ContactCell& c : p.cells) area += c.area_m2, sx += c.area_m2 * c.x_m, ss += c.area_m2 * c.s_m;
      if (area > 0.0) q.centre_x_m = sx / area, q.centre_s_m = ss / area;
      std::array<double, 8> fit[kMapVelocities];
      for (int k = 0; k < kMapVelocities; ++k)
        fit[k] = FitRigidSlip(r[k].patches[j], q.centre_x_m, q.centre_s_m, o.fastsim.marching);
      for (int i = 0; i < 8; ++i)
        for (int k = 0; k < kMapVelocities; ++k) q.slip_map[4 * i + k] = k == 0 ? fit[0][i] : fit[k][i] - fit[0][i];
      std::vector<CellStrip> strips[kMapVelocities];
      for (int k = 0; k < kMapVelocities; ++k) strips[k] = StripsOf(r[k].patches[j], geometry, side, o.fastsim.marching);
      FillStations(strips, &q);
    }
    q.auto_alpha_c_deg = p.auto_alpha_c_deg;
    for (int k = 0; k < kMapVelocities; ++k) {
      const PatchReport& pk = r[k].patches[j];
      const double c[3] = {pk.xi, pk.eta, pk.phi_per_m};
      const double c0[3] = {p.xi, p.eta, p.phi_per_m};
      for (int i = 0; i < 3; ++i) q.creepage_map[4 * i + k] = k == 0 ? c0[i] : c[i] - c0[i];
    }
    node.patches.push_back(q);
  }
  return node;
}

}  // namespace

void ContactLutGrid::validate() const {
  ValidateAxis(lateral_m, "lateral_m");
  ValidateAxis(yaw_rad, "yaw_rad");
  ValidateAxis(load_N, "load_N");
  if (!(load_N.front() > 0.0)) throw InputError("contact LUT grid axis 'load_N' must be > 0");
  if (load_N.back() > kMaxWheelLoadN) throw InputError("contact LUT grid axis 'load_N' exceeds the largest wheel load");
  if (std::max(-yaw_rad.front(), yaw_rad.back()) > kMaxWheelsetYaw_rad)
    throw InputError("contact LUT grid axis 'yaw_rad' reaches beyond +-" + std::to_string(int(kMaxWheelsetYaw_rad * 1e3)) +
                     " mrad: not a wheelset yaw on track");
}

void ContactLutBuildOptions::validate() const {
  grid.validate();
  contact.validate();
  require_positive(match_distance_m, "contact LUT match_distance_m");
  if (threads < 0) throw InputError("contact LUT threads must be >= 0");
}

ContactLut BuildContactLut(const WheelsetTrackGeometry& geometry, const ContactLutBuildOptions& options) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  ContactLut lut;
  lut.grid = options.grid;
  ContactLutHeader& h = lut.header;
  h.wheel_profile = options.wheel_profile;
  h.rail_profile = options.rail_profile;
  h.track = options.track;
  h.conforma_version = CONFORMA_VERSION_STRING;
  h.conforma_commit = CONFORMA_GIT_COMMIT;
  h.model = options.contact.model;
  h.material = options.contact.material;
  h.max_touching_contact_angle_rad = options.contact.max_touching_contact_angle_rad;
  h.kp_strips = options.contact.kp_strips;
  h.candidate_strip_width_m = options.contact.candidate_strip_width_m;
  h.patch_combine_distance_m = options.contact.patch_combine_distance_m;
  h.conformal_variable_penetration = options.contact.conformal_variable_penetration;
  h.match_distance_m = options.match_distance_m;
  for (Side s : {Side::Left, Side::Right}) {
    h.rail_origin_eta_m[side_index(s)] = geometry.rail_origin_eta_m(s);
    h.nominal_radius_m[side_index(s)] = geometry.setup().nominal_radius_m[side_index(s)];
  }
  h.geometry_digest = ContactLutGeometryDigest(geometry);
  const ContactLutGrid& g = lut.grid;
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  h.threads = threads;

  // rigid equilibrium per (y, psi), as EvaluateWheelset (kinematics_quasistatic.cpp) does it
  const size_t ny = g.lateral_m.size(), npsi = g.yaw_rad.size(), nq = g.load_N.size();
  std::vector<EquilibriumResult> eq(ny * npsi);
  EquilibriumOptions eo;
  eo.max_touching_contact_angle_rad = options.contact.max_touching_contact_angle_rad;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long k = 0; k < static_cast<long>(eq.size()); ++k)
    eq[k] = geometry.SolveRigidEquilibrium(g.lateral_m[k / npsi], g.yaw_rad[k % npsi], WheelsetPose{}, eo);

  // nodes: both sides in one loop (each written into its slot)
  const long per_side = static_cast<long>(g.nodes());
  for (auto& v : lut.nodes) v.resize(per_side);
  LowestIndexError error;
  ProgressCounter progress(options.on_progress, 2.0 * static_cast<double>(per_side));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long k = 0; k < 2 * per_side; ++k) {
    const ProgressCounter::Unit counted(progress, "node " + std::to_string(k));
    const Side side = k < per_side ? Side::Left : Side::Right;
    const long n = k % per_side;
    const size_t iq = n % nq, ipsi = (n / nq) % npsi, iy = n / (nq * npsi);
    try {
      lut.nodes[side_index(side)][n] = SolveNode(geometry, side, eq[iy * npsi + ipsi], g.load_N[iq], options.contact);
    } catch (const std::exception& e) {
      error.Record(k, e);
    }
  }
  if (error.any()) throw InputError("contact LUT generation: " + error.what());
  h.generation_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return lut;
}

}  // namespace conforma
