// Completeness of wheel contact results in the command line (contact_status.hpp).
#include "contact_status.hpp"

#include <cstdio>
#include <set>

#include "exit_status.hpp"

namespace conforma::cli {

namespace {
const std::set<std::string> kNormalComplete = {"ok", "hertz_regularised"};
const std::set<std::string> kTangentialComplete = {"ok", "full_slip", "no_creepage", "not_solved"};

bool LoadNotCarried(const WheelContactReport& r, double load_N) {
  return r.status == WheelContactStatus::NotConverged || (load_N > 0.0 && r.status == WheelContactStatus::NoContact);
}
}  // namespace

std::vector<std::string> WheelProblems(const WheelContactReport& r, double load_N) {
  std::vector<std::string> out;
  char buf[320];
  if (LoadNotCarried(r, load_N)) {
    // both vertical forces: which one load control balanced depends on WheelContactOptions::load_balance (the total
    // by default); at a flange they differ by the creep force's vertical part
    std::snprintf(buf, sizeof buf,
                  "%s wheel: status %s: carries %.1f kN of the prescribed %.1f kN (total vertical force; the "
                  "pressure alone %.1f kN)",
                  to_string(r.side), to_string(r.status), r.vertical_force_N * 1e-3, load_N * 1e-3,
                  r.pressure_vertical_force_N * 1e-3);
    out.push_back(buf);
  } else if (r.status == WheelContactStatus::NotConverged) {
    out.push_back(std::string(to_string(r.side)) + " wheel: status " + to_string(r.status));
  }
  for (size_t j = 0; j < r.patches.size(); ++j) {
    const PatchReport& p = r.patches[j];
    if (!kNormalComplete.count(p.normal_status))
      out.push_back(std::string(to_string(r.side)) + " wheel, patch " + std::to_string(j) + ": normal_status " +
                    p.normal_status);
    if (!kTangentialComplete.count(p.tangential_status))
      out.push_back(std::string(to_string(r.side)) + " wheel, patch " + std::to_string(j) + ": tangential_status " +
                    p.tangential_status);
  }
  return out;
}

void PrintWheelStatus(std::ostream& out, const WheelContactReport& report, double load_N) {
  for (const std::string& problem : WheelProblems(report, load_N)) out << "   WARNING: " << problem << "\n";
}

void ThrowIfIncomplete(const std::vector<WheelContactReport>& reports, double load_N) {
  std::string what;
  bool load = false;
  for (const WheelContactReport& r : reports) {
    load |= LoadNotCarried(r, load_N);
    for (const std::string& problem : WheelProblems(r, load_N)) what += (what.empty() ? "" : "; ") + problem;
  }
  if (what.empty()) return;
  if (load) throw IncompleteResult(ExitCode::NotConverged, "load control did not converge: " + what);
  throw IncompleteResult(ExitCode::PartialResult, "a patch solve is incomplete: " + what);
}

}  // namespace conforma::cli
