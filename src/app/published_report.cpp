// Compare report: our runs beside a published study of the same case (published_report.hpp).
#include "published_report.hpp"

#include <algorithm>
#include <cstdio>

namespace conforma::cli {

RunFigures RunFiguresAt(const std::string& model, const WearSimulationResult& run, int steps) {
  RunFigures f;
  f.model = model;
  f.initial = run.initial_dimensions;
  f.last = run.initial_dimensions;
  if (run.steps.empty()) return f;
  const size_t n = steps > 0 ? std::min(run.steps.size(), static_cast<size_t>(steps)) : run.steps.size();
  const WearStepRecord& s = run.steps[n - 1];
  f.steps = static_cast<int>(n);
  f.km = s.km;
  f.tread_wear_m = s.tread_wear_m;
  f.flange_wear_m = s.flange_wear_m;
  f.last = s.dimensions;
  return f;
}

namespace {

std::string Figure(double value, double published, const char* fmt) {  // "ours (published)"
  char a[48], b[48];
  std::snprintf(a, sizeof a, fmt, value);
  if (published > 0.0) std::snprintf(b, sizeof b, fmt, published);
  return std::string(a) + " (" + (published > 0.0 ? b : "-") + ")";
}

}  // namespace

std::vector<PublishedCheck> WritePublishedSection(std::ostream& md, const PublishedStudy& study,
                                                  const std::vector<RunFigures>& runs) {
  if (study.empty()) return {};
  md << "\n## Against the published study\n\n";
  md << "Source: " << study.source << " (scenario key `published`; docs/physics-reference.md §8.11). ";
  if (study.steps > 0) md << "Compared after " << study.steps << " wheel steps. ";
  md << "Ours first, published in parentheses.\n\n";
  md << "| model | steps | km | tread wear mm | flange wear mm | Sd | Sh | qR |\n|---|---|---|---|---|---|---|---|\n";
  for (const RunFigures& r : runs) {
    const PublishedModelFigures* p = study.find(r.model);
    if (p == nullptr) continue;
    md << "| " << r.model << " | " << r.steps << (study.steps > 0 && r.steps < study.steps ? " (short)" : "") << " | "
       << Figure(r.km, p->km, "%.0f") << " | " << Figure(r.tread_wear_m * 1e3, p->tread_wear_m * 1e3, "%.3f") << " | "
       << Figure(r.flange_wear_m * 1e3, p->flange_wear_m * 1e3, "%.3f") << " | "
       << to_string(TrendOf(r.initial.sd_m, r.last.sd_m)) << " (" << to_string(p->sd) << ") | "
       << to_string(TrendOf(r.initial.sh_m, r.last.sh_m)) << " (" << to_string(p->sh) << ") | "
       << to_string(TrendOf(r.initial.qr_m, r.last.qr_m)) << " (" << to_string(p->qr) << ") |\n";
  }
  const std::vector<PublishedCheck> checks = ComparePublished(study, runs);
  int agree = 0;
  md << "\n| finding | ours | published | agrees |\n|---|---|---|---|\n";
  for (const PublishedCheck& c : checks) {
    md << "| " << c.what << " | " << c.ours << " | " << c.published << " | " << (c.agrees ? "yes" : "**no**") << " |\n";
    agree += c.agrees ? 1 : 0;
  }
  char buf[160];
  std::snprintf(buf, sizeof buf,
                "\n%d of %zu findings agree. A trend is flat when Sd, Sh or qR changes by less than %.2f mm.\n", agree,
                checks.size(), kFlatTrendTolerance_m * 1e3);
  md << buf;
  return checks;
}

}  // namespace conforma::cli
