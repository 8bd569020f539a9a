#pragma once
// JSON and table renderings of wheel contact reports (units in the key names).
#include <nlohmann/json.hpp>
#include <ostream>

#include "conforma/wheel_contact.hpp"

namespace conforma::cli {

nlohmann::json ToJson(const PatchReport& patch);
nlohmann::json ToJson(const WheelContactReport& report);
// One line per patch: the main keys in field units (mm, kN, MPa). The header names the first column (label_name:
// the wheel of `contact`, the model of `sweep`) and is followed by a legend line of the columns.
void PrintPatchTableHeader(std::ostream& out, const std::string& label_name = "case");
void PrintPatchRow(std::ostream& out, const std::string& label, const PatchReport& patch);
// The report's plausibility warnings (WheelContactReport::warnings), one "warning: <label>: ..." line each.
void PrintWarnings(std::ostream& out, const std::string& label, const WheelContactReport& report);

}  // namespace conforma::cli
