// Conformal against planar on one situation, and the situation sweeps (threshold.hpp).
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/validation/threshold.hpp"
#include "conforma/validation/worn_heavy_haul_track.hpp"

namespace conforma {

void ThresholdOptions::validate() const {
  require_positive(tolerance, "tolerance");
  if (kp_strips < 3) throw InputError("threshold: kp_strips must be >= 3");
  if (fastsim_elements < 2) throw InputError("threshold: fastsim_elements must be >= 2");
}

const char* to_string(PlanarComparison comparison) {
  switch (comparison) {
    case PlanarComparison::FlattenedKp: return "flat_kp";
    case PlanarComparison::CurvilinearKp: return "kp";
    case PlanarComparison::Hertz: return "hertz";
  }
  return "?";
}

const char* to_string(ThresholdReference reference) {
  return reference == ThresholdReference::Exact ? "exact" : "conformal";
}

ThresholdReference ParseThresholdReference(const std::string& name) {
  for (ThresholdReference r : {ThresholdReference::Conformal, ThresholdReference::Exact})
    if (name == to_string(r)) return r;
  throw InputError("unknown threshold reference '" + name + "' (expected conformal or exact)");
}

PlanarComparison ParsePlanarComparison(const std::string& name) {
  for (PlanarComparison c : {PlanarComparison::FlattenedKp, PlanarComparison::CurvilinearKp, PlanarComparison::Hertz})
    if (name == to_string(c)) return c;
  throw InputError("unknown planar comparison '" + name + "' (expected flat_kp, kp or hertz)");
}

namespace {

// What the threshold compares of one solve, from the bench's patch result or from the exact reference.
struct Compared {
  bool in_contact = false;
  double pmax_Pa = 0.0, area_m2 = 0.0, fx_N = 0.0, fy_N = 0.0, wear_index_N = 0.0, alpha_c_deg = 0.0;
  std::string status;  // "normal/tangential"
};
Compared FromBench(const BenchPatchResult& r) {
  return {r.in_contact, r.pmax_Pa, r.area_m2, r.fx_N, r.fy_N, r.wear_index_N, r.alpha_c_deg,
          r.normal_status + "/" + r.tangential_status};
}
Compared FromExact(const BenchReference& r) {
  return {r.converged, r.pmax_Pa, r.area_m2, r.fx_N, r.fy_N, r.wear_index_N, r.alpha_c_deg,
          r.normal_status + "/" + r.tangential_status};
}

}  // namespace

ThresholdPoint CompareConformalPlanar(const BenchCase& situation, const ThresholdOptions& options) {
  options.validate();
  ThresholdPoint t;
  // the planar model's patch first: a patch that cannot be flattened ends here, before any (exact: costly) solve
  BenchCase planar = situation;
  if (options.against == PlanarComparison::FlattenedKp) {
    try {
      planar.patch = FlattenPatch(situation.patch);
    } catch (const InputError& e) {
      t.name = situation.name, t.family = situation.family, t.status = std::string("flatten: ") + e.what();
      return t;
    }
  }
  PatchSolveOptions o;
  o.kp_strips = options.kp_strips;
  o.fastsim_elements = options.fastsim_elements;
  o.variable_epsilon = options.variable_epsilon;
  o.model = ContactModel::Conformal;
  const Compared c = options.reference == ThresholdReference::Exact ? FromExact(SolveBenchReference(situation))
                                                                      : FromBench(SolveBenchCase(situation, o));
  // The planar KP-type model with the SAME virtual-penetration rule as the conformal model (KPEC for the default
  // variable eps, KP for eps = 0.55), so that the difference isolates the conformity (curved surface + Blanco
  // influence) and not the penetration rule.
  o.model = options.against == PlanarComparison::Hertz ? ContactModel::Hertz
            : o.variable_epsilon                       ? ContactModel::Kpec
                                                       : ContactModel::Kp;
  const Compared p = FromBench(SolveBenchCase(planar, o));
  t.name = situation.name;
  t.family = situation.family;
  t.alpha_c_deg = c.alpha_c_deg;
  t.contact_angle_deg = situation.patch.contact_angle_rad * 180.0 / M_PI;
  t.status = c.status + "|" + p.status;
  t.valid = c.in_contact && p.in_contact && c.pmax_Pa > 0.0 && c.area_m2 > 0.0;
  if (!t.valid) return t;
  auto rel = [](double a, double b) { return a != 0.0 ? std::fabs(a - b) / std::fabs(a) : (b == 0.0 ? 0.0 : 1.0); };
  t.d_pmax = rel(c.pmax_Pa, p.pmax_Pa);
  t.d_area = rel(c.area_m2, p.area_m2);
  const double ft = std::hypot(c.fx_N, c.fy_N);
  t.d_creep = ft > 0.0 ? std::hypot(c.fx_N - p.fx_N, c.fy_N - p.fy_N) / ft : 0.0;
  t.d_wear = rel(c.wear_index_N, p.wear_index_N);
  t.d_max = std::max({t.d_pmax, t.d_area, t.d_creep, t.d_wear});
  return t;
}

std::vector<ThresholdPoint> CompareConformalPlanar(const std::vector<BenchCase>& situations,
                                                   const ThresholdOptions& options) {
  options.validate();
  std::vector<ThresholdPoint> out(situations.size());
  ProgressCounter progress(options.on_progress, static_cast<double>(situations.size()));
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < static_cast<int>(situations.size()); ++i) {
    const ProgressCounter::Unit counted(progress, situations[i].name);
    // an exception must not leave the parallel region: a situation a model rejects is recorded as not valid, with
    // the error as its status (threshold.csv), and the sweep goes on
    try {
      out[i] = CompareConformalPlanar(situations[i], options);
    } catch (const std::exception& e) {
      out[i].name = situations[i].name;
      out[i].family = situations[i].family;
      out[i].failed = true;
      out[i].status = std::string("error: ") + e.what();
    }
  }
  return out;
}

std::vector<BenchCase> MakeThresholdSituations(const std::string& set, const std::string& shared_data_dir,
                                               double vertical_load_N) {
  const FastsimCreepages creepages{1.0e-3, 0.5e-3, 0.2};
  if (set == "groove") {
    return MakeGrooveBenchCases({14.0e-3, 12.0e-3, 11.0e-3, 10.5e-3, 10.25e-3, 10.1e-3, 10.05e-3, 10.02e-3},
                                vertical_load_N);
  }
  TrackSetup setup;
  int k_max = 100;  // lateral shifts -4 ... 10 mm in 0.1 mm steps
  if (set == "new") {
    setup = MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0), std::atan(1.0 / 20.0));
  } else if (set == "worn") {
    // the worn heavy-haul pair on its measured track (issue 15), up to the conformal gauge-corner contact at
    // 15.0-15.5 mm
    setup = WornHeavyHaulTrack(shared_data_dir);
    k_max = 155;
  } else {
    throw InputError("threshold: unknown situation set '" + set + "' (expected new, worn or groove)");
  }
  const WheelsetTrackGeometry geometry(setup);
  Material steel;
  std::vector<BenchCase> out;
  for (double yaw_mrad : {0.0, 5.0, 10.0, 15.0, 20.0}) {
    for (int k = -40; k <= k_max; ++k) {
      WheelsetPose pose;
      pose.lateral_m = k * 0.1e-3;
      pose.yaw_rad = yaw_mrad * 1e-3;
      char name[64];
      std::snprintf(name, sizeof name, "%s_y%.2f_yaw%.0f", set.c_str(), k * 0.1, yaw_mrad);
      const auto found = BenchCasesFromPose(geometry, Side::Left, pose, vertical_load_N, steel, creepages, name, set);
      out.insert(out.end(), found.begin(), found.end());
    }
  }
  return out;
}

}  // namespace conforma
