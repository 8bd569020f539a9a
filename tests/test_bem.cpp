// Reference BEM normal solver: Hertz (a/b = 0.2 ... 5), sphere on a plane (CONTACT reference), symmetry,
// conservation, complementarity, FFT = direct summation, load/approach consistency, statuses and input errors.
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "conforma/bem_reference.hpp"
#include "conforma/error.hpp"
#include "conforma/hertz.hpp"

namespace conforma {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<std::vector<std::string>> ReadCsv(const std::string& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in.good()) << path;
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

int Column(const std::vector<std::string>& header, const std::string& name) {
  for (size_t k = 0; k < header.size(); ++k)
    if (header[k] == name) return static_cast<int>(k);
  ADD_FAILURE() << "no column " << name;
  return 0;
}

// Hertzian gaps of contact_hertz_creep_cases.csv (A1, B1 in 1/mm, Fn = 50 kN, G = 82 GPa, nu = 0.28).
struct HertzCase {
  double aob, A_per_m, B_per_m, force_N;
};
std::vector<HertzCase> HertzCases() {
  const auto rows = ReadCsv(std::string(CONFORMA_SHARED_DATA) + "/reference/contact_hertz_creep_cases.csv");
  std::vector<HertzCase> cases;
  if (rows.empty()) return cases;
  const auto& h = rows[0];
  for (size_t r = 1; r < rows.size(); ++r) {
    const auto& row = rows[r];
    if (row[Column(h, "method")] != "exact" || row[Column(h, "creep_set")] != "c1") continue;
    const double aob = std::stod(row[Column(h, "aob")]);
    bool seen = false;  // the file holds several grids per case; the gap and load are the same
    for (const HertzCase& c : cases) seen = seen || c.aob == aob;
    if (seen) continue;
    cases.push_back({std::stod(row[Column(h, "aob")]), std::stod(row[Column(h, "A1_1pmm")]) * 1e3,
                     std::stod(row[Column(h, "B1_1pmm")]) * 1e3, std::stod(row[Column(h, "fn_N")])});
  }
  return cases;
}

TEST(BemHertz, PressureAreaAndApproachAgainstHertzForFiveEllipticities) {
  const Material material;  // G = 82 GPa, nu = 0.28
  const auto cases = HertzCases();
  ASSERT_EQ(cases.size(), 5u);
  for (const HertzCase& c : cases) {
    const HertzResult hz = SolveHertzForLoad(c.A_per_m, c.B_per_m, c.force_N, material);
    ASSERT_EQ(hz.status, HertzStatus::Ok);
    EXPECT_NEAR(hz.a_m / hz.b_m, c.aob, 0.01 * c.aob);
    // Box 1.25x the Hertz semi-axes, 64 x 64 elements (docs/physics-reference.md §10.3 validation set-up).
    const BemGrid grid = QuadraticGapGrid(c.A_per_m, c.B_per_m, 64, 64, 1.25 * hz.a_m, 1.25 * hz.b_m);
    BemOptions options;
    options.normal_force_N = c.force_N;
    const BemResult bem = SolveBemNormal(grid, material, options);
    ASSERT_EQ(bem.status, BemStatus::Converged);
    const double p0_error = bem.max_pressure_Pa / hz.p0_Pa - 1.0;
    const double area_error = bem.contact_area_m2 / (kPi * hz.a_m * hz.b_m) - 1.0;
    const double approach_error = bem.approach_m / hz.approach_m - 1.0;
    std::printf("a/b %4.1f: p0 %8.2f MPa (Hertz %8.2f, %+.3f %%), area %+.3f %%, approach %+.3f %%, "
                "length %+.2f %%, width %+.2f %%, %d iterations\n",
                c.aob, bem.max_pressure_Pa * 1e-6, hz.p0_Pa * 1e-6, 100 * p0_error, 100 * area_error,
                100 * approach_error, 100 * (bem.contact_length_x_m / (2 * hz.a_m) - 1),
                100 * (bem.contact_width_s_m / (2 * hz.b_m) - 1), bem.iterations);
    EXPECT_LT(std::fabs(p0_error), 0.005) << "a/b " << c.aob;
    EXPECT_LT(std::fabs(area_error), 0.02) << "a/b " << c.aob;
    EXPECT_LT(std::fabs(approach_error), 0.005) << "a/b " << c.aob;
    EXPECT_FALSE(bem.contact_at_grid_edge);
    // Conservation: sum p dA = N (flat patch: both force measures agree).
    EXPECT_NEAR(bem.normal_force_reference_N, c.force_N, 1e-9 * c.force_N);
    EXPECT_NEAR(bem.normal_force_surface_N, c.force_N, 1e-9 * c.force_N);
    // Point of action at the centre of the symmetric gap.
    EXPECT_NEAR(bem.centre_of_pressure_x_m, 0.0, 1e-9 * hz.a_m);
    EXPECT_NEAR(bem.centre_of_pressure_s_m, 0.0, 1e-9 * hz.b_m);
  }
}

TEST(BemHertz, SphereOnPlaneAtPrescribedApproachMatchesContactReference) {
  // contact_basic_cases.csv: sphere R = 100 mm on a plane, approach 0.16 mm, G = 82 GPa, nu = 0.28.
  const auto rows = ReadCsv(std::string(CONFORMA_SHARED_DATA) + "/reference/contact_basic_cases.csv");
  double analytic_force = 0.0, contact_force = 0.0;
  for (const auto& row : rows) {
    if (row.size() > 2 && row[0] == "sphere_r100_on_plane" && row[1] == "analytic_hertz") analytic_force = std::stod(row[2]);
    if (row.size() > 2 && row[0] == "sphere_r100_on_plane" && row[1] == "full_bem_0.2mm_grid") contact_force = std::stod(row[2]);
  }
  ASSERT_GT(analytic_force, 0.0);
  const Material material;
  const double radius = 0.1, approach = 0.16e-3;
  const double A = 1.0 / (2.0 * radius);
  const double a = std::sqrt(radius * approach);  // Hertz contact radius, 4 mm
  const BemGrid grid = QuadraticGapGrid(A, A, 64, 64, 1.25 * a, 1.25 * a);
  BemOptions options;
  options.control = BemLoadControl::Approach;
  options.approach_m = approach;
  const BemResult bem = SolveBemNormal(grid, material, options);
  ASSERT_EQ(bem.status, BemStatus::Converged);
  std::printf("sphere: Fn %.1f N (analytic %.0f N, CONTACT BEM %.0f N), error %+.3f %%, p_max %.1f MPa, %d iterations\n",
              bem.normal_force_reference_N, analytic_force, contact_force,
              100 * (bem.normal_force_reference_N / analytic_force - 1), bem.max_pressure_Pa * 1e-6, bem.iterations);
  EXPECT_NEAR(bem.normal_force_reference_N, analytic_force, 0.005 * analytic_force);
  EXPECT_EQ(bem.approach_m, approach);
  // The project's Hertz solution agrees with the file's analytic value.
  const HertzResult hz = SolveHertzForApproach(A, A, approach, material);
  EXPECT_NEAR(hz.normal_force_N, analytic_force, 1e-3 * analytic_force);
  EXPECT_LT(bem.max_complementarity_m, 1e-6 * approach);
}

TEST(BemSolver, ForceAndApproachControlAreInverse) {
  const Material material;
  const BemGrid grid = QuadraticGapGrid(1.0, 2.5, 32, 32, 6e-3, 4e-3);
  BemOptions by_force;
  by_force.normal_force_N = 40e3;
  const BemResult f = SolveBemNormal(grid, material, by_force);
  ASSERT_EQ(f.status, BemStatus::Converged);
  BemOptions by_approach;
  by_approach.control = BemLoadControl::Approach;
  by_approach.approach_m = f.approach_m;
  const BemResult d = SolveBemNormal(grid, material, by_approach);
  ASSERT_EQ(d.status, BemStatus::Converged);
  EXPECT_NEAR(d.normal_force_reference_N, 40e3, 1e-6 * 40e3);
  EXPECT_NEAR((d.pressure_Pa - f.pressure_Pa).cwiseAbs().maxCoeff(), 0.0, 1e-6 * f.max_pressure_Pa);
}

TEST(BemSolver, SymmetryConservationComplementarity) {
  const Material material;
  // Gap symmetric in x and s about the grid centre, non-Hertzian (quartic term in s).
  BemGrid grid = QuadraticGapGrid(1.2, 0.3, 40, 30, 6e-3, 9e-3);
  for (int j = 0; j < grid.ns; ++j)
    for (int i = 0; i < grid.nx; ++i) grid.gap_m(i, j) += 2e3 * std::pow(grid.s_centre_m(j), 4);
  BemOptions options;
  options.normal_force_N = 15e3;
  const BemResult r = SolveBemNormal(grid, material, options);
  ASSERT_EQ(r.status, BemStatus::Converged);
  const double p_max = r.max_pressure_Pa;
  for (int j = 0; j < grid.ns; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      EXPECT_NEAR(r.pressure_Pa(i, j), r.pressure_Pa(grid.nx - 1 - i, j), 1e-7 * p_max);
      EXPECT_NEAR(r.pressure_Pa(i, j), r.pressure_Pa(i, grid.ns - 1 - j), 1e-7 * p_max);
      EXPECT_GE(r.pressure_Pa(i, j), 0.0);
      EXPECT_LT(std::fabs(r.pressure_Pa(i, j) * r.deformed_gap_m(i, j)), 1e-7 * p_max * r.approach_m);
    }
  EXPECT_NEAR(r.pressure_Pa.sum() * grid.element_area_m2(), 15e3, 1e-9 * 15e3);
  EXPECT_LT(r.max_complementarity_m, 1e-6 * r.approach_m);
  EXPECT_FALSE(r.contact_at_grid_edge);
}

TEST(BemSolver, FftEqualsDirectSummationForCurvedBlancoProblem) {
  const Material material;
  BemGrid grid = QuadraticGapGrid(1.0, 1.5, 14, 11, 5e-3, 5e-3);
  grid.alpha_rad.resize(static_cast<size_t>(grid.ns));
  for (int j = 0; j < grid.ns; ++j)  // non-uniform curvature: alpha not linear in s
    grid.alpha_rad[static_cast<size_t>(j)] = 40.0 * grid.s_centre_m(j) + 3e3 * std::pow(grid.s_centre_m(j), 2);
  for (ConformalCoupling coupling : {ConformalCoupling::CombinedBodies, ConformalCoupling::PaperSingleBody}) {
    BemOptions options;
    options.influence = BemInfluence::Blanco;
    options.coupling = coupling;
    options.normal_force_N = 20e3;
    const BemResult fft = SolveBemNormal(grid, material, options);
    options.use_fft = false;
    const BemResult direct = SolveBemNormal(grid, material, options);
    ASSERT_EQ(fft.status, BemStatus::Converged);
    ASSERT_EQ(direct.status, BemStatus::Converged);
    EXPECT_LT((fft.pressure_Pa - direct.pressure_Pa).cwiseAbs().maxCoeff(), 1e-8 * fft.max_pressure_Pa);
    EXPECT_NEAR(fft.approach_m, direct.approach_m, 1e-10 * fft.approach_m);
    // Prescribed along the reference normal: fn_bar = N, fn_tilde > N.
    EXPECT_NEAR(fft.normal_force_reference_N, 20e3, 1e-9 * 20e3);
    EXPECT_GT(fft.normal_force_surface_N, 20e3);
  }
}

TEST(BemSolver, BlancoEqualsHalfSpaceOnAFlatPatchAndCurvedSurfaceForceMeasure) {
  const Material material;
  BemGrid grid = QuadraticGapGrid(1.0, 1.5, 24, 24, 5e-3, 5e-3);
  BemOptions options;
  options.normal_force_N = 20e3;
  const BemResult half_space = SolveBemNormal(grid, material, options);
  options.influence = BemInfluence::Blanco;
  const BemResult blanco = SolveBemNormal(grid, material, options);
  EXPECT_EQ((half_space.pressure_Pa - blanco.pressure_Pa).cwiseAbs().maxCoeff(), 0.0);
  // Curved: prescribing the surface integral fn_tilde.
  grid.alpha_rad.assign(static_cast<size_t>(grid.ns), 0.0);
  for (int j = 0; j < grid.ns; ++j) grid.alpha_rad[static_cast<size_t>(j)] = grid.s_centre_m(j) / 0.012;
  options.force_measure = BemForceMeasure::CurvedSurface;
  const BemResult curved = SolveBemNormal(grid, material, options);
  ASSERT_EQ(curved.status, BemStatus::Converged);
  EXPECT_NEAR(curved.normal_force_surface_N, 20e3, 1e-8 * 20e3);
  EXPECT_LT(curved.normal_force_reference_N, 20e3);
}

TEST(BemSolver, IterationLimitIsAStatusNotAnError) {
  const Material material;
  const BemGrid grid = QuadraticGapGrid(1.0, 1.0, 32, 32, 8e-3, 8e-3);
  BemOptions options;
  options.normal_force_N = 50e3;
  options.max_iterations = 3;
  const BemResult r = SolveBemNormal(grid, material, options);
  EXPECT_EQ(r.status, BemStatus::NotConverged);
  EXPECT_EQ(r.iterations, 3);
  EXPECT_TRUE(std::isfinite(r.approach_m));
  EXPECT_TRUE(r.pressure_Pa.allFinite());
  EXPECT_NEAR(r.normal_force_reference_N, 50e3, 1e-9 * 50e3);  // the force scaling holds at every iterate
}

TEST(BemSolver, NoContactAndBadInput) {
  const Material material;
  const BemGrid grid = QuadraticGapGrid(1.0, 1.0, 8, 8, 1e-3, 1e-3);
  BemOptions options;
  options.normal_force_N = 0.0;
  EXPECT_EQ(SolveBemNormal(grid, material, options).status, BemStatus::NoContact);
  options.control = BemLoadControl::Approach;
  options.approach_m = -1e-6;
  const BemResult apart = SolveBemNormal(grid, material, options);
  EXPECT_EQ(apart.status, BemStatus::NoContact);
  EXPECT_EQ(apart.normal_force_reference_N, 0.0);
  options.control = BemLoadControl::NormalForce;
  options.normal_force_N = -5.0;
  EXPECT_THROW(SolveBemNormal(grid, material, options), InputError);
  options.normal_force_N = std::nan("");
  EXPECT_THROW(SolveBemNormal(grid, material, options), InputError);
  options.normal_force_N = 1e3;
  BemGrid bad = grid;
  bad.gap_m(2, 3) = std::nan("");
  EXPECT_THROW(SolveBemNormal(bad, material, options), InputError);
  bad = grid;
  bad.alpha_rad = {0.1, 0.2};
  EXPECT_THROW(SolveBemNormal(bad, material, options), InputError);
  PatchGeometry patch;
  patch.ds_m = 1e-3;
  patch.s_m = {0.0, 1e-3};
  patch.gap_m = {0.0, 1e-6};
  patch.longitudinal_curvature_per_m = {1.0, -1.0};
  EXPECT_THROW(SolveBemNormal(patch, material, options), InputError);
}

// A Hertzian patch (gap = B s^2 on strips 0.1 mm apart, h = gap + A x^2, offset 0.3 mm along x): the grid is
// built from the element size (§10.4), the strips are resampled onto its columns.
PatchGeometry HertzPatch(double A, double B, double half_width_m) {
  PatchGeometry patch;
  patch.ds_m = 0.1e-3;
  for (double s = -half_width_m; s <= half_width_m + 1e-12; s += patch.ds_m) {
    patch.s_m.push_back(s);
    patch.gap_m.push_back(B * s * s);
    patch.longitudinal_curvature_per_m.push_back(A);
    patch.wheel_radius_m.push_back(1.0 / (2.0 * A));
    patch.alpha_rad.push_back(0.0);
    patch.x_offset_m.push_back(0.3e-3);
  }
  return patch;
}

TEST(BemPatchGrid, ElementSizeGridOverTheInterpenetrationRegionReproducesHertz) {
  const Material material;
  const double A = 1.087, B = 2.5, force = 20e3;
  const HertzResult hz = SolveHertzForLoad(A, B, force, material);
  const PatchGeometry patch = HertzPatch(A, B, 15e-3);
  for (double h : {0.2e-3, 0.1e-3}) {
    BemOptions options;
    options.normal_force_N = force;
    options.element_dx_m = options.element_ds_m = h;
    const BemResult r = SolveBemNormal(patch, material, options);
    ASSERT_EQ(r.status, BemStatus::Converged);
    EXPECT_DOUBLE_EQ(r.grid.dx_m, h);
    EXPECT_DOUBLE_EQ(r.grid.ds_m, h);
    // trimmed: the grid spans the interpenetration region plus the margins, not the 30 mm wide patch
    EXPECT_LT(r.grid.ns * h, 2.0 * std::sqrt(r.approach_m / B) + 2.0 * (patch.ds_m + h) + h + 1e-9);
    EXPECT_FALSE(r.contact_at_grid_edge);
    EXPECT_NEAR(r.normal_force_reference_N, force, 1e-9 * force);
    EXPECT_LT(r.residual, options.tolerance);
    EXPECT_GT(r.residual, 0.0);
    const double p0_error = r.max_pressure_Pa / hz.p0_Pa - 1.0;
    const double approach_error = r.approach_m / hz.approach_m - 1.0;
    std::printf("patch grid %.2f mm: %d x %d, p0 %+.3f %%, approach %+.3f %%, length %+.2f %%, width %+.2f %%, "
                "centre x %.4f mm, %d iterations, residual %.2g\n", h * 1e3, r.grid.nx, r.grid.ns, 100 * p0_error,
                100 * approach_error, 100 * (r.contact_length_x_m / (2 * hz.a_m) - 1),
                100 * (r.contact_width_s_m / (2 * hz.b_m) - 1), r.centre_of_pressure_x_m * 1e3, r.iterations,
                r.residual);
    EXPECT_LT(std::fabs(p0_error), h == 0.2e-3 ? 0.01 : 0.005);
    EXPECT_LT(std::fabs(approach_error), 0.005);
    EXPECT_NEAR(r.contact_length_x_m, 2 * hz.a_m, 2 * h);
    EXPECT_NEAR(r.contact_width_s_m, 2 * hz.b_m, 2 * h);
    EXPECT_NEAR(r.centre_of_pressure_x_m, 0.3e-3, 1e-9);  // the strips' x offset
    EXPECT_NEAR(r.centre_of_pressure_s_m, 0.0, 1e-9);
  }
}

// Strips left out by the candidate search (a silhouette the rail normal cannot reach) leave holes a whole number
// of strips wide: the BEM interpolates across them. Every third strip of the inner 2 mm removed from a Hertzian
// patch: the solution equals that of the full patch whose removed strips carry the linear interpolant of their
// neighbours (what the BEM sees), and stays near the full patch's (the interpolant lifts the gap by B (0.1 mm)^2 =
// 25 nm, a dent of E* 25 nm / 0.2 mm ~ 30 MPa at most in p_max). Holes that are not a whole number of strips are
// rejected.
TEST(BemPatchGrid, HolesOfWholeStripsAreInterpolated) {
  const Material material;
  const PatchGeometry full = HertzPatch(1.087, 2.5, 10e-3);
  PatchGeometry holed;
  holed.ds_m = full.ds_m;
  for (size_t j = 0; j < full.strips(); ++j) {
    if (std::fabs(full.s_m[j]) < 1e-3 && j % 3 == 0) continue;
    holed.s_m.push_back(full.s_m[j]);
    holed.gap_m.push_back(full.gap_m[j]);
    holed.longitudinal_curvature_per_m.push_back(full.longitudinal_curvature_per_m[j]);
    holed.wheel_radius_m.push_back(full.wheel_radius_m[j]);
    holed.alpha_rad.push_back(full.alpha_rad[j]);
    holed.x_offset_m.push_back(full.x_offset_m[j]);
  }
  ASSERT_LT(holed.strips(), full.strips() - 5);
  PatchGeometry filled = full;  // the removed strips with the interpolant of their two neighbours
  for (size_t j = 1; j + 1 < full.strips(); ++j)
    if (std::fabs(full.s_m[j]) < 1e-3 && j % 3 == 0) filled.gap_m[j] = 0.5 * (full.gap_m[j - 1] + full.gap_m[j + 1]);
  BemOptions options;
  options.normal_force_N = 20e3;
  const BemResult a = SolveBemNormal(full, material, options);
  const BemResult b = SolveBemNormal(holed, material, options);
  const BemResult c = SolveBemNormal(filled, material, options);
  ASSERT_EQ(b.status, BemStatus::Converged);
  EXPECT_NEAR(b.max_pressure_Pa, c.max_pressure_Pa, 1e-6 * c.max_pressure_Pa);
  EXPECT_NEAR(b.approach_m, c.approach_m, 1e-6 * c.approach_m);
  EXPECT_NEAR(b.max_pressure_Pa, a.max_pressure_Pa, 30e6);
  EXPECT_NEAR(b.approach_m, a.approach_m, 25e-9);
  EXPECT_NEAR(b.contact_width_s_m, a.contact_width_s_m, 2 * options.element_ds_m);
  PatchGeometry skewed = holed;
  skewed.s_m[3] += 0.3 * skewed.ds_m;  // 1.3 strips from its neighbour
  EXPECT_THROW(SolveBemNormal(skewed, material, options), InputError);
}

// Columns of the strip width on the strip lattice take the strip data as it is (no interpolation error).
TEST(BemPatchGrid, ColumnsOnTheStripsKeepTheStripGaps) {
  const Material material;
  PatchGeometry patch = HertzPatch(1.087, 2.5, 10e-3);
  for (size_t j = 0; j < patch.strips(); ++j) patch.gap_m[j] += 1e-6 * std::sin(3e3 * patch.s_m[j]);  // not linear
  BemOptions options;
  options.control = BemLoadControl::Approach;
  options.approach_m = 30e-6;
  options.element_ds_m = patch.ds_m;
  const BemResult r = SolveBemNormal(patch, material, options);
  ASSERT_EQ(r.status, BemStatus::Converged);
  for (int j = 0; j < r.grid.ns; ++j) {
    const double s = r.grid.s_centre_m(j);
    const long k = std::lround((s - patch.s_m.front()) / patch.ds_m);
    ASSERT_NEAR(s, patch.s_m[static_cast<size_t>(k)], 1e-12);
    const double x = r.grid.x_centre_m(0) - 0.3e-3;
    EXPECT_NEAR(r.grid.gap_m(0, j), patch.gap_m[static_cast<size_t>(k)] + 1.087 * x * x, 1e-15);
  }
}

TEST(BemPatchGrid, GridAboveTheMemoryBudgetIsAnInputErrorNamingGridBudgetAndElementSize) {
  const Material material;
  const PatchGeometry patch = HertzPatch(1.087, 2.5, 15e-3);
  BemOptions options;
  options.normal_force_N = 20e3;
  options.element_dx_m = options.element_ds_m = 0.01e-3;  // ~1000 x 800 elements
  try {
    SolveBemNormal(patch, material, options);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("elements"), std::string::npos) << what;
    EXPECT_NE(what.find(" x "), std::string::npos) << what;
    EXPECT_NE(what.find("250000"), std::string::npos) << what;
    EXPECT_NE(what.find("exact_max_elements"), std::string::npos) << what;
    EXPECT_NE(what.find("exact_element_size_m"), std::string::npos) << what;
  }
  // the same budget for a given grid
  const BemGrid grid = QuadraticGapGrid(1.0, 1.0, 40, 30, 5e-3, 5e-3);
  BemOptions small;
  small.normal_force_N = 1e3;
  small.max_elements = 1199;
  EXPECT_THROW(SolveBemNormal(grid, material, small), InputError);
  small.max_elements = 1200;
  EXPECT_EQ(SolveBemNormal(grid, material, small).status, BemStatus::Converged);
  // and the option ranges
  options.element_dx_m = 0.0;
  EXPECT_THROW(SolveBemNormal(patch, material, options), InputError);
  options.element_dx_m = 0.2e-3;
  options.element_ds_m = std::nan("");
  EXPECT_THROW(SolveBemNormal(patch, material, options), InputError);
  options.element_ds_m = 0.2e-3;
  options.max_elements = 0;
  EXPECT_THROW(SolveBemNormal(patch, material, options), InputError);
}

}  // namespace
}  // namespace conforma
