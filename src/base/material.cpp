#include "conforma/material.hpp"

#include "conforma/error.hpp"

namespace conforma {

void Material::validate() const {
  require_positive(shear_modulus_Pa, "shear_modulus_Pa");
  require_positive(density_kg_m3, "density_kg_m3");
  require_finite(poisson_ratio, "poisson_ratio");
  if (poisson_ratio < 0.0 || poisson_ratio >= 0.5) throw InputError("parameter 'poisson_ratio' must lie in [0, 0.5)");
}

}  // namespace conforma
