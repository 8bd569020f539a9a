// Manchester benchmark runner (validation_manchester.hpp).
#include <cmath>
#include <fstream>
#include <sstream>

#include "conforma/error.hpp"
#include "conforma/parallel_error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/validation/validation_manchester.hpp"

namespace conforma {

std::vector<ManchesterReferenceCase> ReadManchesterReference(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot open the Manchester reference file");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) names.push_back(c);
  }
  auto column = [&](const char* name) {
    for (size_t i = 0; i < names.size(); ++i)
      if (names[i] == name) return i;
    throw InputError(path, 1, std::string("missing column '") + name + "'");
  };
  const size_t c_case = column("case"), c_y = column("y_ws_mm"), c_yaw = column("yaw_mrad"), c_roll = column("roll_ws_rad"),
               c_ycp = column("y_cp_rail_mm"), c_d = column("delta_cp_rad"), c_fn = column("fn_N"), c_fx = column("fx_N"),
               c_fs = column("fs_N"), c_mn = column("mn_Nmm"), c_xi = column("xi"), c_eta = column("eta"),
               c_phi = column("phi_per_mm"), c_p = column("p_max_MPa"), c_a = column("area_mm2");
  std::vector<ManchesterReferenceCase> cases;
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(c);
    if (cells.size() < names.size()) throw InputError(path, number, "too few columns");
    auto num = [&](size_t i) {
      try {
        size_t used = 0;
        const double v = std::stod(cells[i], &used);
        if (used == cells[i].size()) return v;
      } catch (const std::exception&) {
      }
      throw InputError(path, number, "non-numeric value '" + cells[i] + "' in column " + names[i]);
    };
    ManchesterReferenceCase c;
    c.id = static_cast<int>(num(c_case));
    c.y_ws_mm = num(c_y), c.yaw_mrad = num(c_yaw), c.roll_rad = num(c_roll);
    c.y_cp_rail_mm = num(c_ycp), c.delta_cp_rad = num(c_d);
    c.fn_N = num(c_fn), c.fx_N = num(c_fx), c.fs_N = num(c_fs), c.mn_Nmm = num(c_mn);
    c.xi = num(c_xi), c.eta = num(c_eta), c.phi_per_mm = num(c_phi);
    c.p_max_MPa = num(c_p), c.area_mm2 = num(c_a);
    cases.push_back(c);
  }
  return cases;
}

std::vector<ManchesterComparison> RunManchesterA22(const std::string& shared_data_dir, const ManchesterOptions& options) {
  const std::string examples = shared_data_dir + "/profiles/contact/examples/";
  ProfileReadOptions wheel_read, rail_read;
  wheel_read.kind = ProfileKind::Wheel;
  rail_read.kind = ProfileKind::Rail;
  TrackSetup setup = MakeSymmetricTrack(LoadProfile(examples + "MBench_S1002_v3.prw", wheel_read),
                                        LoadProfile(examples + "MBench_UIC60_v3.prr", rail_read), 0.0);
  const WheelsetTrackGeometry geometry(setup);
  const auto cases = ReadManchesterReference(shared_data_dir + "/reference/contact_mbench_a22_left.csv");
  WheelContactOptions contact;
  contact.model = options.model;
  contact.material.shear_modulus_Pa = 82e9;
  contact.material.poisson_ratio = 0.28;
  contact.friction_coefficient = 0.3;
  contact.vertical_load_N = 10e3;
  contact.fastsim_elements = options.fastsim_elements;
  contact.creepages_given = options.creepages_from_file;
  contact.kp_spin_about_patch_centre = options.kp_spin_about_patch_centre;
  contact.kp_local_flexibilities = options.kp_local_flexibilities;
  contact.load_balance = options.load_balance;
  contact.validate();  // before the parallel loop: an exception may not leave an OpenMP region (it aborted Python)
  std::vector<ManchesterComparison> out(cases.size());
  ProgressCounter progress(options.on_progress, static_cast<double>(cases.size()));
  LowestIndexError error;
#pragma omp parallel for schedule(dynamic)
  for (int i = 0; i < static_cast<int>(cases.size()); ++i) try {
    const ManchesterReferenceCase& c = cases[i];
    const ProgressCounter::Unit counted(progress, "case " + std::to_string(c.id));
    ManchesterComparison& r = out[i];
    r.reference = c;
    WheelsetPose pose;
    pose.lateral_m = -c.y_ws_mm * 1e-3;  // CONTACT's track y points to the right
    pose.yaw_rad = -c.yaw_mrad * 1e-3;
    pose.roll_rad = c.roll_rad;
    WheelContactOptions o = contact;
    o.creepages = {c.xi, c.eta, c.phi_per_mm * 1e3};
    const WheelsetVelocity velocity{2.0, 0.0, 0.0, 2.0 / 0.46};
    r.report = SolveWheelContact(geometry, Side::Left, pose, velocity, o);
    if (options.creepages_from_file && options.creepage_origin == ManchesterCreepageOrigin::ContactReferencePoint) {
      // the creepages moved from CONTACT's reference point to ours (validation_manchester.hpp); our reference point
      // is that of the first solve (xi changes the push-down of the total-force balance only slightly)
      if (const PatchReport* ours = MainPatch(r.report)) {
        const double y_cp_ours_m = -ours->y_contact_rail_m;  // CONTACT's rail y (see the frame mapping above)
        o.creepages.longitudinal = c.xi + o.creepages.spin_per_m * (y_cp_ours_m - c.y_cp_rail_mm * 1e-3);
        r.report = SolveWheelContact(geometry, Side::Left, pose, velocity, o);
      }
    }
    r.patches = static_cast<int>(r.report.patches.size());
    const PatchReport* main = MainPatch(r.report);
    if (!main) continue;
    double fn = 0.0, fx = 0.0, fs = 0.0, area = 0.0;
    for (const PatchReport& p : r.report.patches) fn += p.fn_N, fx += p.fx_N, fs += p.fy_N, area += p.area_m2;
    r.fn_N = fn;
    r.pmax_MPa = main->pmax_Pa * 1e-6;
    r.area_mm2 = area * 1e6;
    r.fx_N = fx;
    r.fs_N = fs;
    r.y_cp_mm = -main->y_contact_rail_m * 1e3;
    r.delta_rad = main->contact_angle_rad;
    r.err_fn = fn / c.fn_N - 1.0;
    r.err_pmax = r.pmax_MPa / c.p_max_MPa - 1.0;
    r.err_area = r.area_mm2 / c.area_mm2 - 1.0;
    r.err_fx_N = fx - c.fx_N;
    r.err_fs_N = fs - c.fs_N;
  } catch (const std::exception& e) {
    error.Record(i, e);
  }
  if (error.any()) throw InputError("Manchester case " + std::to_string(cases[error.index()].id) + ": " + error.what());
  return out;
}

}  // namespace conforma
