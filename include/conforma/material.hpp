#pragma once
// Elastic material of wheel and rail (both bodies the same steel unless stated). SI units.
namespace conforma {

struct Material {
  double shear_modulus_Pa = 82.0e9;  // G
  double poisson_ratio = 0.28;       // nu
  double density_kg_m3 = 7850.0;     // rho (wear depth from mass loss)

  double young_modulus_Pa() const { return 2.0 * shear_modulus_Pa * (1.0 + poisson_ratio); }
  // Combined plane-strain modulus of two identical bodies, E* = E / (2 (1 - nu^2)) = G / (1 - nu)
  // (docs/physics-reference.md §0; CONTACT's e_star).
  double combined_modulus_Pa() const { return shear_modulus_Pa / (1.0 - poisson_ratio); }
  // Throws InputError naming the parameter when a value is not physical.
  void validate() const;
};

}  // namespace conforma
