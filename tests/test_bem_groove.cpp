// Reference BEM on the deep conformal groove of CONTACT's groove_li example (shared data
// reference/contact_groove_li.csv): wheel circle R = 10 mm in grooves R = 10.25 ... 10.02 mm, Fz = 10 kN,
// G = 80 GPa, nu = 0.28, rolling radius 420 mm, CONTACT grid 0.0958 x 0.25 mm.
//
// The patch is built analytically. The curved reference surface is a circle concentric with the groove,
// of radius R_ref = (R_wheel + R_groove) / 2 (CONTACT's "curved reference surface" for this case: its
// printed table has alpha = s / 10.125 mm for the 10.25 mm groove); s is the arc length on it, the local
// normal is the ray from the groove centre, alpha(s) = -s / R_ref (concave rail: the outward normal turns
// towards -s as s grows; only cos(alpha) enters with the default coupling). Along the ray at angle theta
// the gap between groove (radius R_r about the origin) and wheel circle (radius R_w about (0, -e),
// e = R_r - R_w, touching at theta = 0) is
//     h(theta) = R_r - e cos(theta) - sqrt(R_w^2 - e^2 sin^2(theta)).
// The longitudinal curvature is A = cos(theta_w) / (2 r) with the wheel rolling radius
// r = 420 mm - R_r + t cos(theta) at the wheel point t (distance from the groove centre), theta_w the angle
// of the wheel's own normal there (patch.hpp, Meusnier).
// test-links: conformal  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "conforma/bem_reference.hpp"

namespace conforma {
namespace {

struct GrooveRow {
  int id;
  double groove_radius_mm;
  std::string influence;
  double fn_bar_N, fn_tilde_N, approach_mm, p_max_MPa;
  int ncon;
  double s_min_mm, s_max_mm, angle_deg;
};

std::vector<GrooveRow> ReadGrooveRows() {
  std::ifstream in(std::string(CONFORMA_SHARED_DATA) + "/reference/contact_groove_li.csv");
  EXPECT_TRUE(in.good());
  std::vector<GrooveRow> rows;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::vector<std::string> c;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) c.push_back(cell);
    if (c.size() < 10) continue;
    GrooveRow r;
    r.id = std::stoi(c[0]);
    r.groove_radius_mm = std::stod(c[1]);
    r.influence = c[2];
    r.fn_bar_N = std::stod(c[3]);
    r.fn_tilde_N = std::stod(c[4]);
    r.approach_mm = std::stod(c[5]);
    r.p_max_MPa = std::stod(c[6]);
    r.ncon = std::stoi(c[7]);
    r.s_min_mm = std::stod(c[8].substr(0, c[8].find(':')));
    r.s_max_mm = std::stod(c[8].substr(c[8].find(':') + 1));
    r.angle_deg = std::stod(c[9].substr(0, c[9].find(':')));
    rows.push_back(r);
  }
  return rows;
}

// Analytic groove patch (see the file comment). Strips of width ds centred on s = 0, covering the region
// where the gap is below max_gap cos(theta) (the approach closes at most that much; capped at 80 degrees).
PatchGeometry GroovePatch(double wheel_radius, double groove_radius, double reference_radius, double rolling_radius,
                          double ds, double max_gap) {
  const double e = groove_radius - wheel_radius;
  auto wheel_distance = [&](double theta) {  // distance from the groove centre to the wheel along the ray
    return e * std::cos(theta) + std::sqrt(wheel_radius * wheel_radius - e * e * std::sin(theta) * std::sin(theta));
  };
  const double theta_cap = 80.0 * 3.14159265358979323846 / 180.0;
  int half = 0;
  while (true) {
    const double theta = (half + 1) * ds / reference_radius;
    if (theta > theta_cap || groove_radius - wheel_distance(theta) > max_gap * std::cos(theta)) break;
    ++half;
  }
  PatchGeometry patch;
  patch.ds_m = ds;
  for (int k = -half; k <= half; ++k) {
    const double s = k * ds, theta = s / reference_radius;
    const double t = wheel_distance(theta);
    const double theta_wheel = std::atan2(t * std::sin(theta), t * std::cos(theta) - e);
    const double r = rolling_radius - groove_radius + t * std::cos(theta);
    patch.s_m.push_back(s);
    patch.gap_m.push_back(groove_radius - t);
    patch.longitudinal_curvature_per_m.push_back(std::cos(theta_wheel) / (2.0 * r));
    patch.wheel_radius_m.push_back(r);
    patch.alpha_rad.push_back(-theta);
    patch.x_offset_m.push_back(0.0);
  }
  return patch;
}

Material GrooveMaterial() {
  Material material;
  material.shear_modulus_Pa = 80e9;
  material.poisson_ratio = 0.28;
  return material;
}

constexpr double kWheelRadius = 10e-3, kRollingRadius = 0.420, kStripWidth = 0.25e-3;
double ReferenceRadius(const GrooveRow& row) { return 0.5 * (kWheelRadius + row.groove_radius_mm * 1e-3); }
PatchGeometry PatchFor(const GrooveRow& row) {
  return GroovePatch(kWheelRadius, row.groove_radius_mm * 1e-3, ReferenceRadius(row), kRollingRadius, kStripWidth,
                     0.03e-3);
}

BemResult Solve(const PatchGeometry& patch, BemInfluence influence, double force, BemForceMeasure measure,
                ConformalCoupling coupling = ConformalCoupling::CombinedBodies) {
  BemOptions options;
  options.influence = influence;
  options.coupling = coupling;
  options.normal_force_N = force;
  options.force_measure = measure;
  options.element_dx_m = 0.095833e-3;   // CONTACT's grid 0.0958 x 0.25 mm
  options.element_ds_m = kStripWidth;    // columns on the strips
  return SolveBemNormal(patch, GrooveMaterial(), options);
}

void Print(const char* label, const GrooveRow& row, const BemResult& r) {
  std::printf("case %d R %.2f %-10s %-14s: p_max %6.1f MPa (CONTACT %6.1f, %+5.2f %%), fn_bar %6.0f fn_tilde %6.0f "
              "(CONTACT %5.0f), approach %.5f mm (CONTACT %.5f, %+5.2f %%), s %+.3f:%+.3f mm (CONTACT %+.3f:%+.3f), "
              "area %.2f mm2 (CONTACT %.2f), %d it\n",
              row.id, row.groove_radius_mm, row.influence.c_str(), label, r.max_pressure_Pa * 1e-6, row.p_max_MPa,
              100 * (r.max_pressure_Pa * 1e-6 / row.p_max_MPa - 1), r.normal_force_reference_N, r.normal_force_surface_N,
              row.fn_tilde_N, r.approach_m * 1e3, row.approach_mm, 100 * (r.approach_m * 1e3 / row.approach_mm - 1),
              r.contact_s_min_m * 1e3, r.contact_s_max_m * 1e3, row.s_min_mm, row.s_max_mm, r.contact_area_m2 * 1e6,
              row.ncon * 0.095833 * 0.25, r.iterations);
}

TEST(BemGroove, ReferenceSurfaceConventionMatchesTheFile) {
  // The file's contact angle is alpha at the outermost contact element centre: (s_max - ds/2) / R_ref with
  // R_ref = (R_w + R_groove)/2; with R_groove instead it would be 0.2 - 0.5 degrees off.
  for (const GrooveRow& row : ReadGrooveRows()) {
    const double s_centre = row.s_max_mm * 1e-3 - 0.5 * kStripWidth;
    EXPECT_NEAR(s_centre / ReferenceRadius(row) * 180.0 / 3.14159265358979323846, row.angle_deg, 0.01) << row.id;
  }
}

// Fz = 10 kN vertical, prescribed as the force along the reference normal (fn_bar = sum p cos(alpha) dA):
// vertical equilibrium of a frictionless patch.
TEST(BemGroove, PeakPressureAgainstContactAtVerticalLoad) {
  const auto rows = ReadGrooveRows();
  ASSERT_EQ(rows.size(), 8u);
  for (const GrooveRow& row : rows) {
    const bool blanco = row.influence != "half-space";
    const BemResult r = Solve(PatchFor(row), blanco ? BemInfluence::Blanco : BemInfluence::HalfSpace, 10e3,
                              BemForceMeasure::ReferenceNormal);
    Print("Fz as fn_bar", row, r);
    ASSERT_EQ(r.status, BemStatus::Converged) << row.id;
    EXPECT_FALSE(r.contact_at_grid_edge) << row.id;
    EXPECT_NEAR(r.normal_force_reference_N, 10e3, 1e-8 * 10e3);
    EXPECT_GT(r.normal_force_surface_N, r.normal_force_reference_N);
    // Contact extent along the groove within one strip of CONTACT's, symmetric.
    EXPECT_NEAR(r.contact_s_max_m * 1e3, row.s_max_mm, 0.251) << row.id;
    EXPECT_NEAR(r.contact_s_min_m * 1e3, row.s_min_mm, 0.251) << row.id;
    EXPECT_NEAR(r.centre_of_pressure_s_m, 0.0, 1e-9);
    if (blanco) {
      EXPECT_LT(std::fabs(r.max_pressure_Pa * 1e-6 / row.p_max_MPa - 1.0), 0.05) << "case " << row.id;
    }
  }
}

// Half-space with equal materials: the normal problem does not feel the tangential tractions (K = 0), so
// with the same curved-surface normal load fn_tilde as CONTACT's steady-rolling solution (whose frictional
// tractions carry part of Fz) the normal solution must coincide with CONTACT's.
TEST(BemGroove, HalfSpaceMatchesContactAtTheSameSurfaceLoad) {
  for (const GrooveRow& row : ReadGrooveRows()) {
    if (row.influence != "half-space") continue;
    const BemResult r = Solve(PatchFor(row), BemInfluence::HalfSpace, row.fn_tilde_N, BemForceMeasure::CurvedSurface);
    Print("fn_tilde", row, r);
    ASSERT_EQ(r.status, BemStatus::Converged) << row.id;
    EXPECT_NEAR(r.normal_force_surface_N, row.fn_tilde_N, 1e-6 * row.fn_tilde_N);
    EXPECT_LT(std::fabs(r.max_pressure_Pa * 1e-6 / row.p_max_MPa - 1.0), 0.01) << "case " << row.id;
    EXPECT_LT(std::fabs(r.approach_m * 1e3 / row.approach_mm - 1.0), 0.01) << "case " << row.id;
  }
}

// Blanco rows with CONTACT's fn_tilde and with paper 003's single-body coupling (eq. 5). Reported; the
// remaining p_max excess at equal fn_tilde is CONTACT's B_ns = A_ss sin(alpha) coupling of the lateral
// tractions into the normal displacement (its IF_VAR = 3), absent from a normal-only solver.
TEST(BemGroove, BlancoVariants) {
  for (const GrooveRow& row : ReadGrooveRows()) {
    if (row.influence == "half-space") continue;
    const PatchGeometry patch = PatchFor(row);
    const BemResult tilde = Solve(patch, BemInfluence::Blanco, row.fn_tilde_N, BemForceMeasure::CurvedSurface);
    Print("fn_tilde", row, tilde);
    const BemResult base = Solve(patch, BemInfluence::Blanco, 10e3, BemForceMeasure::ReferenceNormal);
    const BemResult paper = Solve(patch, BemInfluence::Blanco, 10e3, BemForceMeasure::ReferenceNormal,
                                  ConformalCoupling::PaperSingleBody);
    Print("paper eq. 5", row, paper);
    ASSERT_EQ(tilde.status, BemStatus::Converged);
    ASSERT_EQ(paper.status, BemStatus::Converged);
    EXPECT_LT(std::fabs(tilde.max_pressure_Pa * 1e-6 / row.p_max_MPa - 1.0), 0.05) << "case " << row.id;
    // For the concave groove (alpha = -s/R_ref) the paper's coupling term -sin(alpha_J - alpha_I) K (s_I - s_J)/r^2
    // is negative: a stiffer kernel, so a smaller approach and a wider patch than the consistent B_nn = A_nn cos.
    EXPECT_LT(paper.approach_m, base.approach_m);
    EXPECT_GE(paper.contact_width_s_m, base.contact_width_s_m);
  }
}

}  // namespace
}  // namespace conforma
