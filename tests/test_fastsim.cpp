// FASTSIM (docs/physics-reference.md §2.3-2.4): Kalker's linear theory in the small-creepage limit,
// saturation at mu N, the traction bound, symmetry, frictional power, the strip core on an analytic rectangular
// strip, and the CONTACT reference cases (contact_basic_cases.csv, contact_hertz_creep_cases.csv).
// test-links: hertz_fastsim  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/fastsim.hpp"
#include "conforma/hertz.hpp"
#include "conforma/kalker.hpp"

using namespace conforma;

namespace {

FastsimHertzInput Patch(double a_over_b, double normal_force_N = 50e3) {
  FastsimHertzInput in;
  in.a_m = 6e-3 * std::sqrt(a_over_b);
  in.b_m = 6e-3 / std::sqrt(a_over_b);
  in.normal_force_N = normal_force_N;
  in.friction_coefficient = 0.3;
  in.nx = in.ny = 30;
  return in;
}

FastsimOptions Options(TractionBound bound, bool blend = false,
                       FastsimMarching marching = FastsimMarching::CentreExact) {
  FastsimOptions o;
  o.bound = bound;
  o.blend_flexibilities = blend;
  o.marching = marching;
  return o;
}

struct CsvRow {
  double aob = 0, A = 0, B = 0, fn = 0, xi = 0, eta = 0, phi_per_mm = 0, mu = 0, G = 0, nu = 0;
  double fx = 0, fy = 0, mz_Nmm = 0;
  std::string method, grid, creep_set;
};

std::vector<CsvRow> ReadCreepCases() {
  const std::string path = std::string(CONFORMA_SHARED_DATA) + "/reference/contact_hertz_creep_cases.csv";
  std::ifstream file(path);
  EXPECT_TRUE(file.good()) << path;
  std::vector<CsvRow> rows;
  std::string line;
  while (std::getline(file, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("aob", 0) == 0) continue;
    std::vector<std::string> c;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) c.push_back(cell);
    if (c.size() < 20) continue;
    CsvRow r;
    r.aob = std::stod(c[0]);
    r.method = c[1];
    r.grid = c[2];
    r.creep_set = c[3];
    r.A = std::stod(c[4]);
    r.B = std::stod(c[5]);
    r.fn = std::stod(c[6]);
    r.xi = std::stod(c[7]);
    r.eta = std::stod(c[8]);
    r.phi_per_mm = std::stod(c[9]);
    r.mu = std::stod(c[10]);
    r.G = std::stod(c[11]);
    r.nu = std::stod(c[12]);
    r.fx = std::stod(c[17]);
    r.fy = std::stod(c[18]);
    r.mz_Nmm = std::stod(c[19]);
    rows.push_back(r);
  }
  return rows;
}

// Our FASTSIM on a CSV row: Hertz from the row's quadratic gap (1/mm -> 1/m), then FASTSIM.
FastsimResult SolveRow(const CsvRow& r, int n, const FastsimOptions& options, HertzResult* hertz) {
  Material m;
  m.shear_modulus_Pa = r.G * 1e6;
  m.poisson_ratio = r.nu;
  const HertzResult h = SolveHertzForLoad(r.A * 1e3, r.B * 1e3, r.fn, m);
  EXPECT_EQ(h.status, HertzStatus::Ok);
  *hertz = h;
  FastsimHertzInput in;
  in.a_m = h.a_m;
  in.b_m = h.b_m;
  in.normal_force_N = r.fn;
  in.creepages = {r.xi, r.eta, r.phi_per_mm * 1e3};
  in.friction_coefficient = r.mu;
  in.material = m;
  in.nx = in.ny = n;
  return SolveFastsimHertz(in, options);
}

}  // namespace

// Small creepage: F_x = -G c^2 C11 xi, F_y = -G c^2 C22 eta, F_y = -G c^3 C23 phi within 1 % for a/b = 0.2 ... 5
// (§2.1, §2.3: the flexibilities are chosen so this holds; measured 0.06 % at 30 x 30).
TEST(Fastsim, ReproducesKalkerLinearTheory) {
  const Material steel;
  const double G = steel.shear_modulus_Pa;
  for (TractionBound bound : {TractionBound::Elliptic, TractionBound::Parabolic}) {
    for (double ab : {0.2, 0.5, 1.0, 2.0, 5.0}) {
      FastsimHertzInput in = Patch(ab);
      const double c = std::sqrt(in.a_m * in.b_m);
      const CreepCoefficients C = KalkerCoefficients(ab, steel.poisson_ratio);
      const double muN = in.friction_coefficient * in.normal_force_N;
      const double xi = 1e-3 * muN / (G * c * c * C.c11);  // 0.1 % of saturation
      in.creepages = {xi, 0.0, 0.0};
      const FastsimResult rx = SolveFastsimHertz(in, Options(bound));
      EXPECT_NEAR(rx.fx_N, -G * c * c * C.c11 * xi, 0.01 * G * c * c * C.c11 * xi) << ab;
      EXPECT_NEAR(rx.fy_N, 0.0, 1e-9 * muN);
      const double eta = 1e-3 * muN / (G * c * c * C.c22);
      in.creepages = {0.0, eta, 0.0};
      const FastsimResult ry = SolveFastsimHertz(in, Options(bound));
      EXPECT_NEAR(ry.fy_N, -G * c * c * C.c22 * eta, 0.01 * G * c * c * C.c22 * eta) << ab;
      const double phi = 1e-3 * muN / (G * c * c * c * C.c23);
      in.creepages = {0.0, 0.0, phi};
      const FastsimResult rs = SolveFastsimHertz(in, Options(bound));
      EXPECT_NEAR(rs.fy_N, -G * c * c * c * C.c23 * phi, 0.01 * G * c * c * c * C.c23 * phi) << ab;
      EXPECT_NEAR(rs.fx_N, 0.0, 1e-9 * muN);
      EXPECT_LT(rs.mz_Nm, 0.0);  // M_z = -G c^4 C33 phi: negative for positive spin
      // The blending of flexibilities vanishes as creepage -> 0.
      in.creepages = {xi, 0.0, 0.0};
      const FastsimResult rb = SolveFastsimHertz(in, Options(bound, true));
      EXPECT_NEAR(rb.fx_N, rx.fx_N, 1e-3 * std::abs(rx.fx_N));
    }
  }
}

// Large creepage: the total force tends to mu N (within 0.5 %), opposite to the creepage direction.
TEST(Fastsim, SaturatesAtMuN) {
  for (TractionBound bound : {TractionBound::Elliptic, TractionBound::Parabolic}) {
    for (double ab : {0.2, 1.0, 5.0}) {
      FastsimHertzInput in = Patch(ab);
      const double muN = in.friction_coefficient * in.normal_force_N;
      for (double angle : {0.0, 0.7, 1.5708, 2.5, 4.0}) {
        in.creepages = {0.05 * std::cos(angle), 0.05 * std::sin(angle), 0.0};
        const FastsimResult r = SolveFastsimHertz(in, Options(bound));
        EXPECT_NEAR(std::hypot(r.fx_N, r.fy_N), muN, 0.005 * muN) << ab << " " << angle;
        EXPECT_LT(r.fx_N * std::cos(angle) + r.fy_N * std::sin(angle), 0.0);
        EXPECT_EQ(r.status, FastsimStatus::FullSlip);
      }
      // Large spin: |F| stays below mu N.
      in.creepages = {0.0, 0.0, 50.0};
      const FastsimResult rs = SolveFastsimHertz(in, Options(bound));
      EXPECT_LE(std::hypot(rs.fx_N, rs.fy_N), muN * (1 + 1e-12));
    }
  }
}

// Traction bound, areas, symmetry, frictional power.
TEST(Fastsim, BoundAreasSymmetryAndPower) {
  FastsimHertzInput in = Patch(1.7);
  in.creepages = {0.0012, -0.0007, 0.9};
  in.rolling_speed_m_per_s = 20.0;
  FastsimPatch patch;
  FastsimResult r;
  SolveFastsimHertz(in, Options(TractionBound::Elliptic), &patch, &r);
  ASSERT_EQ(r.status, FastsimStatus::Ok);
  double area = 0.0, fx = 0.0;
  for (int e = 0; e < patch.elements(); ++e) {
    EXPECT_LE(std::hypot(r.px_Pa[e], r.py_Pa[e]), in.friction_coefficient * patch.bound_pressure_Pa[e] * (1 + 1e-12));
    if (!r.in_slip[e]) {
      EXPECT_EQ(r.sx[e] * r.sx[e] + r.sy[e] * r.sy[e], 0.0);
    }
    area += r.area_m2[e];
    fx += r.px_Pa[e] * r.area_m2[e];
  }
  EXPECT_NEAR(fx, r.fx_N, 1e-9 * std::abs(r.fx_N));
  EXPECT_NEAR(r.adhesion_area_m2 + r.slip_area_m2, area, 1e-12 * area);
  EXPECT_NEAR(area, M_PI * in.a_m * in.b_m, 0.01 * area);  // elliptic mesh, midpoint in y
  EXPECT_GT(r.adhesion_area_m2, 0.0);
  EXPECT_GT(r.slip_area_m2, 0.0);
  EXPECT_GT(r.frictional_power_W, 0.0);
  // Mirror symmetry y -> -y: (xi, eta, phi) -> (xi, -eta, -phi) gives (Fx, -Fy, -Mz).
  FastsimHertzInput mirrored = in;
  mirrored.creepages = {in.creepages.xi, -in.creepages.eta, -in.creepages.phi_per_m};
  const FastsimResult m = SolveFastsimHertz(mirrored, Options(TractionBound::Elliptic));
  EXPECT_NEAR(m.fx_N, r.fx_N, 1e-9 * std::abs(r.fx_N));
  EXPECT_NEAR(m.fy_N, -r.fy_N, 1e-9 * std::abs(r.fy_N));
  EXPECT_NEAR(m.mz_Nm, -r.mz_Nm, 1e-9 * std::abs(r.mz_Nm));
  EXPECT_NEAR(m.frictional_power_W, r.frictional_power_W, 1e-9 * r.frictional_power_W);
  // Without a speed there is no power.
  in.rolling_speed_m_per_s = 0.0;
  EXPECT_EQ(SolveFastsimHertz(in, Options(TractionBound::Elliptic)).frictional_power_W, 0.0);
}

// Full sliding in pure xi: the power sum |p.s| V dA equals |F_x| V xi (the term L p dp/dx integrates to
// L/2 [|p|^2] over each strip, which vanishes with p_n at both edges).
TEST(Fastsim, FrictionalPowerInFullSlip) {
  for (TractionBound bound : {TractionBound::Elliptic, TractionBound::Parabolic}) {
    FastsimHertzInput in = Patch(0.6);
    in.nx = in.ny = 60;
    in.creepages = {0.02, 0.0, 0.0};
    in.rolling_speed_m_per_s = 30.0;
    const FastsimResult r = SolveFastsimHertz(in, Options(bound));
    EXPECT_NEAR(r.frictional_power_W, std::abs(r.fx_N) * 30.0 * 0.02, 0.01 * std::abs(r.fx_N) * 30.0 * 0.02);
  }
}

// The strip core on a rectangle with a uniform bound (not a Hertz patch): one strip of length 2a, pure xi. In
// adhesion p_x = -(xi/L1)(a - x) until it reaches mu p_n at the adhesion length l = mu p_n L1 / xi, then it
// stays at -mu p_n: F = -w mu p_n (2a - l/2) when l < 2a, else -w (xi/L1) 2 a^2. Slip s_x = xi in the slip zone
// (the traction is constant there).
TEST(Fastsim, StripCoreRectangleAnalytic) {
  const double a = 5e-3, width = 1e-3, p_n = 1e9, mu = 0.25, L1 = 1e-11;
  const int n = 400;
  FastsimPatch patch;
  patch.strips.push_back(FastsimStrip{0.002, width, a, -a, 0, n});
  patch.bound_pressure_Pa.assign(n, p_n);
  FastsimFlexibilities L{L1, 2e-11, 3e-11};
  for (double xi : {5e-4, 2e-3, 1e-2}) {
    FastsimResult r;
    SolveFastsimStrips(patch, L, {xi, 0.0, 0.0}, mu, 0.0, FastsimOptions{}, &r);
    const double l = mu * p_n * L1 / xi;
    const double expected = l < 2 * a ? -width * mu * p_n * (2 * a - 0.5 * l) : -width * (xi / L1) * 2 * a * a;
    EXPECT_NEAR(r.fx_N, expected, 2.0 / n * std::abs(expected)) << xi;
    EXPECT_NEAR(r.slip_area_m2, std::max(0.0, 2 * a - l) * width, 2 * (2 * a / n) * width) << xi;
    for (int e = 0; e < n; ++e)
      if (r.in_slip[e] && e > 0 && r.in_slip[e - 1]) {
        EXPECT_NEAR(r.sx[e], xi, 1e-9 * xi);
      }
    // p_y = 0, so M_z = sum -y p_x dA = -y F_x for the offset strip.
    EXPECT_NEAR(r.fy_N, 0.0, 1e-12);
    EXPECT_NEAR(r.mz_Nm, -0.002 * r.fx_N, 1e-12 * std::abs(r.fx_N));
  }
  // Per-element friction field: doubling mu everywhere equals doubling the scalar.
  patch.friction_coefficient.assign(n, 2 * mu);
  FastsimResult field, scalar;
  SolveFastsimStrips(patch, L, {2e-3, 1e-3, 0.0}, 123.0, 0.0, FastsimOptions{}, &field);
  patch.friction_coefficient.clear();
  SolveFastsimStrips(patch, L, {2e-3, 1e-3, 0.0}, 2 * mu, 0.0, FastsimOptions{}, &scalar);
  EXPECT_DOUBLE_EQ(field.fx_N, scalar.fx_N);
  EXPECT_DOUBLE_EQ(field.fy_N, scalar.fy_N);
}

// contact_basic_cases.csv: a = 8 mm, b = 4 mm, 82 kN, eta = -0.000625, phi = 0.000625 rad/mm, mu = 0.3.
// Kalker exact: Fy = -14940 N, Mz = -48210 N mm. CONTACT FASTSIM elliptic -14800 / -48290, parabolic -15050 / -39000.
TEST(Fastsim, BasicCaseAgainstContact) {
  FastsimHertzInput in;
  in.a_m = 8e-3;
  in.b_m = 4e-3;
  in.normal_force_N = 82e3;
  in.creepages = {0.0, -0.000625, 0.625};
  in.friction_coefficient = 0.3;
  for (int n : {30, 60}) {
    in.nx = in.ny = n;
    const FastsimResult r = SolveFastsimHertz(in, Options(TractionBound::Elliptic));
    EXPECT_NEAR(r.fy_N, -14940.0, 0.03 * 14940.0) << n;  // requirement: within 3 % of the exact theory
    EXPECT_NEAR(r.fx_N, 0.0, 1e-6);
    // The spin moment of (converged) FASTSIM is about 8 % below the exact -48210 N mm (not asserted against the
    // exact value; see the report). Asserted: it is grid-converged to 1 % at 30 x 30.
    in.nx = in.ny = 200;
    const FastsimResult fine = SolveFastsimHertz(in, Options(TractionBound::Elliptic));
    EXPECT_NEAR(r.mz_Nm, fine.mz_Nm, 0.01 * std::abs(fine.mz_Nm));
  }
  // CONTACT's own FASTSIM numbers come from the classic first-order marching (with its flexibility blending) on
  // a coarse grid: our classic scheme at 44 x 44 reproduces them within 3 % (grid of the CONTACT run not stated).
  in.nx = in.ny = 44;
  const FastsimResult ce = SolveFastsimHertz(in, Options(TractionBound::Elliptic, true, FastsimMarching::ClassicFullStep));
  EXPECT_NEAR(ce.fy_N, -14800.0, 0.03 * 14800.0);
  EXPECT_NEAR(ce.mz_Nm * 1e3, -48290.0, 0.03 * 48290.0);
  const FastsimResult cp = SolveFastsimHertz(in, Options(TractionBound::Parabolic, true, FastsimMarching::ClassicFullStep));
  EXPECT_NEAR(cp.fy_N, -15050.0, 0.03 * 15050.0);
  EXPECT_NEAR(cp.mz_Nm * 1e3, -39000.0, 0.03 * 39000.0);
}

// contact_hertz_creep_cases.csv, CONTACT's FASTSIM rows (elliptic and parabolic bound, n40 and n80 grids): with
// the same ingredients (classic marching, flexibility blending, n x n grid) our core reproduces them: forces
// within 2 % + 0.5 % mu N, spin moment within 5 % + 0.5 % mu N c (M_z is a small difference in some rows).
TEST(Fastsim, CreepCasesAgainstContactFastsim) {
  int checked = 0;
  for (const CsvRow& r : ReadCreepCases()) {
    if (r.method != "fastsim_ellip" && r.method != "fastsim_parab") continue;
    const int n = r.grid == "n40" ? 40 : 80;
    const TractionBound bound = r.method == "fastsim_ellip" ? TractionBound::Elliptic : TractionBound::Parabolic;
    HertzResult h;
    const FastsimResult f = SolveRow(r, n, Options(bound, true, FastsimMarching::ClassicFullStep), &h);
    const double muN = r.mu * r.fn;
    const double c_mm = 1e3 * std::sqrt(h.a_m * h.b_m);
    const std::string tag = r.method + " " + r.grid + " " + r.creep_set + " a/b " + std::to_string(r.aob);
    EXPECT_NEAR(f.fx_N, r.fx, 0.02 * std::abs(r.fx) + 0.005 * muN) << tag;
    EXPECT_NEAR(f.fy_N, r.fy, 0.02 * std::abs(r.fy) + 0.005 * muN) << tag;
    EXPECT_NEAR(f.mz_Nm * 1e3, r.mz_Nmm, 0.05 * std::abs(r.mz_Nmm) + 0.005 * muN * c_mm) << tag;
    ++checked;
  }
  EXPECT_EQ(checked, 40);
}

// Against Kalker's exact theory (CONTACT full solver, n80 rows). FASTSIM is a simplified theory: §2.5 quotes
// 5-8 % for creep alone and up to 10-20 % with spin. Our default FASTSIM (centre marching, 30 x 30), with and
// without blending, must stay within 8 % of mu N in F_x and F_y for every row (measured max 7.1 %: F_x at
// a/b = 0.2 with spin, unblended);
// M_z is only reported (FASTSIM's spin moment is known to be poor).
TEST(Fastsim, CreepCasesAgainstExactTheory) {
  int checked = 0;
  for (const CsvRow& r : ReadCreepCases()) {
    if (r.method != "exact" || r.grid != "n80") continue;
    const double muN = r.mu * r.fn;
    for (bool blend : {false, true}) {
      HertzResult h;
      const FastsimResult f = SolveRow(r, 30, Options(TractionBound::Elliptic, blend), &h);
      const std::string tag = r.creep_set + " a/b " + std::to_string(r.aob) + (blend ? " blended" : "");
      EXPECT_NEAR(f.fx_N, r.fx, 0.08 * muN) << tag;
      EXPECT_NEAR(f.fy_N, r.fy, 0.08 * muN) << tag;
      std::printf("exact %s %-3s blend=%d  Fx %+6.1f%% (%+5.2f%% muN)  Fy %+6.1f%% (%+5.2f%% muN)  Mz %+6.1f%%\n",
                  r.creep_set.c_str(), std::to_string(r.aob).substr(0, 3).c_str(), blend, 100 * (f.fx_N / r.fx - 1),
                  100 * (f.fx_N - r.fx) / muN, 100 * (f.fy_N / r.fy - 1), 100 * (f.fy_N - r.fy) / muN,
                  100 * (f.mz_Nm * 1e3 / r.mz_Nmm - 1));
    }
    ++checked;
  }
  EXPECT_EQ(checked, 10);
}

// The Hertz entry equals the strip core on the same patch, and the patch/result reuse gives identical numbers.
TEST(Fastsim, HertzEntryEqualsCoreAndReuse) {
  FastsimHertzInput in = Patch(2.5);
  in.nx = 17;
  in.ny = 23;
  in.creepages = {0.001, 0.0005, -0.4};
  const Material steel;
  FastsimPatch patch;
  FastsimResult reused;
  SolveFastsimHertz(in, Options(TractionBound::Parabolic), &patch, &reused);
  EXPECT_EQ(patch.elements(), 17 * 23);
  FastsimResult core;
  const FastsimFlexibilities L = KalkerFlexibilities(in.a_m, in.b_m, KalkerCoefficients(2.5, 0.28), steel.shear_modulus_Pa);
  SolveFastsimStrips(patch, L, in.creepages, in.friction_coefficient, 0.0, FastsimOptions{}, &core);
  const FastsimResult value = SolveFastsimHertz(in, Options(TractionBound::Parabolic));
  EXPECT_DOUBLE_EQ(core.fx_N, reused.fx_N);
  EXPECT_DOUBLE_EQ(value.fy_N, reused.fy_N);
  EXPECT_DOUBLE_EQ(value.mz_Nm, reused.mz_Nm);
  // Discrete load of the bound pressure = N.
  double load = 0.0;
  for (int e = 0; e < patch.elements(); ++e) load += patch.bound_pressure_Pa[e] * reused.area_m2[e];
  EXPECT_NEAR(load, in.normal_force_N, 1e-9 * in.normal_force_N);
  // Second call with the same buffers.
  SolveFastsimHertz(in, Options(TractionBound::Parabolic), &patch, &reused);
  EXPECT_DOUBLE_EQ(value.fx_N, reused.fx_N);
}

TEST(Fastsim, DegenerateAndBadInput) {
  FastsimHertzInput in = Patch(1.0);
  in.normal_force_N = 0.0;
  const FastsimResult none = SolveFastsimHertz(in, FastsimOptions{});
  EXPECT_EQ(none.status, FastsimStatus::NoContact);
  EXPECT_EQ(none.fx_N, 0.0);
  in.creepages.eta = std::numeric_limits<double>::infinity();
  EXPECT_THROW(SolveFastsimHertz(in, FastsimOptions{}), InputError);  // bad input even without load
  in = Patch(1.0);
  in.creepages.xi = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(SolveFastsimHertz(in, FastsimOptions{}), InputError);
  in = Patch(1.0);
  in.friction_coefficient = -0.1;
  EXPECT_THROW(SolveFastsimHertz(in, FastsimOptions{}), InputError);
  in = Patch(1.0);
  in.nx = 0;
  EXPECT_THROW(SolveFastsimHertz(in, FastsimOptions{}), InputError);
  in = Patch(1.0);
  in.normal_force_N = -5.0;
  EXPECT_THROW(SolveFastsimHertz(in, FastsimOptions{}), InputError);
  FastsimPatch bad;
  bad.strips.push_back(FastsimStrip{0.0, 1e-3, -1e-3, 1e-3, 0, 4});  // x_lead < x_trail
  bad.bound_pressure_Pa.assign(4, 1e8);
  FastsimResult r;
  EXPECT_THROW(SolveFastsimStrips(bad, {1e-11, 1e-11, 1e-11}, {}, 0.3, 0.0, FastsimOptions{}, &r), InputError);
  bad.strips[0] = FastsimStrip{0.0, 1e-3, 1e-3, -1e-3, 2, 4};  // elements out of range
  EXPECT_THROW(SolveFastsimStrips(bad, {1e-11, 1e-11, 1e-11}, {}, 0.3, 0.0, FastsimOptions{}, &r), InputError);
  bad.strips[0] = FastsimStrip{0.0, 1e-3, 1e-3, -1e-3, 0, 4};
  bad.bound_pressure_Pa[2] = -1.0;
  EXPECT_THROW(SolveFastsimStrips(bad, {1e-11, 1e-11, 1e-11}, {}, 0.3, 0.0, FastsimOptions{}, &r), InputError);
  bad.bound_pressure_Pa[2] = 1e8;
  EXPECT_THROW(SolveFastsimStrips(bad, {0.0, 1e-11, 1e-11}, {}, 0.3, 0.0, FastsimOptions{}, &r), InputError);
  FastsimPatch empty;
  SolveFastsimStrips(empty, {1e-11, 1e-11, 1e-11}, {}, 0.3, 0.0, FastsimOptions{}, &r);
  EXPECT_EQ(r.status, FastsimStatus::NoContact);
  EXPECT_STREQ(to_string(FastsimStatus::FullSlip), "full_slip");
}
