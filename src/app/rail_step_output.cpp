// Output of the rail steps of a wear run (rail_step_output.hpp).
#include "rail_step_output.hpp"

#include <cstdio>
#include <fstream>
#include <iomanip>

#include "conforma/error.hpp"
#include "wear_output.hpp"

namespace conforma::cli {

namespace {

const char* kSide[2] = {"left", "right"};

std::string Km(double km) {
  char b[32];
  std::snprintf(b, sizeof b, "%.0f", km);
  return b;
}

bool AllValid(const RailStepSummary& k) { return k.wheels_valid && k.side[0].valid && k.side[1].valid; }

bool Holds(const RailStepSummary& k) {
  return k.side[0].area_residual <= kRailAreaIdentityTolerance && k.side[1].area_residual <= kRailAreaIdentityTolerance;
}

}  // namespace

std::vector<RailStepSummary> WriteRailStepFiles(const std::string& dir, const WearSimulationResult& r) {
  const std::vector<RailStepSummary> rail = SummariseRailSteps(r);
  if (r.rails.empty() && r.rail_results.empty()) return rail;
  std::ofstream out(dir + "/rail_steps.csv");
  if (!out) throw InputError(dir + "/rail_steps.csv: cannot write");
  out << "# one row per rail step k (paper 003 Fig. 11): the wheel sequence run on rail r_k (from the new wheel), and "
         "per side the rail r_{k+1} (files rail_<side>_<new_rail>) against r_k: removed area and largest depth along "
         "the normals of r_k, the weighted mean of the virtual rails' areas, their relative difference, validity; "
         "cumulative: r_{k+1} against the initial rail\n";
  out << "rail_step,new_rail,wheel_steps,wheel_km,wheel_area_mm2,wheel_max_depth_mm,tread_wear_mm,flange_wear_mm,"
         "wheels_valid";
  for (const char* s : kSide)
    out << "," << s << "_status," << s << "_valid," << s << "_passages," << s << "_removed_area_mm2," << s
        << "_max_depth_mm," << s << "_virtual_mean_area_mm2," << s << "_area_residual," << s << "_virtual_rails," << s
        << "_cumulative_area_mm2," << s << "_cumulative_max_depth_mm," << s << "_max_curvature_1_m";
  out << "\n" << std::setprecision(12);
  for (const RailStepSummary& k : rail) {
    out << k.rail_step << "," << k.rail_step + 1 << "," << k.wheel_steps << "," << k.wheel_km << ","
        << k.wheel_removed.area_m2 * 1e6 << "," << k.wheel_removed.max_depth_m * 1e3 << "," << k.tread_wear_m * 1e3
        << "," << k.flange_wear_m * 1e3 << "," << (k.wheels_valid ? 1 : 0);
    for (const RailSideStepSummary& o : k.side)
      out << "," << to_string(o.status) << "," << (o.valid ? 1 : 0) << "," << o.passages << ","
          << o.removed.area_m2 * 1e6 << "," << o.removed.max_depth_m * 1e3 << "," << o.virtual_mean_area_m2 * 1e6 << ","
          << o.area_residual << "," << o.virtual_removed.size() << "," << o.cumulative.area_m2 * 1e6 << ","
          << o.cumulative.max_depth_m * 1e3 << "," << o.max_abs_curvature_1_m;
    out << "\n";
  }
  // depth of every virtual rail and of the averaged rail, along r_k (arc length and position of r_k's nodes)
  for (size_t k = 0; k < rail.size(); ++k) {
    const std::string name = dir + "/rail_step_" + Num3(static_cast<int>(k + 1)) + "_depth.csv";
    std::ofstream d(name);
    if (!d) throw InputError(name + ": cannot write");
    size_t nv = 0;
    for (const RailSideStepSummary& o : rail[k].side) nv = std::max(nv, o.virtual_removed.size());
    d << "# rail step " << k << ": depth along the normals of r_" << k << " (y, z its nodes, mounted rail) of the "
      << "averaged rail r_" << k + 1 << " and of each virtual rail (one per wheel profile of the sequence; weight = "
      << "share of the sequence's km)\n";
    d << "side,s_mm,y_mm,z_mm,rail_mm";
    for (size_t j = 0; j < nv; ++j) d << ",virtual_" << j << "_mm";
    d << "\n# weights" << std::setprecision(17);
    for (const RailSideStepSummary& o : rail[k].side) {
      d << " |";
      for (double w : o.weights) d << " " << w;
    }
    d << "\n" << std::setprecision(10);
    for (int side = 0; side < 2; ++side) {
      const RailSideStepSummary& o = rail[k].side[side];
      const Profile& base = RailBeforeStep(r, k, side);
      for (size_t i = 0; i < o.removed.depth.size(); ++i) {
        const double s = o.removed.depth.s(i);
        const Eigen::Vector2d q = base.position(s);
        d << kSide[side] << "," << s * 1e3 << "," << q.x() * 1e3 << "," << q.y() * 1e3 << ","
          << o.removed.depth.depth_m[i] * 1e3;
        for (size_t j = 0; j < nv; ++j)
          d << "," << (j < o.virtual_removed.size() && i < o.virtual_removed[j].depth.size()
                           ? o.virtual_removed[j].depth.depth_m[i] * 1e3
                           : 0.0);
        d << "\n";
      }
    }
  }
  // every rail against the initial rail, on the initial rail's nodes
  std::ofstream c(dir + "/rail_cumulative_depth.csv");
  if (!c) throw InputError(dir + "/rail_cumulative_depth.csv: cannot write");
  c << "# depth of rail r_k along the normals of the initial rail r_0 (y, z its nodes, mounted rail)\n";
  c << "side,new_rail,s_mm,y_mm,z_mm,depth_mm\n" << std::setprecision(10);
  for (int side = 0; side < 2; ++side)
    for (size_t k = 0; k < rail.size(); ++k) {
      const RemovedAlongNormals& m = rail[k].side[side].cumulative;
      for (size_t i = 0; i < m.depth.size(); ++i) {
        const Eigen::Vector2d q = r.initial_rail[side].position(m.depth.s(i));
        c << kSide[side] << "," << k + 1 << "," << m.depth.s(i) * 1e3 << "," << q.x() * 1e3 << "," << q.y() * 1e3
          << "," << m.depth.depth_m[i] * 1e3 << "\n";
      }
    }
  return rail;
}

void WriteRailStepReport(const std::string& dir, const Scenario& sc, const std::vector<RailStepSummary>& rail,
                         const std::string& label, const std::string& plot_note) {
  std::ofstream md(dir + "/rail_steps.md");
  if (!md) throw InputError(dir + "/rail_steps.md: cannot write");
  md << "# Rail steps: " << sc.name << " (" << label << ")\n\n";
  md << "Scenario `" << sc.source << "`: " << sc.rail_steps.steps << " rail steps (paper 003 §6, Fig. 11), rail cap "
     << sc.rail_steps.cap_m * 1e3 << " mm, wheel cap " << sc.update.cap_m * 1e3 << " mm, each rail step runs the wheel "
     << "from the new profile over " << (sc.update.total_km > 0 ? Km(sc.update.total_km) + " km" : "its steps")
     << " (at most " << sc.update.steps << " wheel steps). " << rail.size() << " rail steps computed.\n\n";
  md << "Areas along the normals of the rail before the step (first order in the depth, "
        "`include/conforma/rail_step_summary.hpp`); identity: |A - sum_j w_j A_j| / sum_j w_j A_j <= "
     << kRailAreaIdentityTolerance << ".\n\n";
  md << "| rail step | wheel steps | wheel km | wheel area mm² | wheel max depth mm | side | passages | rail area mm² | "
        "rail max depth mm | mean of virtual rails mm² | residual | cumulative area mm² | cumulative max depth mm | "
        "valid |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  char buf[512];
  for (const RailStepSummary& k : rail)
    for (int side = 0; side < 2; ++side) {
      const RailSideStepSummary& o = k.side[side];
      std::snprintf(buf, sizeof buf,
                    "| %d | %d | %.0f | %.4f | %.3f | %s | %.4g | %.6f | %.4f | %.6f | %.2e | %.5f | %.4f | %s |\n",
                    k.rail_step + 1, k.wheel_steps, k.wheel_km, k.wheel_removed.area_m2 * 1e6,
                    k.wheel_removed.max_depth_m * 1e3, kSide[side], o.passages, o.removed.area_m2 * 1e6,
                    o.removed.max_depth_m * 1e3, o.virtual_mean_area_m2 * 1e6, o.area_residual,
                    o.cumulative.area_m2 * 1e6, o.cumulative.max_depth_m * 1e3,
                    o.valid && k.wheels_valid ? "yes" : "**NO**");
      md << buf;
    }
  bool holds = true, valid = true;
  for (const RailStepSummary& k : rail) holds = holds && Holds(k), valid = valid && AllValid(k);
  md << "\nIdentity " << (holds ? "holds" : "**FAILS**") << " in every rail step; every wheel and rail profile "
     << (valid ? "valid" : "**NOT valid**") << ".\n\n## Plots\n\n";
  if (plot_note.empty()) {
    md << "![rail evolution](rail_evolution.png)\n\n";
    for (const RailStepSummary& k : rail)
      md << "![rail step " << k.rail_step + 1 << "](rail_step_" << Num3(k.rail_step + 1) << ".png)\n\n";
  } else {
    md << "**(plots not produced: " << plot_note << ")**\n";
  }
}

bool PrintRailStepSummary(const std::vector<RailStepSummary>& rail) {
  bool ok = true;
  std::printf("rail steps (area along the normals of the rail before the step; residual = |A - mean of the virtual "
              "rails' A| / mean):\n");
  for (const RailStepSummary& k : rail) {
    std::printf("  rail step %2d: wheel %d steps %.0f km, area %.4f mm2, max %.3f mm | left: %.5f mm2 max %.4f mm "
                "res %.1e | right: %.5f mm2 max %.4f mm res %.1e | %s\n",
                k.rail_step + 1, k.wheel_steps, k.wheel_km, k.wheel_removed.area_m2 * 1e6,
                k.wheel_removed.max_depth_m * 1e3, k.side[0].removed.area_m2 * 1e6, k.side[0].removed.max_depth_m * 1e3,
                k.side[0].area_residual, k.side[1].removed.area_m2 * 1e6, k.side[1].removed.max_depth_m * 1e3,
                k.side[1].area_residual, AllValid(k) ? "valid" : "NOT VALID");
    ok = ok && AllValid(k) && Holds(k);
  }
  std::fflush(stdout);
  return ok;
}

}  // namespace conforma::cli
