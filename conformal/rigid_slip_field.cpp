// Rigid slip fields of the exact tangential solver from creepages (Kalker 1990 §1.4; exact_tangential.hpp).
#include <string>

#include "conforma/error.hpp"
#include "conforma/exact_tangential.hpp"

namespace conforma {

namespace {
constexpr double kSpinOffset = 1.0 / 6.0;  // CONTACT's facphi: the spin slip at x + dx/6 in steady rolling
}  // namespace

RigidSlipField RigidSlipFromColumnCreepages(const BemGrid& grid, const std::vector<FastsimCreepages>& per_column,
                                            double spin_origin_x_m, double spin_origin_s_m) {
  grid.validate();
  if (per_column.size() != static_cast<size_t>(grid.ns))
    throw InputError("rigid slip: " + std::to_string(per_column.size()) + " column creepages for a grid of " +
                     std::to_string(grid.ns) + " columns");
  require_finite(spin_origin_x_m, "spin_origin_x_m");
  require_finite(spin_origin_s_m, "spin_origin_s_m");
  RigidSlipField w;
  w.wx.resize(grid.nx, grid.ns);
  w.ws.resize(grid.nx, grid.ns);
  for (int j = 0; j < grid.ns; ++j) {
    const FastsimCreepages& c = per_column[static_cast<size_t>(j)];
    require_finite(c.xi, "creepage xi");
    require_finite(c.eta, "creepage eta");
    require_finite(c.phi_per_m, "creepage phi");
    const double y = grid.s_centre_m(j) - spin_origin_s_m;
    for (int i = 0; i < grid.nx; ++i) {
      // w = (xi - phi y, eta + phi x)   (Kalker's rigid slip; fastsim.hpp), with the spin term at x + dx/6 as CONTACT
      // evaluates it in steady rolling (m_sdis.f90 set_tang_rhs, facphi = 1/6 [V-code]; docs/physics-reference.md §14.1)
      w.wx(i, j) = c.xi - c.phi_per_m * y;
      w.ws(i, j) = c.eta + c.phi_per_m * (grid.x_centre_m(i) + kSpinOffset * grid.dx_m - spin_origin_x_m);
    }
  }
  return w;
}

RigidSlipField RigidSlipFromCreepages(const BemGrid& grid, const FastsimCreepages& creepages, double spin_origin_x_m,
                                      double spin_origin_s_m) {
  grid.validate();  // ns >= 1 before it sizes the vector
  return RigidSlipFromColumnCreepages(grid, std::vector<FastsimCreepages>(static_cast<size_t>(grid.ns), creepages),
                                      spin_origin_x_m, spin_origin_s_m);
}

}  // namespace conforma
