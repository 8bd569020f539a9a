// Names of the contact models (contact_model.hpp): in the core library so that scenario files, the pipeline and the
// bindings share one table.
#include "conforma/contact_model.hpp"

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(ContactModel model) {
  switch (model) {
    case ContactModel::Hertz: return "hertz";
    case ContactModel::Kp: return "kp";
    case ContactModel::Kpec: return "kpec";
    case ContactModel::Conformal: return "conformal";
    case ContactModel::Reference: return "reference";
    case ContactModel::Auto: return "auto";
  }
  return "?";
}

ContactModel ParseContactModel(const std::string& name) {
  for (ContactModel m : {ContactModel::Hertz, ContactModel::Kp, ContactModel::Kpec, ContactModel::Conformal,
                         ContactModel::Reference, ContactModel::Auto})
    if (name == to_string(m)) return m;
  throw InputError("unknown contact model '" + name + "' (expected hertz, kp, kpec, conformal, reference or auto)");
}

}  // namespace conforma
