#pragma once
// The completeness rule of a wheel contact result in the command line (issue 13; the same sets as Python's
// conforma/_status.py): a wheel is incomplete when
//   - its load control did not converge (status not_converged): it carries another load than the one prescribed;
//   - it has no contact although a positive load is prescribed (load control: the load is not carried);
//   - a patch's normal_status is not "ok" / "hertz_regularised", or its tangential_status not "ok" / "full_slip" /
//     "no_creepage" / "not_solved" (the normal-only reference model).
// The text output says so per wheel, and the command ends with NotConverged (exit 4; the first two) or
// PartialResult (exit 5; patch statuses) after writing its output (--allow-partial: exit 0).
#include <ostream>
#include <string>
#include <vector>

#include "conforma/wheel_contact.hpp"

namespace conforma::cli {

// What is incomplete in one wheel's result ([] when complete); load_N < 0: approach mode (no prescribed load).
std::vector<std::string> WheelProblems(const WheelContactReport& report, double load_N);
// One line per problem ("   WARNING: right wheel: status not_converged: carries 129.9 kN of the prescribed
// 163.1 kN"); nothing for a complete wheel.
void PrintWheelStatus(std::ostream& out, const WheelContactReport& report, double load_N);
// Throws IncompleteResult naming every problem of `reports` (exit 4 when a load is not carried, else 5).
void ThrowIfIncomplete(const std::vector<WheelContactReport>& reports, double load_N);

}  // namespace conforma::cli
