// Roller-rig adhesion tests of paper 000: table, rig contact, linear theory, FASTSIM creep curve
// (conforma/validation/roller_rig_adhesion.hpp, docs/physics-reference.md §7.5).
#include "conforma/validation/roller_rig_adhesion.hpp"

#include <cmath>
#include <fstream>

#include "conforma/csv_columns.hpp"
#include "conforma/error.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/geometry.hpp"
#include "conforma/kalker.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_contact_options.hpp"

namespace conforma {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kMaxAdhesion = 1.0;  // F_x / N of steel on steel (dry tests: ~0.4-0.6)
const char* const kColumns[] = {"test", "reference_speed_rpm", "wheel_load_kg", "max_adhesion",
                                "steady_adhesion", "initial_slope_N", "condition"};
}  // namespace

std::vector<RollerRigAdhesionTest> ReadRollerRigAdhesionTable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "cannot be read");
  std::vector<RollerRigAdhesionTest> tests;
  std::string line;
  int line_no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string trimmed = TrimCsvCell(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    const std::vector<std::string> cells = SplitCsvCells(trimmed);
    if (!header) {
      if (cells.size() != 7) throw InputError(path, line_no, "expected the 7 columns of Table 6 in the header");
      for (int c = 0; c < 7; ++c)
        if (cells[c] != kColumns[c])
          throw InputError(path, line_no, "column " + std::to_string(c + 1) + " must be '" + kColumns[c] + "'");
      header = true;
      continue;
    }
    if (cells.size() != 7) throw InputError(path, line_no, "expected 7 cells");
    RollerRigAdhesionTest t;
    const double test_number = ParseCsvNumber(cells[0], kColumns[0], path, line_no);
    if (!(test_number >= 0.0 && test_number <= 1e6 && test_number == std::floor(test_number)))
      throw InputError(path, line_no, "test number '" + cells[0] + "' is not a whole number 0 ... 1000000");
    t.test = static_cast<int>(test_number);
    t.reference_speed_rpm = ParseCsvNumber(cells[1], kColumns[1], path, line_no);
    t.wheel_load_kg = ParseCsvNumber(cells[2], kColumns[2], path, line_no);
    t.max_adhesion = ParseCsvNumber(cells[3], kColumns[3], path, line_no);
    t.steady_adhesion = ParseCsvNumber(cells[4], kColumns[4], path, line_no);
    t.initial_slope_N = ParseCsvNumber(cells[5], kColumns[5], path, line_no);
    t.condition = cells[6];
    if (t.reference_speed_rpm <= 0.0 || t.wheel_load_kg <= 0.0 || t.initial_slope_N <= 0.0)
      throw InputError(path, line_no, "speed, load and slope must be > 0");
    if (t.max_adhesion <= 0.0 || t.steady_adhesion <= 0.0 || t.steady_adhesion > t.max_adhesion)
      throw InputError(path, line_no, "adhesion coefficients must satisfy 0 < steady <= max");
    // bounds of a wheel-rail (or scaled rig) adhesion test: beyond them a unit or column mistake
    if (t.max_adhesion > kMaxAdhesion)
      throw InputError(path, line_no, "max_adhesion " + cells[3] +
                                          " is not a wheel-rail adhesion coefficient (F_x / N <= 1): a percentage?");
    if (t.reference_speed_rpm > kMaxRollerRigSpeedRpm)
      throw InputError(path, line_no, "reference_speed_rpm " + cells[1] + " is beyond a roller rig's " +
                                          MessageNumber(kMaxRollerRigSpeedRpm) + " rpm");
    // the wheel-load bound of RequireWheelLoad, in kg at the options' default gravity (the table is read before them)
    const double gravity = RollerRigAdhesionOptions{}.gravity_m_per_s2;
    if (t.wheel_load_kg * gravity > kMaxWheelLoadN)
      throw InputError(path, line_no, "wheel_load_kg " + cells[2] + " is beyond a wheel's load (at most " +
                                          MessageNumber(kMaxWheelLoadN / gravity) + " kg: " +
                                          MessageNumber(kMaxWheelLoadN) + " N)");
    for (const RollerRigAdhesionTest& other : tests)
      if (other.test == t.test)
        throw InputError(path, line_no, "test " + std::to_string(t.test) + " is given twice");
    if (t.condition != "dry" && t.condition != "wet")
      throw InputError(path, line_no, "condition '" + t.condition + "': expected dry or wet");
    tests.push_back(t);
  }
  if (tests.empty()) throw InputError(path, 0, "no test rows");
  return tests;
}

const char* to_string(RollerProfileChoice choice) {
  return choice == RollerProfileChoice::ScaledUic60 ? "scaled_uic60" : "track_ellipse_ratio";
}

void RollerRigAdhesionOptions::validate() const {
  require_positive(wheel_radius_m, "wheel_radius_m");
  require_positive(roller_radius_m, "roller_radius_m");
  require_positive(length_factor, "length_factor");
  require_positive(gravity_m_per_s2, "gravity_m_per_s2");
  material.validate();
  if (fastsim_elements < 4) throw InputError("fastsim_elements must be >= 4");
}

RollerRigCurvatures RollerRigCentredCurvatures(const RollerRigAdhesionOptions& options) {
  options.validate();
  // Full-scale wheelset: S1002 on 60E1 canted 1:20 (paper 000 §4), nominal radius r_w / phi.
  TrackSetup track = MakeSymmetricTrack(MakeS1002(), MakeRail(RailSection::R60E1, 0.0), rail_inclination_1in20());
  const double r_full = options.wheel_radius_m / options.length_factor;
  track.nominal_radius_m = {r_full, r_full};
  const WheelsetTrackGeometry geometry(track);
  const EquilibriumResult eq = geometry.SolveRigidEquilibrium(0.0, 0.0);
  if (eq.status != EquilibriumStatus::Converged || eq.contact.wheel[0].points.empty())
    throw InputError("roller rig: no centred S1002 / 60E1 1:20 contact (equilibrium " +
                     std::string(to_string(eq.status)) + ")");
  const RigidContactPoint& p = eq.contact.wheel[0].points.front();
  RollerRigCurvatures c;
  c.full_scale_A_per_m = p.hertz_A_per_m;
  c.full_scale_B_per_m = p.hertz_B_per_m;
  c.full_scale_wheel_curvature_per_m = p.wheel_lateral_curvature_per_m;
  c.full_scale_rail_curvature_per_m = p.rail_lateral_curvature_per_m;
  c.contact_angle_rad = p.contact_angle_rad;
  c.wheel_profile_y_m = p.wheel_profile_m.x();
  // Rig: both bodies curved along x (issue 18: A gets 1/(2 R_r)); transverse curvatures scale as 1/phi.
  c.A_per_m = 0.5 / options.wheel_radius_m + 0.5 / options.roller_radius_m;
  if (options.roller_profile == RollerProfileChoice::ScaledUic60)
    c.B_per_m = c.full_scale_B_per_m / options.length_factor;
  else
    c.B_per_m = c.A_per_m * c.full_scale_B_per_m / c.full_scale_A_per_m;  // same A/B, same a/b as on track
  return c;
}

RollerRigLinearContact RollerRigLinearTheory(const RollerRigCurvatures& curvatures, double normal_force_N,
                                             const Material& material) {
  require_positive(normal_force_N, "roller rig normal force");
  RollerRigLinearContact r;
  r.normal_force_N = normal_force_N;
  r.hertz = SolveHertzForLoad(curvatures.A_per_m, curvatures.B_per_m, normal_force_N, material);
  if (r.hertz.status != HertzStatus::Ok) throw InputError("roller rig: the Hertz problem has no solution");
  r.c11 = KalkerCoefficients(r.hertz.a_over_b, material.poisson_ratio).c11;
  // Paper 000 eq. 22 (Kalker's linear theory): F_x = G a b C11 xi.
  r.linear_slope_N = material.shear_modulus_Pa * r.hertz.a_m * r.hertz.b_m * r.c11;
  return r;
}

double RollerRigRollingSpeed(double reference_speed_rpm, double roller_radius_m) {
  require_positive(reference_speed_rpm, "reference_speed_rpm");
  require_positive(roller_radius_m, "roller_radius_m");
  return reference_speed_rpm * 2.0 * kPi / 60.0 * roller_radius_m;  // paper 000 eq. 13, V0 = omega_r r_r
}

double RollerRigTractionCoefficient(const RollerRigLinearContact& contact, const Material& material,
                                    const FrictionLaw& law, double slope_reduction, double creepage,
                                    double rolling_speed_m_per_s, int elements) {
  require_non_negative(creepage, "creepage");
  require_positive(rolling_speed_m_per_s, "rolling speed");
  FastsimHertzInput input;
  input.a_m = contact.hertz.a_m;
  input.b_m = contact.hertz.b_m;
  input.normal_force_N = contact.normal_force_N;
  input.creepages.xi = creepage;
  input.friction_coefficient = law.static_value();
  input.material = material;
  input.nx = elements;
  input.ny = elements;
  input.rolling_speed_m_per_s = rolling_speed_m_per_s;
  FastsimOptions options;  // elliptic bound, centre-exact marching, no blending
  FastsimPatch patch;
  BuildFastsimHertzPatch(input, options, &patch);
  const FastsimFlexibilities flex =
      ReducedFlexibilities(FastsimHertzFlexibilities(input, options), slope_reduction);
  FastsimResult result;
  SolveFastsimStripsWithLaw(patch, flex, input.creepages, law, rolling_speed_m_per_s, options, &result);
  return -result.fx_N / contact.normal_force_N;
}

}  // namespace conforma
