#pragma once
// The status of each wheel of `conforma contact` (issue 13): a wheel whose load control did not converge carries
// another load than the one prescribed; the text output says so per wheel, and the command ends with
// NotConverged (exit 4) after writing its output (--allow-partial: exit 0).
#include <ostream>
#include <string>
#include <vector>

#include "conforma/wheel_contact.hpp"

namespace conforma::cli {

// One line "   <side>: status not_converged: carries 129.9 kN of the prescribed 163.1 kN" for a wheel whose
// status is not ok (nothing for an ok wheel); load_N < 0 (approach mode): no prescribed load.
void PrintWheelStatus(std::ostream& out, const WheelContactReport& report, double load_N);
// Throws IncompleteResult(NotConverged) naming every wheel of `reports` whose load control did not converge.
void ThrowIfNotConverged(const std::vector<WheelContactReport>& reports, double load_N);

}  // namespace conforma::cli
