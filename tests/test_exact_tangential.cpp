// Kalker's exact steady-rolling tangential solver (exact_tangential.hpp) against CONTACT's exact theory on Hertzian
// patches (shared data reference/contact_hertz_creep_cases.csv: a/b 0.2 ... 5, Fn = 50 kN, two creepage sets, grids
// of n x n elements over the Hertz rectangle [-a, a] x [-b, b]), and against the limits: Kalker's linear theory,
// full slip, Carter's two-dimensional solution.
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
#include "conforma/exact_tangential.hpp"
#include "conforma/kalker.hpp"

namespace conforma {
namespace {

struct CreepRow {
  double aob = 0.0;
  int n = 0;
  std::string creep_set;
  double A_per_m = 0.0, B_per_m = 0.0, fn_N = 0.0, xi = 0.0, eta = 0.0, phi_per_m = 0.0, mu = 0.0, G_Pa = 0.0,
         nu = 0.0, a_m = 0.0, b_m = 0.0, pmax_hertz_Pa = 0.0, fx_N = 0.0, fy_N = 0.0, mz_Nm = 0.0;
  int nadh = 0, nslip = 0;
};

std::vector<CreepRow> ReadExactRows() {
  std::ifstream in(std::string(CONFORMA_SHARED_DATA) + "/reference/contact_hertz_creep_cases.csv");
  EXPECT_TRUE(in.good());
  std::vector<CreepRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("aob", 0) == 0) continue;
    std::vector<std::string> c;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) c.push_back(cell);
    if (c.size() < 25 || c[1] != "exact") continue;
    CreepRow r;
    r.aob = std::stod(c[0]);
    r.n = std::stoi(c[2].substr(1));
    r.creep_set = c[3];
    r.A_per_m = std::stod(c[4]) * 1e3;
    r.B_per_m = std::stod(c[5]) * 1e3;
    r.fn_N = std::stod(c[6]);
    r.xi = std::stod(c[7]);
    r.eta = std::stod(c[8]);
    r.phi_per_m = std::stod(c[9]) * 1e3;
    r.mu = std::stod(c[10]);
    r.G_Pa = std::stod(c[11]) * 1e6;
    r.nu = std::stod(c[12]);
    r.a_m = std::stod(c[13]) * 1e-3;
    r.b_m = std::stod(c[14]) * 1e-3;
    r.pmax_hertz_Pa = std::stod(c[15]) * 1e6;
    r.fx_N = std::stod(c[17]);
    r.fy_N = std::stod(c[18]);
    r.mz_Nm = std::stod(c[19]) * 1e-3;
    r.nadh = std::stoi(c[23]);
    r.nslip = std::stoi(c[24]);
    rows.push_back(r);
  }
  return rows;
}

struct Solved {
  BemResult normal;
  ExactTangentialResult tangential;
};

// The Hertz problem of a row on n x n elements over [-a, a] x [-b, b] (CONTACT's grid for these cases).
Solved SolveRow(const CreepRow& r, int n, const FastsimCreepages& creepages, double mu) {
  Material m;
  m.shear_modulus_Pa = r.G_Pa;
  m.poisson_ratio = r.nu;
  const BemGrid grid = QuadraticGapGrid(r.A_per_m, r.B_per_m, n, n, r.a_m, r.b_m);
  BemOptions bo;
  bo.normal_force_N = r.fn_N;
  Solved s;
  s.normal = SolveBemNormal(grid, m, bo);
  ExactTangentialOptions to;
  to.friction_coefficient = mu;
  s.tangential = SolveExactTangential(grid, s.normal.pressure_Pa, RigidSlipFromCreepages(grid, creepages), m, to);
  return s;
}

FastsimCreepages CreepagesOf(const CreepRow& r) { return FastsimCreepages{r.xi, r.eta, r.phi_per_m}; }

// CONTACT's exact theory at the same grid. Issue 14 asks Fx, Fy within 1 %, Mz within 5 % (or 200 N mm where small),
// pmax = Hertz within 0.1 %; with CONTACT's discretisation (§14.1) the forces agree to CONTACT's 4 printed digits, so
// the test holds them to 0.2 % (Fx, Fy) and 0.5 % (Mz).
TEST(ExactTangential, HertzCreepCasesAgainstContact) {
  const std::vector<CreepRow> rows = ReadExactRows();
  ASSERT_EQ(rows.size(), 20u);
  for (const CreepRow& r : rows) {
    const Solved s = SolveRow(r, r.n, CreepagesOf(r), r.mu);
    const ExactTangentialResult& t = s.tangential;
    std::printf("a/b %.1f n%d %s: Fx %.0f (%.0f) Fy %.0f (%.0f) Mz %.0f (%.0f) N mm  pmax %.2f (%.2f) MPa  sweeps %d "
                "adh %d slip %d\n",
                r.aob, r.n, r.creep_set.c_str(), t.fx_N, r.fx_N, t.fy_N, r.fy_N, t.mz_Nm * 1e3, r.mz_Nm * 1e3,
                s.normal.max_pressure_Pa * 1e-6, r.pmax_hertz_Pa * 1e-6, t.sweeps,
                static_cast<int>((t.state.array() == 1).count()), static_cast<int>((t.state.array() == 2).count()));
    ASSERT_EQ(t.status, ExactTangentialStatus::Converged);
    EXPECT_NEAR(t.fx_N, r.fx_N, 0.002 * std::fabs(r.fx_N));
    EXPECT_NEAR(t.fy_N, r.fy_N, 0.002 * std::fabs(r.fy_N));
    EXPECT_NEAR(t.mz_Nm, r.mz_Nm, std::max(0.005 * std::fabs(r.mz_Nm), 0.2));
    EXPECT_NEAR(s.normal.max_pressure_Pa, r.pmax_hertz_Pa, 1e-3 * r.pmax_hertz_Pa);
  }
}

}  // namespace
}  // namespace conforma

namespace conforma {
namespace {

const double kPi = 3.14159265358979323846;

// The Hertz case of the a/b = 1 row (A = B = 1.087 /m, Fn = 50 kN) on n x n elements over [-a, a]^2.
CreepRow UnitRatioRow() {
  for (const CreepRow& r : ReadExactRows())
    if (r.aob == 1.0) return r;
  ADD_FAILURE() << "no a/b = 1 row";
  return CreepRow{};
}

// The BEM normal solution of the a/b = 1 row on n x n elements over [-a, a]^2.
struct UnitRowProblem {
  CreepRow row;
  Material material;
  BemGrid grid;
  BemResult normal;
  // the exact tangential problem at the row's creepages
  ExactTangentialResult Solve(const ExactTangentialOptions& options = {}) const {
    return SolveExactTangential(grid, normal.pressure_Pa, RigidSlipFromCreepages(grid, CreepagesOf(row)), material,
                                options);
  }
};
UnitRowProblem SolveUnitRow(int n) {
  UnitRowProblem u;
  u.row = UnitRatioRow();
  u.grid = QuadraticGapGrid(u.row.A_per_m, u.row.B_per_m, n, n, u.row.a_m, u.row.b_m);
  BemOptions bo;
  bo.normal_force_N = u.row.fn_N;
  u.normal = SolveBemNormal(u.grid, u.material, bo);
  return u;
}

// Kalker's linear theory (kalker.hpp: C_ij of the project's table) as creepage -> 0: Fx = -G c^2 C11 xi,
// Fy = -G c^2 C22 eta - G c^3 C23 phi, c = sqrt(ab). The discretisation error is first order in the element size
// (0.6 % to 1.8 % at 80 x 80 elements, larger at a/b = 5 where b is small), so the forces are Richardson-extrapolated
// from 40 and 80 elements per semi-axis pair: F = 2 F_80 - F_40.
TEST(ExactTangential, LinearTheoryLimit) {
  Material m;
  for (const CreepRow& r : ReadExactRows()) {
    if (r.n != 40 || r.creep_set != "c1" || (r.aob != 0.2 && r.aob != 1.0 && r.aob != 5.0)) continue;
    m.shear_modulus_Pa = r.G_Pa;
    m.poisson_ratio = r.nu;
    const CreepCoefficients c = KalkerCoefficients(r.a_m / r.b_m, r.nu);
    const double c2 = r.a_m * r.b_m, cc = std::sqrt(c2), creep = 1e-6;
    const FastsimCreepages sets[3] = {{creep, 0.0, 0.0}, {0.0, creep, 0.0}, {0.0, 0.0, creep / cc}};
    const double linear[3] = {-r.G_Pa * c2 * c.c11 * creep, -r.G_Pa * c2 * c.c22 * creep,
                              -r.G_Pa * cc * c2 * c.c23 * creep / cc};
    double force[2][3];
    for (int level = 0; level < 2; ++level) {
      const int n = level == 0 ? 40 : 80;
      const BemGrid grid = QuadraticGapGrid(r.A_per_m, r.B_per_m, n, n, r.a_m, r.b_m);
      BemOptions bo;
      bo.normal_force_N = r.fn_N;
      const BemResult normal = SolveBemNormal(grid, m, bo);
      ExactTangentialOptions tight;  // converged far below the discretisation error, for the symmetry check
      tight.tolerance = 1e-8;
      for (int k = 0; k < 3; ++k) {
        const ExactTangentialResult t =
            SolveExactTangential(grid, normal.pressure_Pa, RigidSlipFromCreepages(grid, sets[k]), m, tight);
        ASSERT_EQ(t.status, ExactTangentialStatus::Converged);
        force[level][k] = k == 0 ? t.fx_N : t.fy_N;
        // the cross terms vanish by symmetry (Fy from xi; Fx from eta and phi)
        EXPECT_LT(std::fabs(k == 0 ? t.fy_N : t.fx_N), 1e-5 * std::fabs(linear[k]));
      }
    }
    for (int k = 0; k < 3; ++k) {
      const double extrapolated = 2.0 * force[1][k] - force[0][k];
      std::printf("a/b %.1f %s: n40 %.5g n80 %.5g extrapolated %.5g linear %.5g (%+.2f %%)\n", r.aob,
                  k == 0 ? "xi -> Fx" : k == 1 ? "eta -> Fy" : "phi -> Fy", force[0][k], force[1][k], extrapolated,
                  linear[k], 100.0 * (extrapolated / linear[k] - 1.0));
      EXPECT_NEAR(extrapolated, linear[k], 0.01 * std::fabs(linear[k]));
    }
  }
}

// Full slip: every element slips, |F| = mu Fn.
TEST(ExactTangential, FullSlipCarriesMuTimesLoad) {
  const CreepRow r = UnitRatioRow();
  const Solved s = SolveRow(r, 40, FastsimCreepages{0.05, -0.02, 0.0}, r.mu);
  ASSERT_EQ(s.tangential.status, ExactTangentialStatus::Converged);
  EXPECT_EQ((s.tangential.state.array() == 1).count(), 0);
  const double force = std::hypot(s.tangential.fx_N, s.tangential.fy_N);
  std::printf("full slip: |F| %.2f N, mu Fn %.2f N\n", force, r.mu * s.normal.normal_force_reference_N);
  EXPECT_NEAR(force, r.mu * s.normal.normal_force_reference_N, 1e-3 * r.mu * r.fn_N);
  // the traction opposes the slip everywhere
  for (int j = 0; j < s.tangential.state.cols(); ++j)
    for (int i = 0; i < s.tangential.state.rows(); ++i)
      if (s.tangential.state(i, j) == 2) {
        EXPECT_LT(s.tangential.px_Pa(i, j) * s.tangential.sx(i, j) + s.tangential.ps_Pa(i, j) * s.tangential.ss(i, j),
                  0.0);
      }
}

// Carter (1926; Johnson 1985 §8.2): a long cylinder, F'/(mu P') = 1 - (1 - xi/xi_s)^2 with xi_s = mu a / R, on the
// middle line of a patch 60 half-widths long (2-D in its middle).
TEST(ExactTangential, CarterTwoDimensionalSolution) {
  Material m;
  const double R = 0.46, A = 1.0 / (2.0 * R), load_per_m = 1.0e6;
  const double a = std::sqrt(4.0 * load_per_m * R / (kPi * m.combined_modulus_Pa()));  // 2-D Hertz half-width
  const int nx = 80, ns = 61;
  const double length = 61.0 * a;
  BemGrid grid = QuadraticGapGrid(A, 0.0, nx, ns, 1.15 * a, 0.5 * length);
  BemOptions bo;
  bo.normal_force_N = load_per_m * length;
  const BemResult normal = SolveBemNormal(grid, m, bo);
  ASSERT_EQ(normal.status, BemStatus::Converged);
  const int middle = ns / 2;
  const double p_line = normal.pressure_Pa.col(middle).sum() * grid.dx_m;  // P' of the middle line
  const double a_line = std::sqrt(4.0 * p_line * R / (kPi * m.combined_modulus_Pa()));
  const double mu = 0.3, xi_s = mu * a_line / R;
  for (double ratio : {0.25, 0.5, 0.75}) {
    ExactTangentialOptions to;
    to.friction_coefficient = mu;
    const ExactTangentialResult t =
        SolveExactTangential(grid, normal.pressure_Pa, RigidSlipFromCreepages(grid, {ratio * xi_s, 0.0, 0.0}), m, to);
    ASSERT_EQ(t.status, ExactTangentialStatus::Converged);
    const double f_line = t.px_Pa.col(middle).sum() * grid.dx_m;
    const double carter = 1.0 - (1.0 - ratio) * (1.0 - ratio);
    std::printf("Carter xi/xi_s %.2f: F'/(mu P') %.4f, Carter %.4f\n", ratio, -f_line / (mu * p_line), carter);
    EXPECT_NEAR(-f_line / (mu * p_line), carter, 0.02 * carter);
  }
}

// The FFT product and the direct summation give the same solution; the solve is deterministic.
TEST(ExactTangential, FftMatchesDirectSummationAndRepeats) {
  const UnitRowProblem u = SolveUnitRow(16);
  ExactTangentialOptions fft, direct;
  direct.use_fft = false;
  const ExactTangentialResult a = u.Solve(fft);
  const ExactTangentialResult b = u.Solve(direct);
  const ExactTangentialResult c = u.Solve(fft);
  EXPECT_NEAR(a.fx_N, b.fx_N, 1e-8 * std::fabs(a.fx_N));
  EXPECT_NEAR(a.fy_N, b.fy_N, 1e-8 * std::fabs(a.fy_N));
  EXPECT_EQ(a.fx_N, c.fx_N);
  EXPECT_EQ(a.mz_Nm, c.mz_Nm);
  EXPECT_TRUE(a.px_Pa == c.px_Pa);
}

// Bad input is an InputError naming what is wrong.
TEST(ExactTangential, RejectsBadInput) {
  const BemGrid grid = QuadraticGapGrid(1.0, 1.0, 8, 8, 1e-3, 1e-3);
  Material m;
  Eigen::MatrixXd p = Eigen::MatrixXd::Constant(8, 8, 1e8);
  const RigidSlipField w = RigidSlipFromCreepages(grid, {1e-3, 0.0, 0.0});
  ExactTangentialOptions o;
  EXPECT_THROW(SolveExactTangential(grid, Eigen::MatrixXd::Constant(7, 8, 1e8), w, m, o), InputError);
  Eigen::MatrixXd bad = p;
  bad(3, 4) = std::nan("");
  EXPECT_THROW(SolveExactTangential(grid, bad, w, m, o), InputError);
  bad(3, 4) = -1.0;
  EXPECT_THROW(SolveExactTangential(grid, bad, w, m, o), InputError);
  o.friction_coefficient = -0.1;
  EXPECT_THROW(SolveExactTangential(grid, p, w, m, o), InputError);
  o = ExactTangentialOptions{};
  o.friction = [](double) { return std::nan(""); };
  EXPECT_THROW(SolveExactTangential(grid, p, w, m, o), InputError);
  EXPECT_THROW(RigidSlipFromColumnCreepages(grid, std::vector<FastsimCreepages>(3), 0.0, 0.0), InputError);
  // zero pressure: no contact, all zero
  const ExactTangentialResult none = SolveExactTangential(grid, Eigen::MatrixXd::Zero(8, 8), w, m, ExactTangentialOptions{});
  EXPECT_EQ(none.status, ExactTangentialStatus::NoContact);
  EXPECT_EQ(none.fx_N, 0.0);
}

}  // namespace
}  // namespace conforma

#include "conforma/hertz.hpp"

namespace conforma {
namespace {

// CONTACT's FASTSIM example solved with its exact theory (reference/contact_basic_cases.csv, row "exact", 44 x 44
// grid): Hertzian patch a = 8 mm, b = 4 mm, Fn = 82 kN, xi = 0, eta = -0.000625, phi = 0.000625 rad/mm, mu = 0.3,
// G = 82 GPa, nu = 0.28: Fy = -14940 N within 1 %, Mz = -48210 N mm within 3 %.
TEST(ExactTangential, BasicCaseAgainstContact) {
  Material m;
  const double a = 8e-3, b = 4e-3, fn = 82e3;
  // the gap curvatures of that ellipse: B/A by bisection on a/b, then A from a ~ A^(-1/3) at fixed B/A
  double lo = 1.0, hi = 20.0;
  for (int it = 0; it < 200; ++it) {
    const double mid = 0.5 * (lo + hi);
    const HertzResult h = SolveHertzForLoad(1.0, mid, fn, m);
    (h.a_m / h.b_m < a / b ? lo : hi) = mid;
  }
  const double ratio = 0.5 * (lo + hi);
  const HertzResult unit = SolveHertzForLoad(1.0, ratio, fn, m);
  const double A = std::pow(unit.a_m / a, 3.0);
  const HertzResult h = SolveHertzForLoad(A, ratio * A, fn, m);
  ASSERT_NEAR(h.a_m, a, 1e-9);
  ASSERT_NEAR(h.b_m, b, 1e-9);
  const BemGrid grid = QuadraticGapGrid(A, ratio * A, 44, 44, a, b);
  BemOptions bo;
  bo.normal_force_N = fn;
  const BemResult normal = SolveBemNormal(grid, m, bo);
  ExactTangentialOptions to;
  to.tolerance = 1e-8;
  const ExactTangentialResult t = SolveExactTangential(
      grid, normal.pressure_Pa, RigidSlipFromCreepages(grid, {0.0, -0.000625, 0.000625e3}), m, to);
  ASSERT_EQ(t.status, ExactTangentialStatus::Converged);
  std::printf("basic case: Fy %.0f N (CONTACT -14940), Mz %.0f N mm (-48210), pmax %.1f MPa (1223)\n", t.fy_N,
              t.mz_Nm * 1e3, normal.max_pressure_Pa * 1e-6);
  EXPECT_NEAR(t.fy_N, -14940.0, 0.01 * 14940.0);
  EXPECT_NEAR(t.mz_Nm, -48.210, 0.03 * 48.210);
  EXPECT_LT(std::fabs(t.fx_N), 1e-3 * 14940.0);  // no longitudinal creepage: Fx = 0 by symmetry
}

}  // namespace
}  // namespace conforma

#include <thread>

namespace conforma {
namespace {

// Slip-dependent friction (§14.3): at convergence every slip element carries |p| = mu(|s|) p_n with its own slip, every
// adhesion element |p| <= mu(0) p_n; a falling law lowers the force below the constant-mu one at the same creepage.
TEST(ExactTangential, SlipDependentFrictionBound) {
  const UnitRowProblem u = SolveUnitRow(30);
  const Material& m = u.material;
  const BemGrid& grid = u.grid;
  const BemResult& normal = u.normal;
  const RigidSlipField w = RigidSlipFromCreepages(grid, {0.002, 0.0, 0.0});
  ExactTangentialOptions constant;
  constant.tolerance = 1e-9;
  ExactTangentialOptions falling = constant;
  auto mu = [](double gamma) { return 0.3 * (0.4 + 0.6 * std::exp(-300.0 * gamma)); };  // paper 002 eq. 6 form
  falling.friction = mu;
  const ExactTangentialResult c = SolveExactTangential(grid, normal.pressure_Pa, w, m, constant);
  const ExactTangentialResult f = SolveExactTangential(grid, normal.pressure_Pa, w, m, falling);
  ASSERT_EQ(f.status, ExactTangentialStatus::Converged);
  int slipping = 0;
  for (int j = 0; j < grid.ns; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double p = std::hypot(f.px_Pa(i, j), f.ps_Pa(i, j)), pn = normal.pressure_Pa(i, j);
      if (f.state(i, j) == 2) {
        ++slipping;
        EXPECT_NEAR(p, mu(std::hypot(f.sx(i, j), f.ss(i, j))) * pn, 1e-6 * 0.3 * pn);
      } else if (f.state(i, j) == 1) {
        EXPECT_LE(p, mu(0.0) * pn * (1.0 + 1e-12));
      }
    }
  EXPECT_GT(slipping, 0);
  std::printf("falling friction: Fx %.1f N (constant mu %.1f N)\n", f.fx_N, c.fx_N);
  EXPECT_LT(std::fabs(f.fx_N), std::fabs(c.fx_N));
}

// Thread safety: concurrent solves give the single-thread answer bit for bit.
TEST(ExactTangential, ConcurrentSolvesAreIdentical) {
  const UnitRowProblem u = SolveUnitRow(24);
  const ExactTangentialResult alone = u.Solve();
  std::vector<ExactTangentialResult> results(4);
  std::vector<std::thread> threads;
  for (auto& result : results) threads.emplace_back([&] { result = u.Solve(); });
  for (auto& t : threads) t.join();
  for (const auto& result : results) {
    EXPECT_EQ(result.fx_N, alone.fx_N);
    EXPECT_EQ(result.fy_N, alone.fy_N);
    EXPECT_TRUE(result.px_Pa == alone.px_Pa);
  }
}

}  // namespace
}  // namespace conforma
