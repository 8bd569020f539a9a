// S1002 wheel profile from the piecewise definition (EN 13715 / UIC 510-2; DLR coefficients),
// docs/profiles-and-formats.md §1.1. S = lateral coordinate [mm] (taping line 0, flange at S < 0), F = height [mm].
#include <algorithm>
#include <cmath>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma {

namespace {

// Section bounds, ascending (§1.1 "YS").
constexpr double kBreaks[] = {-70.0, -62.764705882, -49.662510381, -39.764473993, -38.426669071,
                              -35.0, -26.0, 32.15796, 60.0};

double circle_upper(double A, double B, double C, double S) { return A + std::sqrt(std::max(0.0, B * B - (S + C) * (S + C))); }

}  // namespace

double S1002Height_mm(double S) {
  if (!(S >= -70.0 - 1e-9 && S <= 60.0 + 1e-9)) throw InputError("S1002Height_mm: S outside [-70, 60] mm");
  if (S >= kBreaks[7]) return 1.364323640 - 0.066666667 * S;  // section A: outer tread, slope -1/15
  if (S >= kBreaks[6]) {                                       // section B: tread polynomial
    const double c[] = {0.0, -3.358537058e-02, 1.565681624e-03, -2.810427944e-05, 5.844240864e-08,
                        -1.562379023e-08, 5.309217349e-15, -5.957839843e-12, 2.646656573e-13};
    double f = 0.0;
    for (int k = 8; k >= 0; --k) f = f * S + c[k];
    return f;
  }
  if (S >= kBreaks[5]) {  // section C: flange-root polynomial
    const double c[] = {-4.320221063e+03, -1.038384026e+03, -1.065501873e+02, -6.051367875,
                        -2.054332446e-01, -4.169739389e-03, -4.687195829e-05, -2.252755540e-07};
    double f = 0.0;
    for (int k = 7; k >= 0; --k) f = f * S + c[k];
    return f;
  }
  if (S >= kBreaks[4]) return 16.446 - std::sqrt(std::max(0.0, 169.0 - (S + 26.210665) * (S + 26.210665)));  // D: R13 concave
  if (S >= kBreaks[3]) return -93.576667419 - 2.747477419 * S;                      // E: 70 degree flank
  if (S >= kBreaks[2]) return circle_upper(8.834924130, 20.0, 58.558326413, S);     // F: R20
  if (S >= kBreaks[1]) return circle_upper(16.0, 12.0, 55.0, S);                   // G: flange tip R12
  return circle_upper(9.519259302, 20.5, 49.5, S);                                  // H: flange back R20.5
}

Profile MakeS1002(const ProfileFitOptions& options) {
  // Adaptive sampling: split each section until neighbouring points are closer than 0.02 mm (the back arc H has
  // a vertical tangent at S = -70, so uniform steps in S would be far too coarse there).
  constexpr double kMaxChord = 0.02;  // mm
  std::vector<Eigen::Vector2d> pts;
  for (int sec = 0; sec < 8; ++sec) {
    const double a = kBreaks[sec], b = kBreaks[sec + 1];
    // evaluate strictly inside the section so each piece uses its own formula
    auto F = [&](double S) { return S1002Height_mm(std::clamp(S, a + 1e-12, b - 1e-12)); };
    std::vector<std::pair<double, double>> stack{{a, b}};
    std::vector<Eigen::Vector2d> sec_pts{{a, F(a)}};
    // depth-first, left to right
    while (!stack.empty()) {
      auto [lo, hi] = stack.back();
      stack.pop_back();
      const Eigen::Vector2d p0(lo, F(lo)), p1(hi, F(hi));
      if ((p1 - p0).norm() > kMaxChord && hi - lo > 1e-9) {
        const double mid = 0.5 * (lo + hi);
        stack.push_back({mid, hi});
        stack.push_back({lo, mid});
      } else {
        sec_pts.push_back(p1);
      }
    }
    if (!pts.empty()) sec_pts.erase(sec_pts.begin());  // shared breakpoint (value jumps < 1.2e-4 mm, §1.1)
    pts.insert(pts.end(), sec_pts.begin(), sec_pts.end());
  }
  for (auto& p : pts) p *= 1e-3;
  ProfileFitOptions fit = options;
  fit.function_of_y = false;  // points are already in curve order
  return Profile::FromPoints(std::move(pts), ProfileKind::Wheel, fit, "S1002 (EN 13715)");
}

}  // namespace conforma
