#include "conforma/material.hpp"

#include <string>

#include "conforma/error.hpp"

namespace conforma {

namespace {
constexpr double kMinShearModulus_Pa = 1e8;
constexpr double kMaxShearModulus_Pa = 1e12;
// (1e300 kg/m^3 gave a wear step of 1.6e296 km, 1e-300 one of 0 km, both exit 0: sanitizer probe, session 27;
// steels ~7850, polymer rollers ~1200, tungsten carbide ~15600)
constexpr double kMinDensity_kg_m3 = 500.0;
constexpr double kMaxDensity_kg_m3 = 30000.0;

// A positive `value` within [lo, hi] `unit`, else an InputError: "<name> = <value> <unit> is outside <lo> ... <hi>
// <unit>: not a wheel or rail material (unit? <typical>)".
void RequireMaterialRange(double value, const char* name, double lo, double hi, const char* unit, const char* typical) {
  require_positive(value, name);
  if (value < lo || value > hi)
    throw InputError(std::string(name) + " = " + MessageNumber(value) + " " + unit + " is outside " +
                     MessageNumber(lo) + " ... " + MessageNumber(hi) + " " + unit +
                     ": not a wheel or rail material (unit? " + typical + ")");
}
}  // namespace

void Material::validate() const {
  // (G = 100 Pa under a wheel load came back as "no contact", 1e300 Pa as 1e280 N: fuzzing, session 25; steels
  // 75-85 GPa, polymer rollers of scaled rigs ~1 GPa)
  RequireMaterialRange(shear_modulus_Pa, "shear_modulus_Pa", kMinShearModulus_Pa, kMaxShearModulus_Pa, "Pa",
                       "steel ~8e10 Pa");
  RequireMaterialRange(density_kg_m3, "density_kg_m3", kMinDensity_kg_m3, kMaxDensity_kg_m3, "kg/m^3",
                       "steel ~7850 kg/m^3");
  require_finite(poisson_ratio, "poisson_ratio");
  if (poisson_ratio < 0.0 || poisson_ratio >= 0.5) throw InputError("parameter 'poisson_ratio' must lie in [0, 0.5)");
}

}  // namespace conforma
