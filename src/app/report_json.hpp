#pragma once
// JSON and table renderings of wheel contact reports (units in the key names).
#include <nlohmann/json.hpp>
#include <ostream>

#include "conforma/wheel_contact.hpp"

namespace conforma::cli {

nlohmann::json ToJson(const PatchReport& patch);
nlohmann::json ToJson(const WheelContactReport& report);
// One line per patch: the main keys in field units (mm, kN, MPa).
void PrintPatchTableHeader(std::ostream& out);
void PrintPatchRow(std::ostream& out, const std::string& label, const PatchReport& patch);

}  // namespace conforma::cli
