#pragma once
// Small numerical helpers shared by the geometry sources (not part of the public API).
#include <cmath>
#include <utility>
#include <vector>

#include "conforma/geometry.hpp"

namespace conforma::geometry_detail {

// Profile tables and rail mounting (wheelset_track.cpp), shared with the worn-profile update (wheelset_track_worn.cpp).
using GraphTable = WheelsetTrackGeometry::GraphTable;
void tabulate_node(const Profile& p, GraphTable& t, int k, double y0_profile, double s_a, double s_b, double* s);
bool function_like(const Profile& p, double s, double max_slope);
GraphTable build_table(const Profile& p, double spacing, double max_slope, const char* what);
Eigen::Vector2d highest_point(const std::vector<Eigen::Vector2d>& pts);
int highest_sample(const Profile& p);  // index of the first highest stored sample
Eigen::Vector2d uninclined_mount_shift(const Profile& rail, int top_sample);
Profile mount_rail(const Profile& rail, double inclination, bool refit_uninclined, Eigen::Vector2d* shift);
double gauge_point_y(const Profile& rail, double gauge_height, int top);
double gauge_point_y(const Profile& rail, double gauge_height);
void check_roller_radius(double roller_radius, const GraphTable& rail, int k, const Profile& profile);

// Brent's minimisation (golden section with parabolic steps) of f on [a, b]; returns (x_min, f_min).
template <class F>
std::pair<double, double> brent_minimize(F&& f, double a, double b, double x_tolerance, int max_iterations = 60) {
  const double golden = 0.3819660112501051;
  double x = a + golden * (b - a), w = x, v = x;
  double fx = f(x), fw = fx, fv = fx;
  double d = 0.0, e = 0.0;
  for (int it = 0; it < max_iterations; ++it) {
    const double m = 0.5 * (a + b);
    const double tol1 = x_tolerance + 1e-12 * std::abs(x), tol2 = 2.0 * tol1;
    if (std::abs(x - m) <= tol2 - 0.5 * (b - a)) break;
    bool golden_step = true;
    if (std::abs(e) > tol1) {  // trial parabola through x, w, v
      double r = (x - w) * (fx - fv), q = (x - v) * (fx - fw), p = (x - v) * q - (x - w) * r;
      q = 2.0 * (q - r);
      if (q > 0) p = -p;
      q = std::abs(q);
      const double e_previous = e;
      e = d;
      if (std::abs(p) < std::abs(0.5 * q * e_previous) && p > q * (a - x) && p < q * (b - x)) {
        d = p / q;
        const double u = x + d;
        if (u - a < tol2 || b - u < tol2) d = (m > x) ? tol1 : -tol1;
        golden_step = false;
      }
    }
    if (golden_step) {
      e = (x >= m) ? a - x : b - x;
      d = golden * e;
    }
    const double u = (std::abs(d) >= tol1) ? x + d : x + (d > 0 ? tol1 : -tol1);
    const double fu = f(u);
    if (fu <= fx) {
      if (u >= x) a = x; else b = x;
      v = w; fv = fw; w = x; fw = fx; x = u; fx = fu;
    } else {
      if (u < x) a = u; else b = u;
      if (fu <= fw || w == x) { v = w; fv = fw; w = u; fw = fu; }
      else if (fu <= fv || v == x || v == w) { v = u; fv = fu; }
    }
  }
  return {x, fx};
}

}  // namespace conforma::geometry_detail
