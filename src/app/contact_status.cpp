// Wheel status of `conforma contact` (contact_status.hpp).
#include "contact_status.hpp"

#include <cstdio>

#include "exit_status.hpp"

namespace conforma::cli {

namespace {
std::string Describe(const WheelContactReport& r, double load_N) {
  char buf[200];
  if (load_N >= 0.0 && r.status == WheelContactStatus::NotConverged)
    std::snprintf(buf, sizeof buf, "%s wheel: status %s: carries %.1f kN of the prescribed %.1f kN", to_string(r.side),
                  to_string(r.status), r.pressure_vertical_force_N * 1e-3, load_N * 1e-3);
  else
    std::snprintf(buf, sizeof buf, "%s wheel: status %s", to_string(r.side), to_string(r.status));
  return buf;
}
}  // namespace

void PrintWheelStatus(std::ostream& out, const WheelContactReport& report, double load_N) {
  if (report.status == WheelContactStatus::Ok) return;
  out << "   " << (report.status == WheelContactStatus::NotConverged ? "WARNING: " : "") << Describe(report, load_N)
      << "\n";
}

void ThrowIfNotConverged(const std::vector<WheelContactReport>& reports, double load_N) {
  std::string what;
  for (const WheelContactReport& r : reports)
    if (r.status == WheelContactStatus::NotConverged) what += (what.empty() ? "" : "; ") + Describe(r, load_N);
  if (!what.empty()) throw IncompleteResult(ExitCode::NotConverged, "load control did not converge: " + what);
}

}  // namespace conforma::cli
