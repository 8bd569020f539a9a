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

// CONTACT's exact theory at the same grid: Fx, Fy within 1 %, Mz within 5 % (or 200 N mm where small), pmax = Hertz
// within 0.1 %.
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
    EXPECT_NEAR(t.fx_N, r.fx_N, 0.01 * std::fabs(r.fx_N));
    EXPECT_NEAR(t.fy_N, r.fy_N, 0.01 * std::fabs(r.fy_N));
    EXPECT_NEAR(t.mz_Nm, r.mz_Nm, std::max(0.05 * std::fabs(r.mz_Nm), 0.2));
    EXPECT_NEAR(s.normal.max_pressure_Pa, r.pmax_hertz_Pa, 1e-3 * r.pmax_hertz_Pa);
  }
}

}  // namespace
}  // namespace conforma
