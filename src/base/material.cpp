#include "conforma/material.hpp"

#include <cstdio>

#include "conforma/error.hpp"

namespace conforma {

namespace {
constexpr double kMinShearModulus_Pa = 1e8;
constexpr double kMaxShearModulus_Pa = 1e12;
// (1e300 kg/m^3 gave a wear step of 1.6e296 km, 1e-300 one of 0 km, both exit 0: sanitizer probe, session 27;
// steels ~7850, polymer rollers ~1200, tungsten carbide ~15600)
constexpr double kMinDensity_kg_m3 = 500.0;
constexpr double kMaxDensity_kg_m3 = 30000.0;
}  // namespace

void Material::validate() const {
  require_positive(shear_modulus_Pa, "shear_modulus_Pa");
  // (G = 100 Pa under a wheel load came back as "no contact", 1e300 Pa as 1e280 N: fuzzing, session 25; steels
  // 75-85 GPa, polymer rollers of scaled rigs ~1 GPa)
  if (shear_modulus_Pa < kMinShearModulus_Pa || shear_modulus_Pa > kMaxShearModulus_Pa) {
    char text[200];
    std::snprintf(text, sizeof text, "shear_modulus_Pa = %g Pa is outside %g ... %g Pa: not a wheel or rail material "
                  "(unit? steel ~8e10 Pa)", shear_modulus_Pa, kMinShearModulus_Pa, kMaxShearModulus_Pa);
    throw InputError(text);
  }
  require_positive(density_kg_m3, "density_kg_m3");
  if (density_kg_m3 < kMinDensity_kg_m3 || density_kg_m3 > kMaxDensity_kg_m3) {
    char text[200];
    std::snprintf(text, sizeof text, "density_kg_m3 = %g kg/m^3 is outside %g ... %g kg/m^3: not a wheel or rail "
                  "material (unit? steel ~7850 kg/m^3)", density_kg_m3, kMinDensity_kg_m3, kMaxDensity_kg_m3);
    throw InputError(text);
  }
  require_finite(poisson_ratio, "poisson_ratio");
  if (poisson_ratio < 0.0 || poisson_ratio >= 0.5) throw InputError("parameter 'poisson_ratio' must lie in [0, 0.5)");
}

}  // namespace conforma
