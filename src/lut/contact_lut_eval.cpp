// Evaluation of a contact look-up table (contact_lut.hpp): topology-preserving interpolation of the normal
// solution, creepages from the tabulated affine maps, FASTSIM on the tabulated patch (docs/physics-reference.md §17).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "conforma/contact_lut.hpp"
#include "conforma/contact_plausibility.hpp"
#include "conforma/error.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/friction_law.hpp"
#include "conforma/polach_creep_force.hpp"
#include "lut_locate.hpp"

namespace conforma {

namespace {

bool SameTopology(const LutNode& a, const LutNode& b, double match_distance_m) {
  if (a.status != b.status || a.patches.size() != b.patches.size()) return false;
  for (size_t j = 0; j < a.patches.size(); ++j) {
    if (a.patches[j].model != b.patches[j].model) return false;
    if (!(std::fabs(a.patches[j].rail_s_m - b.patches[j].rail_s_m) < match_distance_m)) return false;
  }
  return true;
}

// Fields of a patch normalised by their Hertzian power of the node's load (forces ~ Q, lengths and pressure
// ~ Q^(1/3), area and approach ~ Q^(2/3)): nearly independent of Q, so the interpolation in Q is close to exact.
constexpr int kScaled = 19, kStationValues = kLutStations * kLutStationFields;
constexpr int kFields = kScaled + 12 + 32 + kStationValues;
// nf: the fields used (NumberOfFields: kHertzFields when the creep solve reads no slip map and no stations; else kFields)
constexpr int kHertzFields = kScaled + 12;
void Pack(const LutPatch& p, double Q, double* f, int nf) {
  const double q1 = 1.0 / Q, q13 = 1.0 / std::cbrt(Q), q23 = q13 * q13;
  const double v[kScaled] = {p.y_contact_rail_m, p.z_contact_rail_m, p.rail_s_m, p.y_contact_wheel_m, p.lead_m,
                                  p.contact_angle_rad, p.rolling_radius_m, p.fn_N * q1, p.pressure_vertical_N * q1,
                                  p.pressure_lateral_N * q1, p.pmax_Pa * q13, p.area_m2 * q23, p.approach_m * q23,
                                  p.a_m * q13, p.b_m * q13, p.centre_x_m * q13, p.centre_s_m * q13,
                             p.station_s_min_m * q13, p.station_s_max_m * q13};
  std::copy(v, v + kScaled, f);
  std::copy(p.creepage_map.begin(), p.creepage_map.end(), f + kScaled);
  if (nf == kHertzFields) return;
  std::copy(p.slip_map.begin(), p.slip_map.end(), f + kScaled + 12);
  double* st = f + kScaled + 44;
  std::copy(p.stations.begin(), p.stations.end(), st);
  for (int k = 0; k < kLutStations; ++k)  // half-length, centre x, peak pressure ~ Q^(1/3)
    for (int i = 0; i < 3; ++i) st[k * kLutStationFields + i] *= q13;
}
void Unpack(const double* f, double Q, LutPatch* p, int nf) {
  const double q13 = std::cbrt(Q), q23 = q13 * q13;
  p->y_contact_rail_m = f[0];
  p->z_contact_rail_m = f[1];
  p->rail_s_m = f[2];
  p->y_contact_wheel_m = f[3];
  p->lead_m = f[4];
  p->contact_angle_rad = f[5];
  p->rolling_radius_m = f[6];
  p->fn_N = f[7] * Q;
  p->pressure_vertical_N = f[8] * Q;
  p->pressure_lateral_N = f[9] * Q;
  p->pmax_Pa = f[10] * q13;
  p->area_m2 = f[11] * q23;
  p->approach_m = f[12] * q23;
  p->a_m = f[13] * q13;
  p->b_m = f[14] * q13;
  p->centre_x_m = f[15] * q13;
  p->centre_s_m = f[16] * q13;
  p->station_s_min_m = f[17] * q13;
  p->station_s_max_m = f[18] * q13;
  std::copy(f + kScaled, f + kScaled + 12, p->creepage_map.begin());
  if (nf == kHertzFields) return;
  std::copy(f + kScaled + 12, f + kScaled + 44, p->slip_map.begin());
  std::copy(f + kScaled + 44, f + kFields, p->stations.begin());
  for (int k = 0; k < kLutStations; ++k)
    for (int i = 0; i < 3; ++i) p->stations[k * kLutStationFields + i] *= q13;
}

// Fields that vanish with the patch (Pack's order): normal force, pressure resultants, p_max, area, approach, the
// ellipse's semi-axes, and per station the half-length and the peak pressure. The others are its geometry and
// kinematics (position, angle, radius, creepage and slip maps, centres, station extents).
bool IsMagnitudeField(int k) {
  if (k >= 7 && k <= 14) return true;
  if (k < kScaled + 44) return false;
  const int i = (k - kScaled - 44) % kLutStationFields;
  return i == 0 || i == 2;
}

// Patch tracks of a cell whose 8 corners are all Ok: every corner's patches matched to tracks (same model, reference
// points closer than the match distance along the rail, the nearest free track; a patch without one starts a track),
// the tracks ordered along the rail as the nodes' patches. index[c]: the corner's patch on the track, -1 where the
// corner has none. false when a corner is not Ok or there are more than kMaxTracks tracks.
constexpr int kMaxTracks = 8;
struct PatchTrack {
  double rail_s_m = 0.0;
  int model = 0;
  std::array<int, 8> index{-1, -1, -1, -1, -1, -1, -1, -1};
};
bool TracksOfCorners(const LutNode* const corner[8], double match_distance_m, std::vector<PatchTrack>* tracks) {
  const int ok = static_cast<int>(WheelContactStatus::Ok);
  tracks->clear();
  for (int c = 0; c < 8; ++c) {
    if (corner[c]->status != ok) return false;
    for (size_t i = 0; i < corner[c]->patches.size(); ++i) {
      const LutPatch& p = corner[c]->patches[i];
      int best = -1;
      double best_distance = match_distance_m;
      for (size_t t = 0; t < tracks->size(); ++t) {
        const PatchTrack& k = (*tracks)[t];
        const double d = std::fabs(k.rail_s_m - p.rail_s_m);
        if (k.model == p.model && k.index[c] < 0 && d < best_distance) best = static_cast<int>(t), best_distance = d;
      }
      if (best < 0) {
        if (static_cast<int>(tracks->size()) == kMaxTracks) return false;
        PatchTrack k;
        k.rail_s_m = p.rail_s_m;
        k.model = p.model;
        tracks->push_back(k);
        best = static_cast<int>(tracks->size()) - 1;
      }
      (*tracks)[best].index[c] = static_cast<int>(i);
    }
  }
  std::stable_sort(tracks->begin(), tracks->end(),
                   [](const PatchTrack& x, const PatchTrack& y) { return x.rail_s_m < y.rail_s_m; });
  return true;
}

// The fields a patch's creep solve reads: FASTSIM on a KP patch reads the slip map and the stations too; a hertz
// patch, and Polach's ellipse on any patch, only the first kHertzFields.
int NumberOfFields(const LutPatch& p, LutCreepForce law) {
  return p.model == static_cast<int>(ContactModel::Hertz) || law == LutCreepForce::Polach ? kHertzFields : kFields;
}

// The interpolated normal solution at (y, psi, Q).
struct NormalAtPose {
  int status = 0;
  double vertical_m = 0.0, roll_rad = 0.0;
  std::vector<LutPatch> patches;
  LutCellInfo cell;
};

// Q: where the table is read; Q_scale: the load the normalised fields are scaled back to (the same; a Hertzian
// rescaling of the patches of Q to the total balance's effective load was tried and was worse: see §17.4).
NormalAtPose InterpolateNormal(const ContactLut& lut, Side side, double y, double psi, double Q, double Q_scale,
                               LutCreepForce law) {
  const ContactLutGrid& g = lut.grid;
  size_t iy, ip, iq;
  double ty, tp, tq;
  LocateOnLutAxis(g.lateral_m, y, "lateral shift y", "mm", 1e3, &iy, &ty);
  LocateOnLutAxis(g.yaw_rad, psi, "yaw psi", "mrad", 1e3, &ip, &tp);
  LocateOnLutAxis(g.load_N, Q, "wheel load Q", "kN", 1e-3, &iq, &tq);
  const std::vector<LutNode>& nodes = lut.nodes[side_index(side)];
  const LutNode* corner[8];
  double w[8], Qc[8];
  for (int c = 0; c < 8; ++c) {
    const int dy = c >> 2 & 1, dp = c >> 1 & 1, dq = c & 1;
    corner[c] = &nodes[g.index(iy + dy, ip + dp, iq + dq)];
    Qc[c] = g.load_N[iq + dq];
    w[c] = (dy ? ty : 1.0 - ty) * (dp ? tp : 1.0 - tp) * (dq ? tq : 1.0 - tq);
  }
  NormalAtPose out;
  out.cell.iy = iy, out.cell.ipsi = ip, out.cell.iq = iq;
  bool single = true;
  for (int c = 1; c < 8; ++c) single = single && SameTopology(*corner[0], *corner[c], lut.header.match_distance_m);
  out.cell.single_topology = single && corner[0]->status == static_cast<int>(WheelContactStatus::Ok);
  // A cell with a topology change whose corners are all Ok: the patch tracks of its corners (TracksOfCorners); a
  // patch missing at a corner enters there with zero force, so a flange patch that appears, or a contact point
  // that moves to another place on the tread, changes the forces continuously across the cell (the multi-Hertz
  // solve is continuous in the pose in the same way: a new gap minimum enters with zero force). Otherwise (a corner
  // not Ok) the topology of the nearest corner (largest weight; the first on a tie) and the corners sharing it.
  int nearest = 0;
  for (int c = 1; c < 8; ++c)
    if (w[c] > w[nearest]) nearest = c;
  std::vector<PatchTrack> tracks;
  const bool union_rule =
      !out.cell.single_topology && TracksOfCorners(corner, lut.header.match_distance_m, &tracks);
  out.cell.union_topology = union_rule;
  const LutNode& ref = *corner[nearest];
  double wsum = 0.0;
  for (int c = 0; c < 8; ++c) {
    if (!union_rule && !SameTopology(ref, *corner[c], lut.header.match_distance_m)) w[c] = 0.0;
    wsum += w[c];
  }
  out.status = union_rule ? static_cast<int>(WheelContactStatus::Ok) : ref.status;
  const size_t np = union_rule ? tracks.size() : ref.patches.size();
  // the patch whose integer and non-interpolated fields (model, alpha_c, extents) a result patch takes: the nearest
  // corner's, or on a track that of the corner with the largest weight that has it
  std::vector<const LutPatch*> rep(np, nullptr);
  for (size_t j = 0; j < np; ++j) {
    if (!union_rule) {
      rep[j] = &ref.patches[j];
      continue;
    }
    int best = -1;
    for (int c = 0; c < 8; ++c)
      if (tracks[j].index[c] >= 0 && (best < 0 || w[c] > w[best])) best = c;
    rep[j] = &corner[best]->patches[tracks[j].index[best]];
  }
  std::vector<double> acc(np * kFields, 0.0), f(kFields), present(np, 0.0);
  std::vector<char> missing(np, 0);
  for (int c = 0; c < 8; ++c) {
    if (w[c] == 0.0) continue;
    const double wc = w[c] / wsum;
    out.vertical_m += wc * corner[c]->vertical_m;
    out.roll_rad += wc * corner[c]->roll_rad;
    for (size_t j = 0; j < np; ++j) {
      const int i = union_rule ? tracks[j].index[c] : static_cast<int>(j);
      if (i < 0) {
        missing[j] = 1;
        continue;
      }
      const int nf = NumberOfFields(*rep[j], law);
      Pack(corner[c]->patches[i], Qc[c], f.data(), nf);
      for (int k = 0; k < nf; ++k) acc[j * kFields + k] += wc * f[k];
      present[j] += wc;
    }
  }
  out.patches.reserve(np);
  for (size_t j = 0; j < np; ++j) {
    // a patch missing at some corners: its magnitudes averaged with zero there, its geometry over the corners that
    // have it; where none of the corners with a weight has it (a query on a cell face or edge), it is not there
    if (missing[j] && !(present[j] > 0.0)) continue;
    const int nf = NumberOfFields(*rep[j], law);
    if (missing[j])
      for (int k = 0; k < nf; ++k)
        if (!IsMagnitudeField(k)) acc[j * kFields + k] /= present[j];
    out.patches.push_back(*rep[j]);
    Unpack(&acc[j * kFields], Q_scale, &out.patches.back(), nf);
  }
  return out;
}

// Mean of sqrt(1 - t^2) over [t1, t2] (the semi-ellipse's element mean), -1 <= t1 < t2 <= 1.
double SemiEllipseMean(double t1, double t2) {
  auto F = [](double t) { return 0.5 * (t * std::sqrt(std::max(0.0, 1.0 - t * t)) + std::asin(t)); };
  return (F(t2) - F(t1)) / (t2 - t1);
}

// KP patches: the pipeline's curved-patch FASTSIM (patch_model_kp.cpp, curved_fastsim.hpp) on the tabulated patch
// (LutPatch::stations): one strip per station with its half-length, centre, semi-elliptic traction bound scaled to
// the normal force, its rigid slip (per-strip creepages at the spin origin, local_creepage.hpp) and the SDEC
// flexibilities; the strip forces along their local tangents projected on t0 (cos alpha), as force_reference_N.
void SolveOnStations(const LutPatch& q, const double* u, const FastsimHertzInput& in, const WheelContactOptions& options,
                     FastsimResult* t, double* fx, double* fy, double* mz) {
  const int n = options.fastsim_elements;
  const double width = (q.station_s_max_m - q.station_s_min_m) / kLutStations;
  FastsimPatch patch;
  std::vector<FastsimCreepages> creep;
  std::vector<double> alpha;
  const FastsimFlexibilities L = FastsimHertzFlexibilities(in, options.fastsim);
  // the element means of the semi-ellipse, the same on every station (elements from the leading edge)
  std::vector<double> element_mean(n);
  for (int e = 0; e < n; ++e) {
    const double t2 = 1.0 - 2.0 * e / n, t1 = 1.0 - 2.0 * (e + 1.0) / n;
    element_mean[e] = SemiEllipseMean(t1, t2);
  }
  patch.strips.reserve(kLutStations);
  patch.bound_pressure_Pa.reserve(static_cast<size_t>(kLutStations) * n);
  creep.reserve(kLutStations);
  alpha.reserve(kLutStations);
  double projected = 0.0;
  for (int k = 0; k < kLutStations; ++k) {
    const double* f = &q.stations[k * kLutStationFields];
    const double c = f[0], xm = f[1], peak = f[2];
    if (!(c > 0.0) || !(peak > 0.0)) continue;
    FastsimStrip strip;
    strip.y_m = q.station_s_min_m + (k + 0.5) * width;
    strip.width_m = width;
    strip.x_lead_m = xm + c;
    strip.x_trail_m = xm - c;
    strip.first_element = patch.elements();
    strip.n_elements = n;
    double strip_load = 0.0;
    for (int e = 0; e < n; ++e) {
      const double p = peak * element_mean[e];
      patch.bound_pressure_Pa.push_back(p);
      strip_load += p * width * 2.0 * c / n;
    }
    projected += strip_load * std::cos(f[3]);  // along n0 (KpResult::fn_N sums cos(alpha_j) F_j the same way)
    patch.strips.push_back(strip);
    double w[3] = {0.0, 0.0, 0.0};
    for (int r = 0; r < 3; ++r)
      for (int j = 0; j < 4; ++j) w[r] += f[4 + 4 * r + j] * u[j];
    // the core's rigid slip is (xi_j - phi_j y L1/L3, eta_j + phi_j x L2/L3) (fastsim_core.cpp)
    FastsimCreepages cr;
    cr.phi_per_m = w[2] * L.L3 / L.L2;
    cr.xi = w[0] + cr.phi_per_m * strip.y_m * L.L1 / L.L3;
    cr.eta = w[1];
    creep.push_back(cr);
    alpha.push_back(f[3]);
  }
  *fx = *fy = *mz = 0.0;
  if (patch.strips.empty() || !(projected > 0.0)) {
    t->status = FastsimStatus::NoContact;
    return;
  }
  // The bound is the pressure on the curved surface, whose resultant along the reference normal n0 is F_n: scaled so
  // that sum p dA cos(alpha) = F_n, i.e. sum p dA = the surface integral (fn_surface_N, as the direct KP FASTSIM's
  // CurvedFastsimOptions::load_N, patch_model_kp.cpp). Scaled to F_n itself the bound was short by 1 - F_n/fn_surface
  // (up to 6 % of mu Q at the flange, docs/physics-reference.md §17.3).
  for (double& p : patch.bound_pressure_Pa) p *= in.normal_force_N / projected;
  std::vector<FastsimStripTotals> totals;
  SolveFastsimStripsEach(patch, L, creep, in.friction_coefficient, in.rolling_speed_m_per_s, options.fastsim, t, &totals);
  t->fx_N = t->fy_N = t->mz_Nm = t->adhesion_area_m2 = t->slip_area_m2 = t->frictional_power_W = 0.0;
  for (size_t j = 0; j < totals.size(); ++j) {
    *fx += totals[j].fx_N;
    *fy += totals[j].fy_N * std::cos(alpha[j]);
    *mz += totals[j].mz_Nm;
    t->adhesion_area_m2 += totals[j].adhesion_area_m2;
    t->slip_area_m2 += totals[j].slip_area_m2;
    t->frictional_power_W += totals[j].frictional_power_W;
  }
  t->fx_N = *fx, t->fy_N = *fy, t->mz_Nm = *mz;
  t->status = t->adhesion_area_m2 > 0.0 ? FastsimStatus::Ok : FastsimStatus::FullSlip;
}

// Polach's creep forces (polach_creep_force.hpp) on the patch's ellipse with FASTSIM's input (creepages already moved
// to the ellipse centre, in.creepages); the force acts at the ellipse centre: its moment about the reference point
// as for FASTSIM's forces below.
void SolvePolachOnEllipse(const LutPatch& q, const FastsimHertzInput& in, const CreepCoefficients& coefficients,
                          double V, PatchReport* p) {
  PolachInput pi;
  pi.a_m = in.a_m;
  pi.b_m = in.b_m;
  pi.normal_force_N = in.normal_force_N;
  pi.friction_coefficient = in.friction_coefficient;
  pi.creepages = in.creepages;
  pi.material = in.material;
  const PolachResult r = SolvePolachCreepForce(pi, coefficients);
  p->tangential_status = "ok";
  p->fx_N = r.fx_N;
  p->fy_N = r.fy_N;
  p->mz_Nm = q.centre_x_m * r.fy_N - q.centre_s_m * r.fx_N;  // about the reference point (Polach: no spin moment)
  p->adhesion_area_m2 = p->slip_area_m2 = 0.0;
  p->frictional_power_W = std::max(0.0, r.frictional_power_per_speed_N) * V;
}

// Creep forces of one patch: FASTSIM on the stored ellipse, as the hertz model's tangential solve
// (patch_model_hertz.cpp) does it.
// u: (1, v_lat / V, yaw_rate / V, axle_rate / V) with the wheelset kinematics, nullptr with given creepages.
void SolveCreep(const LutPatch& q, const Creepages& cr, const double* u, double V, const WheelContactOptions& options,
                LutCreepForce law, PatchReport* p) {
  if (!options.solve_tangential || !(q.a_m > 0.0) || !(q.b_m > 0.0)) {
    p->tangential_status = "not_solved";
    return;
  }
  if (cr.longitudinal == 0.0 && cr.lateral == 0.0 && cr.spin_per_m == 0.0) {
    p->tangential_status = "no_creepage";
    return;
  }
  FastsimHertzInput in;
  in.a_m = q.a_m;
  in.b_m = q.b_m;
  in.normal_force_N = q.fn_N;
  in.creepages = FastsimCreepages{cr.longitudinal, cr.lateral, cr.spin_per_m};
  in.friction_coefficient = options.effective_friction_law().static_value();
  in.material = options.material;
  in.nx = in.ny = options.fastsim_elements;
  in.rolling_speed_m_per_s = V;
  // Polach needs Kalker's coefficients of the ellipse, and so does the centre shift below: computed once
  const bool polach = law == LutCreepForce::Polach;
  CreepCoefficients kalker;
  if (polach) kalker = KalkerCoefficients(in.a_m / in.b_m, in.material.poisson_ratio);
  if (q.centre_x_m != 0.0 || q.centre_s_m != 0.0) {
    // creepages at the ellipse centre (x_c, s_c) such that FASTSIM's rigid slip (xi - phi y L1/L3,
    // eta + phi x L2/L3; docs/physics-reference.md §2.4) equals the one about the reference point
    const FastsimFlexibilities L = polach ? FastsimHertzFlexibilities(in, options.fastsim, kalker)
                                          : FastsimHertzFlexibilities(in, options.fastsim);
    in.creepages.xi -= cr.spin_per_m * q.centre_s_m * L.L1 / L.L3;
    in.creepages.eta += cr.spin_per_m * q.centre_x_m * L.L2 / L.L3;
  }
  if (polach) {
    SolvePolachOnEllipse(q, in, kalker, V, p);
    return;
  }
  FastsimResult t;
  if (u != nullptr && q.model != static_cast<int>(ContactModel::Hertz) && options.friction_law.is_constant() &&
      q.station_s_max_m > q.station_s_min_m) {
    SolveOnStations(q, u, in, options, &t, &p->fx_N, &p->fy_N, &p->mz_Nm);
    p->tangential_status = to_string(t.status);
    p->adhesion_area_m2 = t.adhesion_area_m2;
    p->slip_area_m2 = t.slip_area_m2;
    p->frictional_power_W = t.frictional_power_W;
    return;
  } else if (u != nullptr && q.model != static_cast<int>(ContactModel::Hertz) && options.friction_law.is_constant()) {
    // KP models: strip by strip with the tabulated rigid slip (LutPatch::slip_map), about the ellipse centre
    double c[8] = {};
    for (int i = 0; i < 8; ++i)
      for (int k = 0; k < 4; ++k) c[i] += q.slip_map[4 * i + k] * u[k];
    in.creepages = FastsimCreepages{cr.longitudinal, cr.lateral, cr.spin_per_m};
    FastsimPatch patch;
    BuildFastsimHertzPatch(in, options.fastsim, &patch);
    const FastsimFlexibilities L = FastsimHertzFlexibilities(in, options.fastsim);
    std::vector<FastsimCreepages> strip(patch.strips.size());
    for (size_t j = 0; j < strip.size(); ++j) {
      // the core's rigid slip is (xi_j - phi_j y L1/L3, eta_j + phi_j x L2/L3) (fastsim_core.cpp)
      const double y = patch.strips[j].y_m;
      const double phi = (c[6] + c[7] * y) * L.L3 / L.L2;
      strip[j].phi_per_m = phi;
      strip[j].xi = c[0] + c[1] * y + c[2] * y * y + phi * y * L.L1 / L.L3;
      strip[j].eta = c[3] + c[4] * y + c[5] * y * y;
    }
    std::vector<FastsimStripTotals> totals;
    SolveFastsimStripsEach(patch, L, strip, in.friction_coefficient, V, options.fastsim, &t, &totals);
    t.fx_N = t.fy_N = t.mz_Nm = t.adhesion_area_m2 = t.slip_area_m2 = t.frictional_power_W = 0.0;
    for (const FastsimStripTotals& s : totals) {
      t.fx_N += s.fx_N;
      t.fy_N += s.fy_N;
      t.mz_Nm += s.mz_Nm;
      t.adhesion_area_m2 += s.adhesion_area_m2;
      t.slip_area_m2 += s.slip_area_m2;
      t.frictional_power_W += s.frictional_power_W;
    }
    t.status = patch.strips.empty() ? FastsimStatus::NoContact
               : t.adhesion_area_m2 > 0.0 ? FastsimStatus::Ok : FastsimStatus::FullSlip;
  } else if (options.friction_law.is_constant()) {
    t = SolveFastsimHertz(in, options.fastsim);
  } else {
    FastsimPatch patch;
    BuildFastsimHertzPatch(in, options.fastsim, &patch);
    if (patch.strips.empty()) {
      t = SolveFastsimHertz(in, options.fastsim);
    } else {
      SolveFastsimStripsWithLaw(patch, FastsimHertzFlexibilities(in, options.fastsim), in.creepages,
                                options.friction_law, V, options.fastsim, &t);
    }
  }
  p->tangential_status = to_string(t.status);
  p->fx_N = t.fx_N;
  p->fy_N = t.fy_N;
  p->mz_Nm = t.mz_Nm + q.centre_x_m * t.fy_N - q.centre_s_m * t.fx_N;  // about the reference point
  p->adhesion_area_m2 = t.adhesion_area_m2;
  p->slip_area_m2 = t.slip_area_m2;
  p->frictional_power_W = t.frictional_power_W;
}

bool IsKpModel(ContactModel m) {
  return m == ContactModel::Kp || m == ContactModel::Kpec || m == ContactModel::Conformal;
}

// The report at the pressure-balanced load Q_eff read at Q_table (= Q_eff; what the direct solve gives with
// LoadBalance::Pressure).
WheelContactReport ReportAt(const ContactLut& lut, Side side, const WheelsetPose& pose, const WheelsetVelocity& velocity,
                            const WheelContactOptions& options, double Q_table, double Q_eff, LutCellInfo* info,
                            LutCreepForce law) {
  const NormalAtPose n = InterpolateNormal(lut, side, pose.lateral_m, pose.yaw_rad, Q_table, Q_eff, law);
  if (info) *info = n.cell;
  WheelContactReport report;
  report.side = side;
  report.model = options.model;
  report.pose = pose;
  report.pose.vertical_m = n.vertical_m;
  report.pose.roll_rad = n.roll_rad;
  if (n.status == kLutNoEquilibrium || n.status == static_cast<int>(WheelContactStatus::NoContact)) {
    report.status = WheelContactStatus::NoContact;
    return report;
  }
  const double V = velocity.forward_speed_m_s;
  const bool kinematics = !options.creepages_given;
  if (kinematics && options.solve_tangential && !n.patches.empty()) {
    require_positive(V, "WheelsetVelocity.forward_speed_m_s");
    require_finite(velocity.lateral_velocity_m_s, "WheelsetVelocity.lateral_velocity_m_s");
    require_finite(velocity.yaw_rate_rad_s, "WheelsetVelocity.yaw_rate_rad_s");
    require_finite(velocity.axle_angular_velocity_rad_s, "WheelsetVelocity.axle_angular_velocity_rad_s");
  }
  for (const LutPatch& q : n.patches) {
    PatchReport p;
    p.model = static_cast<ContactModel>(q.model);
    p.auto_alpha_c_deg = q.auto_alpha_c_deg;
    p.normal_status = "ok";  // the node solutions are accepted ones
    p.fn_N = q.fn_N;
    p.pmax_Pa = q.pmax_Pa;
    p.p0_Pa = p.model == ContactModel::Hertz ? q.pmax_Pa : 0.0;
    p.area_m2 = q.area_m2;
    p.a_m = q.a_m;
    p.b_m = q.b_m;
    p.width_m = q.width_m;
    p.length_m = q.length_m;
    p.approach_m = q.approach_m;
    p.contact_angle_rad = q.contact_angle_rad;
    p.y_contact_rail_m = q.y_contact_rail_m;
    p.z_contact_rail_m = q.z_contact_rail_m;
    p.y_contact_wheel_m = q.y_contact_wheel_m;
    p.rolling_radius_m = q.rolling_radius_m;
    p.lead_m = q.lead_m;
    p.reference_s_on_rail_m = q.rail_s_m;
    p.alpha_c_deg = q.alpha_c_deg;
    p.is_conformal = IsKpModel(p.model) && q.alpha_c_deg > options.conformity_threshold_deg;
    Creepages cr = options.creepages;
    const double u[4] = {1.0, V > 0.0 ? velocity.lateral_velocity_m_s / V : 0.0,
                         V > 0.0 ? velocity.yaw_rate_rad_s / V : 0.0,
                         V > 0.0 ? velocity.axle_angular_velocity_rad_s / V : 0.0};
    if (kinematics && V > 0.0) {
      double c[3] = {0.0, 0.0, 0.0};
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 4; ++k) c[i] += q.creepage_map[4 * i + k] * u[k];
      cr = Creepages{c[0], c[1], c[2]};
    }
    p.xi = cr.longitudinal;
    p.eta = cr.lateral;
    p.phi_per_m = cr.spin_per_m;
    SolveCreep(q, cr, kinematics && V > 0.0 ? u : nullptr, V, options, law, &p);
    p.vertical_force_N = q.pressure_vertical_N + p.fy_N * std::sin(q.contact_angle_rad);
    p.lateral_force_N = q.pressure_lateral_N + p.fy_N * std::cos(q.contact_angle_rad);
    report.vertical_force_N += p.vertical_force_N;
    report.pressure_vertical_force_N += q.pressure_vertical_N;
    report.lateral_force_N += p.lateral_force_N;
    report.patches.push_back(p);
  }
  report.status = n.status == static_cast<int>(WheelContactStatus::Ok)
                      ? (report.patches.empty() ? WheelContactStatus::NoContact : WheelContactStatus::Ok)
                      : WheelContactStatus::NotConverged;
  return report;
}

// An elastic-flange angle as the option gives it: degrees, or none (the rigid flange)
std::string ElasticFlangeText(double max_touching_contact_angle_rad) {
  if (max_touching_contact_angle_rad >= WheelsetTrackGeometry::kAllContactAngles) return "none: rigid flange";
  return MessageNumber(max_touching_contact_angle_rad * 180.0 / M_PI) + " deg";
}

void CheckCompatible(const ContactLut& lut, const WheelsetTrackGeometry& geometry, const WheelContactOptions& o) {
  const ContactLutHeader& h = lut.header;
  auto mismatch = [](const std::string& what, const std::string& table, const std::string& given) {
    throw InputError("contact LUT: " + what + " of the table (" + table + ") differs from the one given (" + given + ")");
  };
  if (o.model != h.model) mismatch("contact model", to_string(h.model), to_string(o.model));
  if (o.material.shear_modulus_Pa != h.material.shear_modulus_Pa || o.material.poisson_ratio != h.material.poisson_ratio)
    mismatch("material", "G " + MessageNumber(h.material.shear_modulus_Pa) + " Pa, nu " +
                             MessageNumber(h.material.poisson_ratio),
             "G " + MessageNumber(o.material.shear_modulus_Pa) + " Pa, nu " + MessageNumber(o.material.poisson_ratio));
  if (o.max_touching_contact_angle_rad != h.max_touching_contact_angle_rad)
    mismatch("elastic flange (--elastic-flange-deg)", ElasticFlangeText(h.max_touching_contact_angle_rad),
             ElasticFlangeText(o.max_touching_contact_angle_rad));
  for (Side s : {Side::Left, Side::Right}) {
    const int i = side_index(s);
    if (std::fabs(geometry.rail_origin_eta_m(s) - h.rail_origin_eta_m[i]) > 1e-9 ||
        std::fabs(geometry.setup().nominal_radius_m[i] - h.nominal_radius_m[i]) > 1e-9)
      throw InputError("contact LUT: the track geometry given is not the table's (rail position or nominal wheel "
                       "radius differ; table made for wheel '" + h.wheel_profile + "' on rail '" + h.rail_profile + "')");
  }
}

}  // namespace

WheelContactReport EvaluateContactLut(const ContactLut& lut, const WheelsetTrackGeometry& geometry, Side side,
                                      const WheelsetPose& pose, const WheelsetVelocity& velocity,
                                      const WheelContactOptions& options, LutCellInfo* info,
                                      const LutEvaluationOptions& evaluation) {
  options.validate();
  const LutCreepForce law = evaluation.creep_force;
  if (law == LutCreepForce::Polach && !options.friction_law.is_constant())
    throw InputError("contact LUT: the polach creep force needs a constant friction coefficient (friction law '" +
                     std::string(to_string(options.friction_law.kind)) + "' given)");
  CheckCompatible(lut, geometry, options);
  if (options.vertical_load_N < 0.0)
    throw InputError("contact LUT: approach mode (vertical_load_N < 0) is not tabulated; give the wheel load");
  if (options.vertical_load_N == 0.0) {  // unloaded wheel: no contact, as the pipeline
    WheelContactReport r;
    r.side = side;
    r.model = options.model;
    r.pose = pose;
    return r;
  }
  const double Q = options.vertical_load_N;
  // (LoadBalance::TotalConsistent: the same balance; the table's nodes are its definition, §17.4)
  const bool total = options.load_balance != LoadBalance::Pressure && options.solve_tangential;
  WheelContactReport r = ReportAt(lut, side, pose, velocity, options, Q, Q, info, law);
  if (total && r.status == WheelContactStatus::Ok) {
    // Total-force balance: Q_eff + C(Q_eff) = Q, C = vertical creep forces (header comment); secant iteration
    // from the fixed-point step, kept inside the bracket of a sign change once there is one (false position when the
    // secant leaves it); a bracket narrower than 1e-9 Q without a root is a jump of the forces in Q_eff (a
    // topology change by the nearest-corner rule, §17.2): not converged, without spending the iteration budget
    auto residual = [&](const WheelContactReport& rep) { return rep.vertical_force_N - Q; };
    double x0 = Q, g0 = residual(r);
    int evaluations = 1;
    const double tolerance = options.load_tolerance * Q;
    if (std::fabs(g0) > tolerance) {
      double lo = 0.0, g_lo = 0.0, hi = 0.0, g_hi = 0.0;  // bracket: g(lo) < 0 < g(hi)
      bool has_lo = false, has_hi = false;
      auto bracket = [&](double x, double g) {
        if (g < 0.0) lo = x, g_lo = g, has_lo = true;
        else hi = x, g_hi = g, has_hi = true;
      };
      bracket(x0, g0);
      double x1 = Q - g0;
      bool converged = false;
      for (; evaluations < 60; ) {
        if (!(x1 >= lut.grid.load_N.front() && x1 <= lut.grid.load_N.back())) {
          char text[256];
          std::snprintf(text, sizeof text, "contact LUT: the total-force balance needs the effective load Q_eff = "
                        "%.6g kN (load %.6g kN minus the vertical creep forces), outside the table's wheel load axis "
                        "[%.6g, %.6g] kN (not extrapolated)", x1 * 1e-3, Q * 1e-3, lut.grid.load_N.front() * 1e-3,
                        lut.grid.load_N.back() * 1e-3);
          throw InputError(text);
        }
        r = ReportAt(lut, side, pose, velocity, options, x1, x1, info, law);
        ++evaluations;
        if (r.status != WheelContactStatus::Ok) break;
        const double g1 = residual(r);
        if (std::fabs(g1) <= tolerance) { converged = true; break; }
        bracket(x1, g1);
        const double slope = (g1 - g0) / (x1 - x0);
        double x2 = slope > 0.0 && std::isfinite(slope) ? x1 - g1 / slope : x1 - g1;
        if (has_lo && has_hi) {
          if (std::fabs(hi - lo) < 1e-9 * Q) break;  // a jump: no root
          const double a = std::min(lo, hi), b = std::max(lo, hi);
          if (!(x2 > a && x2 < b)) x2 = lo - g_lo * (hi - lo) / (g_hi - g_lo);  // false position
        }
        x0 = x1, g0 = g1, x1 = x2;
        if (!(x1 > 0.0)) break;
      }
      if (!converged && r.status == WheelContactStatus::Ok) r.status = WheelContactStatus::NotConverged;
    }
    r.load_iterations = evaluations;
  }
  r.warnings = ContactPlausibilityWarnings(r, geometry, options);
  return r;
}

LutContactFunction MakeLutContactFunction(std::shared_ptr<const ContactLut> lut, LutEvaluationOptions evaluation) {
  if (!lut) throw InputError("contact LUT: no table given");
  return [lut, evaluation](const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                           const WheelsetVelocity& velocity, const WheelContactOptions& options) {
    return EvaluateContactLut(*lut, geometry, side, pose, velocity, options, nullptr, evaluation);
  };
}

const char* to_string(LutCreepForce law) {
  switch (law) {
    case LutCreepForce::Fastsim: return "fastsim";
    case LutCreepForce::Polach: return "polach";
  }
  return "?";
}

LutCreepForce ParseLutCreepForce(const std::string& text) {
  for (LutCreepForce l : {LutCreepForce::Fastsim, LutCreepForce::Polach})
    if (text == to_string(l)) return l;
  throw InputError("contact LUT: unknown creep force '" + text + "' (fastsim, polach)");
}

}  // namespace conforma
