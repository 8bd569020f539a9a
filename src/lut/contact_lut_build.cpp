// Generation of a contact look-up table (contact_lut.hpp): every node solved independently with the pipeline.
#include <chrono>
#include <cmath>
#include <string>

#include <omp.h>

#include <Eigen/Dense>

#include "conforma/contact_lut.hpp"
#include "conforma/error.hpp"

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
  std::string first_error;  // of the lowest node index (the same message for any thread count)
  long first_error_node = -1;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (long k = 0; k < 2 * per_side; ++k) {
    const Side side = k < per_side ? Side::Left : Side::Right;
    const long n = k % per_side;
    const size_t iq = n % nq, ipsi = (n / nq) % npsi, iy = n / (nq * npsi);
    try {
      lut.nodes[side_index(side)][n] = SolveNode(geometry, side, eq[iy * npsi + ipsi], g.load_N[iq], options.contact);
    } catch (const std::exception& e) {
#pragma omp critical(contact_lut_error)
      if (first_error_node < 0 || k < first_error_node) first_error = e.what(), first_error_node = k;
    }
  }
  if (!first_error.empty()) throw InputError("contact LUT generation: " + first_error);
  h.generation_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return lut;
}

}  // namespace conforma
