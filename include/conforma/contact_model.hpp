#pragma once
// The contact models of the pipeline (wheel_contact.hpp; docs/architecture.md "Models to compare").
#include <string>

namespace conforma {

enum class ContactModel { Hertz, Kp, Kpec, Conformal, Reference, Auto };
constexpr int kContactModelCount = 6;
const char* to_string(ContactModel model);
// "hertz", "kp", "kpec", "conformal", "reference", "auto"; InputError naming the value otherwise.
ContactModel ParseContactModel(const std::string& name);
// "hertz, kp, kpec, conformal, reference, auto": the names in the table's order, for help texts and messages.
const std::string& ContactModelNames();

}  // namespace conforma
