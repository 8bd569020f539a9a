#pragma once
// The contact models of the pipeline (wheel_contact.hpp; docs/architecture.md "Models to compare").
#include <string>

namespace conforma {

// docs/architecture.md "Models to compare":
//   Hertz: Hertz ellipse per rigid gap minimum + FASTSIM (three flexibilities)
//   Kp: planar Kik-Piotrowski, eps = 0.55, half-space + FASTSIM on the KP patch with SDEC flexibilities
//   Kpec: KP with CONTACT's variable eps + the same FASTSIM as Kp
//   Conformal: extended KP in (x^r, s^r), Blanco-Lorenzo coefficients + curved-patch FASTSIM
//   Exact: BEM on the curved surface + Kalker's exact steady-rolling tangential theory (bem_reference.hpp,
//          exact_tangential.hpp): the reference the fast models are measured against
//   Auto: per patch the cheapest adequate one of Hertz, Kpec, Conformal (model_selection.hpp)
enum class ContactModel { Hertz, Kp, Kpec, Conformal, Exact, Auto };
constexpr int kContactModelCount = 6;
const char* to_string(ContactModel model);
// "hertz", "kp", "kpec", "conformal", "exact", "auto" ("reference", the name before the exact tangential part, is
// accepted for "exact"); InputError naming the value otherwise.
ContactModel ParseContactModel(const std::string& name);
// "hertz, kp, kpec, conformal, exact, auto": the names in the table's order, for help texts and messages.
const std::string& ContactModelNames();

}  // namespace conforma
