// Integrated outputs of the reference BEM: forces along the reference normal (fn_bar) and on the curved
// surface (fn_tilde, docs/physics-reference.md §9 last item), area, extents, point of action, complementarity.
#include <algorithm>
#include <cmath>

#include "bem_operator.hpp"

namespace conforma {
namespace bem_detail {

void SummariseBem(const Eigen::VectorXd& pressure, const Eigen::VectorXd& deformed_gap, BemResult& result) {
  const BemGrid& grid = result.grid;
  const int nx = grid.nx, ns = grid.ns;
  const double area = grid.element_area_m2();
  result.pressure_Pa = Eigen::Map<const Eigen::MatrixXd>(pressure.data(), nx, ns);
  result.deformed_gap_m = Eigen::Map<const Eigen::MatrixXd>(deformed_gap.data(), nx, ns);
  double fn_bar = 0.0, fn_tilde = 0.0, moment_x = 0.0, moment_s = 0.0, p_max = 0.0, complementarity = 0.0;
  int count = 0, i_min = nx, i_max = -1, j_min = ns, j_max = -1;
  for (int j = 0; j < ns; ++j) {
    const double c = std::cos(grid.alpha(j));
    for (int i = 0; i < nx; ++i) {
      const double p = result.pressure_Pa(i, j);
      const double g = result.deformed_gap_m(i, j);
      if (p > 0.0) {
        fn_bar += p * c * area;
        fn_tilde += p * area;
        moment_x += p * area * grid.x_centre_m(i);
        moment_s += p * area * grid.s_centre_m(j);
        p_max = std::max(p_max, p);
        ++count;
        i_min = std::min(i_min, i);
        i_max = std::max(i_max, i);
        j_min = std::min(j_min, j);
        j_max = std::max(j_max, j);
        complementarity = std::max(complementarity, std::fabs(g));
      } else {
        complementarity = std::max(complementarity, -g);
      }
    }
  }
  result.normal_force_reference_N = fn_bar;
  result.normal_force_surface_N = fn_tilde;
  result.contact_elements = count;
  result.contact_area_m2 = count * area;
  result.max_pressure_Pa = p_max;
  result.max_complementarity_m = complementarity;
  if (count == 0) return;
  result.centre_of_pressure_x_m = moment_x / fn_tilde;
  result.centre_of_pressure_s_m = moment_s / fn_tilde;
  result.contact_x_min_m = grid.x_centre_m(i_min) - 0.5 * grid.dx_m;
  result.contact_x_max_m = grid.x_centre_m(i_max) + 0.5 * grid.dx_m;
  result.contact_s_min_m = grid.s_centre_m(j_min) - 0.5 * grid.ds_m;
  result.contact_s_max_m = grid.s_centre_m(j_max) + 0.5 * grid.ds_m;
  result.contact_length_x_m = result.contact_x_max_m - result.contact_x_min_m;
  result.contact_width_s_m = result.contact_s_max_m - result.contact_s_min_m;
  result.contact_at_grid_edge = i_min == 0 || i_max == nx - 1 || j_min == 0 || j_max == ns - 1;
}

}  // namespace bem_detail
}  // namespace conforma
