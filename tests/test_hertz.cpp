// Hertz elliptical contact (docs/physics-reference.md §1.2) checked against independent facts: the sphere formula,
// the Boussinesq surface displacement of the Hertz pressure (h + u = delta inside the ellipse), the identity
// A a^2 + B b^2 = delta, the integrated load, the §1.3 table, the load-approach law and the degenerate cases.
// test-links: hertz_fastsim  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/hertz.hpp"

using conforma::HertzResult;
using conforma::HertzStatus;
using conforma::Material;

namespace {

// Gauss-Legendre nodes/weights on [0, 1] (Golub-Welsch by Newton on P_n).
void GaussLegendre01(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0.0);
  w.assign(n, 0.0);
  for (int i = 0; i < n; ++i) {
    double z = std::cos(M_PI * (i + 0.75) / (n + 0.5));
    double dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = 0.0;
      for (int k = 1; k <= n; ++k) {
        const double p2 = p1;
        p1 = p0;
        p0 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p2) / k;
      }
      dp = n * (z * p0 - p1) / (z * z - 1.0);
      const double dz = p0 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    x[i] = 0.5 * (1.0 - z);
    w[i] = 1.0 / ((1.0 - z * z) * dp * dp);  // = 2/((1-z^2) P'^2) / 2
  }
}

// Combined normal surface displacement of both bodies at (x0, y0) under the Hertz pressure, from the
// Boussinesq kernel 1 / (pi E* r) (§0, §4.3), integrated in polar coordinates centred on the point (the 1/r
// singularity cancels against r dr). Along each ray rho = R (1 - t^2) removes the square-root end point.
double BoussinesqDisplacement(const HertzResult& h, double e_star, double x0, double y0) {
  std::vector<double> t, wt;
  GaussLegendre01(24, t, wt);
  const int n_theta = 256;
  double integral = 0.0;
  for (int i = 0; i < n_theta; ++i) {
    const double th = 2.0 * M_PI * i / n_theta;
    const double c = std::cos(th), s = std::sin(th);
    // Distance R to the ellipse boundary along the ray: (x0 + R c)^2/a^2 + (y0 + R s)^2/b^2 = 1.
    const double qa = c * c / (h.a_m * h.a_m) + s * s / (h.b_m * h.b_m);
    const double qb = 2.0 * (x0 * c / (h.a_m * h.a_m) + y0 * s / (h.b_m * h.b_m));
    const double qc = x0 * x0 / (h.a_m * h.a_m) + y0 * y0 / (h.b_m * h.b_m) - 1.0;
    const double R = (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
    double ray = 0.0;
    for (size_t k = 0; k < t.size(); ++k) {
      const double rho = R * (1.0 - t[k] * t[k]);
      ray += wt[k] * 2.0 * R * t[k] * conforma::HertzPressure(h, x0 + rho * c, y0 + rho * s);
    }
    integral += ray * 2.0 * M_PI / n_theta;
  }
  return integral / (M_PI * e_star);
}

}  // namespace

TEST(Hertz, SphereOnPlaneReference) {
  // contact_basic_cases.csv: sphere R = 100 mm on a plane, approach 0.16 mm -> Fn = 97185 N, p0 = 2900 MPa.
  Material steel;  // G = 82 GPa, nu = 0.28
  const double R = 0.1;
  const HertzResult h = conforma::SolveHertzForApproach(1.0 / (2 * R), 1.0 / (2 * R), 0.16e-3, steel);
  ASSERT_EQ(h.status, HertzStatus::Ok);
  EXPECT_NEAR(h.normal_force_N, 97185.0, 97185.0 * 1e-3);
  EXPECT_NEAR(h.p0_Pa, 2900e6, 2900e6 * 1e-3);
  EXPECT_NEAR(h.a_m, h.b_m, 1e-12);
  // Sphere closed forms: a = sqrt(R delta), C_H = 4/3 E* sqrt(R).
  EXPECT_NEAR(h.a_m, std::sqrt(R * 0.16e-3), 1e-9 * h.a_m);
  EXPECT_NEAR(h.stiffness_N_per_m15, 4.0 / 3.0 * steel.combined_modulus_Pa() * std::sqrt(R), 1e-9 * h.stiffness_N_per_m15);
}

TEST(Hertz, EllipticIntegralsAgainstStdLibrary) {
  // libstdc++'s comp_ellint_* agree with mpmath to ~4e-13 (the AGM here to ~1e-15), hence 2e-12.
  // Loop over the modulus k (the std functions' argument) and form g = sqrt((1 - k)(1 + k)) accurately.
  for (double k : {0.9999, 0.99, 0.9, 0.7, 0.5, 0.1, 1e-3}) {
    const double g = std::sqrt((1.0 - k) * (1.0 + k));
    const auto ei = conforma::EllipticIntegralsFromComplementaryModulus(g);
    EXPECT_NEAR(ei.K, std::comp_ellint_1(k), 2e-12 * ei.K) << g;
    EXPECT_NEAR(ei.E, std::comp_ellint_2(k), 2e-12) << g;
    EXPECT_NEAR(ei.K_minus_E, std::comp_ellint_1(k) - std::comp_ellint_2(k), 2e-12 * ei.K) << g;
  }
  const auto circle = conforma::EllipticIntegralsFromComplementaryModulus(1.0);
  EXPECT_DOUBLE_EQ(circle.K, M_PI / 2);
  EXPECT_DOUBLE_EQ(circle.E, M_PI / 2);
}

// The independent check: for curvature ratios 1 ... 100 (both orientations) the Hertz pressure, integrated with
// the Boussinesq kernel, must give a surface displacement u with h + u = delta at points inside the ellipse.
// A wrong a/b, p0 or delta by 0.1 % breaks this at the 1e-3 level, so the tolerance is 2e-4 delta.
TEST(Hertz, BoussinesqDisplacementClosesTheGapInsideTheEllipse) {
  Material steel;
  const double e_star = steel.combined_modulus_Pa();
  const double N = 100e3;
  for (double ratio : {1.0, 1.5, 3.0, 10.0, 30.0, 100.0}) {
    for (bool b_larger : {true, false}) {
      const double A = b_larger ? 1.0 : ratio;
      const double B = b_larger ? ratio : 1.0;
      const HertzResult h = conforma::SolveHertzForLoad(A, B, N, steel);
      ASSERT_EQ(h.status, HertzStatus::Ok);
      EXPECT_NEAR(A * h.a_m * h.a_m + B * h.b_m * h.b_m, h.approach_m, 1e-12 * h.approach_m);  // §1.2 identity
      EXPECT_EQ(h.a_m >= h.b_m, A <= B);  // the longer axis along the smaller curvature
      const double pts[][2] = {{0, 0}, {0.5, 0}, {0, 0.5}, {0.3, -0.6}, {-0.7, 0.4}, {0.85, 0.1}};
      for (const auto& p : pts) {
        const double x = p[0] * h.a_m, y = p[1] * h.b_m;
        const double u = BoussinesqDisplacement(h, e_star, x, y);
        EXPECT_NEAR(A * x * x + B * y * y + u, h.approach_m, 2e-4 * h.approach_m)
            << "ratio " << ratio << " point " << p[0] << "," << p[1];
      }
      // N = integral of p over the ellipse (midpoint rule on a fine polar grid in normalised coordinates).
      double load = 0.0;
      const int nr = 400, nt = 64;
      for (int i = 0; i < nr; ++i) {
        const double rr = (i + 0.5) / nr;
        for (int j = 0; j < nt; ++j) {
          const double th = 2 * M_PI * (j + 0.5) / nt;
          load += conforma::HertzPressure(h, rr * std::cos(th) * h.a_m, rr * std::sin(th) * h.b_m) * rr;
        }
      }
      load *= h.a_m * h.b_m * (1.0 / nr) * (2 * M_PI / nt);
      EXPECT_NEAR(load, N, 2e-4 * N);
    }
  }
}

// §1.3 table (E = 210 GPa, nu = 0.3, N = 100 kN, R_w = 0.46 m), compared within the rounding of the table.
TEST(Hertz, TypicalWheelRailTable) {
  Material m;
  m.poisson_ratio = 0.3;
  m.shear_modulus_Pa = 210e9 / (2 * 1.3);
  struct Row { double A, B, a_mm, b_mm, p0_MPa, delta_um; };
  const double A = 1.0 / (2 * 0.46);
  const Row rows[] = {{A, 1.0 / 0.6, 7.16, 5.39, 1238, 104.1},
                      {A, 1.0 / 0.16, 8.54, 2.70, 2070, 124.9},
                      {A, 0.5 * (-2.0 + 1.0 / 0.3), 6.14, 8.51, 913, 89.3},
                      {A, 0.5 * (-1.0 / 0.35 + 1.0 / 0.3), 5.06, 13.8, 684, 73.2}};
  for (const Row& r : rows) {
    const HertzResult h = conforma::SolveHertzForLoad(r.A, r.B, 100e3, m);
    ASSERT_EQ(h.status, HertzStatus::Ok);
    EXPECT_NEAR(h.a_m * 1e3, r.a_mm, 0.006 + 1e-3 * r.a_mm);
    EXPECT_NEAR(h.b_m * 1e3, r.b_mm, (r.b_mm > 10 ? 0.06 : 0.006) + 1e-3 * r.b_mm);
    EXPECT_NEAR(h.p0_Pa * 1e-6, r.p0_MPa, 0.6 + 1e-3 * r.p0_MPa);
    EXPECT_NEAR(h.approach_m * 1e6, r.delta_um, 0.06 + 1e-3 * r.delta_um);
  }
}

TEST(Hertz, LoadAndApproachAreInverse) {
  Material steel;
  for (double ratio : {1.0, 2.0, 7.0, 50.0}) {
    const HertzResult by_load = conforma::SolveHertzForLoad(1.087, 1.087 * ratio, 80e3, steel);
    const HertzResult by_approach = conforma::SolveHertzForApproach(1.087, 1.087 * ratio, by_load.approach_m, steel);
    EXPECT_NEAR(by_approach.normal_force_N, 80e3, 80e3 * 1e-12);
    EXPECT_NEAR(by_approach.a_m, by_load.a_m, 1e-12 * by_load.a_m);
    EXPECT_NEAR(by_load.normal_force_N, by_load.stiffness_N_per_m15 * std::pow(by_load.approach_m, 1.5), 1e-9 * 80e3);
    // Scaling: a ~ N^(1/3), delta ~ N^(2/3).
    const HertzResult eight = conforma::SolveHertzForLoad(1.087, 1.087 * ratio, 8 * 80e3, steel);
    EXPECT_NEAR(eight.a_m, 2 * by_load.a_m, 1e-12);
    EXPECT_NEAR(eight.approach_m, 4 * by_load.approach_m, 1e-12);
  }
}

TEST(Hertz, NearlyCircularIsContinuous) {
  Material steel;
  const HertzResult circle = conforma::SolveHertzForLoad(1.0, 1.0, 50e3, steel);
  const HertzResult near = conforma::SolveHertzForLoad(1.0, 1.0 + 1e-9, 50e3, steel);
  EXPECT_NEAR(near.a_m, circle.a_m, 1e-8 * circle.a_m);
  EXPECT_NEAR(near.p0_Pa, circle.p0_Pa, 1e-8 * circle.p0_Pa);
  EXPECT_GT(near.a_m, near.b_m);
}

TEST(Hertz, DegenerateAndBadInput) {
  Material steel;
  EXPECT_EQ(conforma::SolveHertzForLoad(1.0, 0.0, 1e4, steel).status, HertzStatus::NoSolution);
  EXPECT_EQ(conforma::SolveHertzForLoad(1.0, -0.5, 1e4, steel).status, HertzStatus::NoSolution);
  EXPECT_EQ(conforma::SolveHertzForApproach(-1.0, 2.0, 1e-4, steel).status, HertzStatus::NoSolution);
  const HertzResult none = conforma::SolveHertzForLoad(1.0, 2.0, 0.0, steel);
  EXPECT_EQ(none.status, HertzStatus::NoContact);
  EXPECT_EQ(none.a_m, 0.0);
  EXPECT_EQ(conforma::SolveHertzForApproach(1.0, 2.0, 0.0, steel).status, HertzStatus::NoContact);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(conforma::SolveHertzForLoad(1.0, 2.0, -1.0, steel), conforma::InputError);
  EXPECT_THROW(conforma::SolveHertzForLoad(1.0, 2.0, nan, steel), conforma::InputError);
  EXPECT_THROW(conforma::SolveHertzForLoad(nan, 2.0, 1e4, steel), conforma::InputError);
  EXPECT_THROW(conforma::SolveHertzForApproach(1.0, 2.0, -1e-5, steel), conforma::InputError);
  Material bad;
  bad.poisson_ratio = 0.7;
  EXPECT_THROW(conforma::SolveHertzForLoad(1.0, 2.0, 1e4, bad), conforma::InputError);
  EXPECT_STREQ(conforma::to_string(HertzStatus::NoSolution), "no_solution");
}
