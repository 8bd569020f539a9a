// Names of the contact models (contact_model.hpp): one table that scenario files, the command line, the pipeline
// and the bindings share.
#include "conforma/contact_model.hpp"

#include <array>

#include "conforma/error.hpp"

namespace conforma {

namespace {
struct ModelName {
  ContactModel model;
  const char* name;
};
// In the order of ContactModel; a new model adds its line here (docs/adding-a-model.md).
constexpr std::array<ModelName, kContactModelCount> kNames = {{{ContactModel::Hertz, "hertz"},
                                                               {ContactModel::Kp, "kp"},
                                                               {ContactModel::Kpec, "kpec"},
                                                               {ContactModel::Conformal, "conformal"},
                                                               {ContactModel::Exact, "exact"},
                                                               {ContactModel::Auto, "auto"}}};
}  // namespace

const char* to_string(ContactModel model) {
  for (const ModelName& m : kNames)
    if (m.model == model) return m.name;
  return "?";
}

const std::string& ContactModelNames() {
  static const std::string names = [] {
    std::string list;
    for (const ModelName& m : kNames) list += (list.empty() ? "" : ", ") + std::string(m.name);
    return list;
  }();
  return names;
}

ContactModel ParseContactModel(const std::string& name) {
  for (const ModelName& m : kNames)
    if (name == m.name) return m.model;
  if (name == "reference") return ContactModel::Exact;  // the name of the normal-only BEM model before issue 14
  throw InputError("unknown contact model '" + name + "' (expected one of " + ContactModelNames() + ")");
}

}  // namespace conforma
