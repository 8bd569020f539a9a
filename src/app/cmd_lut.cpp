// conforma lut build|info|eval|check: the contact look-up table of one wheel-rail pair (contact_lut.hpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli_setup.hpp"
#include "cli_checks.hpp"
#include "commands.hpp"
#include "text_format.hpp"
#include "conforma/contact_lut.hpp"
#include "conforma/contact_lut_check.hpp"
#include "conforma/contact_lut_grid.hpp"
#include "conforma/contact_lut_io.hpp"
#include "conforma/error.hpp"
#include "contact_status.hpp"
#include "progress.hpp"
#include "report_json.hpp"

namespace conforma::cli {

namespace {

struct LutArgs {
  TrackArgs track;
  ContactArgs contact;
  double elastic_flange_deg = 0.0;  // 0: rigid flange
  void add_to(CLI::App* sub) {
    track.add_to(sub);
    contact.add_to(sub);
    sub->add_option("--elastic-flange-deg", elastic_flange_deg,
                    "elastic flange: contact points steeper than this do not define the touching position "
                    "(scenario key elastic_flange_deg; 0 = rigid flange)");
  }
  WheelContactOptions options() const {
    WheelContactOptions o = contact.options();
    if (elastic_flange_deg != 0.0) {
      if (!(elastic_flange_deg > 0.0 && elastic_flange_deg < 90.0))
        throw InputError("--elastic-flange-deg must be between 0 and 90");
      o.max_touching_contact_angle_rad = elastic_flange_deg * M_PI / 180.0;
    }
    return o;
  }
};

void PrintHeader(std::ostream& out, const ContactLut& lut) {
  const ContactLutHeader& h = lut.header;
  const ContactLutGrid& g = lut.grid;
  char line[512];
  out << "contact LUT: wheel " << h.wheel_profile << " on rail " << h.rail_profile << " (" << h.track << ")\n";
  std::snprintf(line, sizeof line,
                "  model %s, G = %.6g GPa, nu = %.4g, elastic flange %s, KP strips %d, match distance %.3g mm\n",
                to_string(h.model), h.material.shear_modulus_Pa * 1e-9, h.material.poisson_ratio,
                h.max_touching_contact_angle_rad < 10.0
                    ? (Fmt("%g", h.max_touching_contact_angle_rad * 180.0 / M_PI) + " deg").c_str()
                    : "off (rigid)",
                h.kp_strips, h.match_distance_m * 1e3);
  out << line;
  auto axis = [&](const char* name, const std::vector<double>& v, double s, const char* unit) {
    std::snprintf(line, sizeof line, "  %-12s %4zu values  %.6g .. %.6g %s\n", name, v.size(), v.front() * s,
                  v.back() * s, unit);
    out << line;
  };
  axis("lateral y", g.lateral_m, 1e3, "mm");
  axis("yaw psi", g.yaw_rad, 1e3, "mrad");
  axis("load Q", g.load_N, 1e-3, "kN");
  for (Side s : {Side::Left, Side::Right}) {
    int ok = 0, patches = 0, two = 0;
    for (const LutNode& n : lut.nodes[side_index(s)]) {
      ok += n.status == static_cast<int>(WheelContactStatus::Ok);
      patches += static_cast<int>(n.patches.size());
      two += n.patches.size() >= 2;
    }
    std::snprintf(line, sizeof line, "  %-5s %zu nodes, %d ok, %d patches, %d nodes with 2+ patches\n", to_string(s),
                  lut.nodes[side_index(s)].size(), ok, patches, two);
    out << line;
  }
  std::snprintf(line, sizeof line, "  Conforma %s (commit %s), generated in %.2f s on %d threads\n",
                h.conforma_version.c_str(), h.conforma_commit.c_str(), h.generation_s, h.threads);
  out << line;
}

void PrintPercentiles(std::ostream& out, const char* name, const Percentiles& p, double scale, const char* unit) {
  char line[256];
  std::snprintf(line, sizeof line,
                "  %-18s n=%-5d p50 %-8.3g p90 %-8.3g p95 %-8.3g p99 %-8.3g max %-8.3g %-3s (max at %s y %.3f mm, "
                "yaw %.2f mrad, Q %.1f kN)\n",
                name, p.count, p.p50 * scale, p.p90 * scale, p.p95 * scale, p.p99 * scale, p.max * scale, unit,
                p.worst_side == 0 ? "left" : "right", p.worst_y_m * 1e3, p.worst_yaw_rad * 1e3, p.worst_load_N * 1e-3);
  out << line;
}

}  // namespace

void RegisterLutCommand(CLI::App& app) {
  CLI::App* lut = app.add_subcommand("lut", "contact look-up table: build, info, eval, check");
  lut->require_subcommand(1);

  // build
  {
    struct Build {
      LutArgs args;
      // default grid: the default scenario's pair (contact_lut_grid.hpp, docs/architecture.md "Contact look-up table")
      std::string out = "contact_lut.h5";
      ContactLutGridText grid;
      double match_mm = kDefaultLutMatchDistance_m * 1e3;
      int threads = 0;
    };
    auto b = std::make_shared<Build>();
    CLI::App* sub = lut->add_subcommand("build", "solve the table and write it (HDF5)");
    b->args.add_to(sub);
    sub->add_option("--out", b->out, "output file (.h5)");
    sub->add_option("--y-mm", b->grid.lateral_mm, "lateral shift axis: min:max:step or a comma list [mm]");
    sub->add_option("--yaw-mrad", b->grid.yaw_mrad, "yaw axis: min:max:step or a comma list [mrad]");
    sub->add_option("--load-kN", b->grid.load_kN, "wheel load axis: min:max:step or a comma list [kN]");
    sub->add_option("--match-mm", b->match_mm, "patches farther apart along the rail are different patches [mm]");
    sub->add_option("--threads", b->threads, "OpenMP threads (0: default)");
    sub->callback([b, sub]() {
      const auto geometry = b->args.track.make_geometry();
      ContactLutBuildOptions o;
      o.contact = b->args.options();
      o.grid = ParseContactLutGrid(b->grid);
      o.match_distance_m = b->match_mm * 1e-3;
      RequireThreads(b->threads, "--threads");
      o.threads = b->threads;
      o.wheel_profile = b->args.track.wheel;
      o.rail_profile = b->args.track.rail;
      const TrackArgs& t = b->args.track;
      o.track = "inclination " + (t.inclination.empty() ? std::string("default") : t.inclination) + ", gauge " +
                Fmt("%g", t.gauge_mm) + " mm, r0 " + Fmt("%g", t.nominal_radius_mm) + " mm";
      ProgressReporter progress("lut build", 0.0, "", ProgressModeOf(sub), std::cerr);
      o.on_progress = progress.Function();
      const ContactLut table = BuildContactLut(*geometry, o);
      progress.Finish();
      SaveContactLut(table, b->out);
      const auto bytes = std::filesystem::file_size(b->out);
      char line[256];
      std::snprintf(line, sizeof line, "lut build: %zu nodes per side (%zu in all), %.2f s on %d threads, file %s %.3f MB\n",
                    table.grid.nodes(), 2 * table.grid.nodes(), table.header.generation_s, table.header.threads,
                    b->out.c_str(), bytes / 1e6);
      std::cout << line;
    });
  }
  // info
  {
    auto file = std::make_shared<std::string>();
    CLI::App* sub = lut->add_subcommand("info", "print the header of a table file");
    sub->add_option("file", *file, "table file (.h5)")->required();
    sub->callback([file]() { PrintHeader(std::cout, LoadContactLut(*file)); });
  }
  // eval
  {
    struct Eval {
      LutArgs args;
      std::string file, side = "both";
      double y_mm = 0.0, yaw_mrad = 0.0;
      bool json = false, direct = false;
    };
    auto e = std::make_shared<Eval>();
    CLI::App* sub = lut->add_subcommand("eval", "patches of one pose from the table (track/model options as at build)");
    sub->add_option("file", e->file, "table file (.h5)")->required();
    e->args.add_to(sub);
    sub->add_option("--y-mm", e->y_mm, "lateral shift of the wheelset");
    sub->add_option("--yaw-mrad", e->yaw_mrad, "yaw angle");
    sub->add_option("--side", e->side, "left, right or both")->check(CLI::IsMember({"left", "right", "both"}));
    sub->add_flag("--json", e->json, "machine-readable output");
    sub->add_flag("--direct", e->direct, "also solve the pose directly (SolveWheelContact) for comparison");
    sub->callback([e, sub]() {
      const ContactLut table = LoadContactLut(e->file);
      const auto geometry = e->args.track.make_geometry();
      CheckContactLutGeometry(table, *geometry);
      WheelContactOptions options = e->args.options();
      // no --load-N: the middle of the table's load axis (the shared default, 10 kN, lies outside a default table)
      const bool load_given = sub->count("--load-N") > 0;
      if (!load_given && !table.grid.load_N.empty())
        options.vertical_load_N = 0.5 * (table.grid.load_N.front() + table.grid.load_N.back());
      require_finite(e->y_mm, "--y-mm");
      require_finite(e->yaw_mrad, "--yaw-mrad");
      EquilibriumOptions eo;
      eo.max_touching_contact_angle_rad = options.max_touching_contact_angle_rad;
      const EquilibriumResult eq = geometry->SolveRigidEquilibrium(e->y_mm * 1e-3, e->yaw_mrad * 1e-3, WheelsetPose{}, eo);
      if (eq.status != EquilibriumStatus::Converged)
        throw InputError("no rigid equilibrium at --y-mm " + MessageNumber(e->y_mm));
      const WheelsetVelocity velocity = e->args.contact.rolling_velocity(geometry->setup().nominal_radius_m[0]);
      nlohmann::json out = {{"model", e->args.contact.model}, {"load_N", options.vertical_load_N},
                            {"wheels", nlohmann::json::array()}};
      if (!e->json) {
        std::cout << "conforma lut eval: " << e->file << ", y = " << e->y_mm << " mm, yaw = " << e->yaw_mrad
                  << " mrad, load " << options.vertical_load_N * 1e-3 << " kN"
                  << (load_given ? "" : " (the middle of the table's load axis; --load-N to choose)") << "\n";
        PrintPatchTableHeader(std::cout, "wheel");
      }
      std::vector<WheelContactReport> reports;
      for (Side s : {Side::Left, Side::Right}) {
        if (e->side != "both" && e->side != to_string(s)) continue;
        LutCellInfo info;
        const WheelContactReport r = EvaluateContactLut(table, *geometry, s, eq.pose, velocity, options, &info);
        reports.push_back(r);
        if (e->json) {
          nlohmann::json w = ToJson(r);
          w["lut_single_topology_cell"] = info.single_topology;
          out["wheels"].push_back(w);
        } else {
          for (const PatchReport& p : r.patches) PrintPatchRow(std::cout, std::string(to_string(s)) + "-lut", p);
          PrintWheelStatus(std::cout, r, options.vertical_load_N);
          if (!info.single_topology) std::cout << "   (" << to_string(s) << ": the cell holds a topology change)\n";
        }
        if (e->direct) {
          const WheelContactReport d = SolveWheelContact(*geometry, s, eq.pose, velocity, options);
          if (e->json) out["direct"].push_back(ToJson(d));
          else
            for (const PatchReport& p : d.patches) PrintPatchRow(std::cout, std::string(to_string(s)) + "-dir", p);
        }
      }
      if (e->json) std::cout << out.dump(2) << "\n";
      std::cout.flush();
      ThrowIfIncomplete(reports, options.vertical_load_N);
    });
  }
  // check
  {
    struct Check {
      LutArgs args;
      std::string file;
      ContactLutCheckOptions o;
      std::string creep = "fastsim";
      std::string samples_csv;
      bool json = false;
    };
    auto c = std::make_shared<Check>();
    CLI::App* sub = lut->add_subcommand("check", "LUT against the direct solver at random poses inside the table");
    sub->add_option("file", c->file, "table file (.h5)")->required();
    c->args.add_to(sub);
    sub->add_option("--samples", c->o.samples, "random poses");
    sub->add_option("--creep", c->creep, "the table's creep forces: fastsim (as the direct solve) or polach (closed form)")
        ->check(CLI::IsMember({"fastsim", "polach"}));
    sub->add_option("--seed", c->o.seed, "random seed");
    sub->add_option("--threads", c->o.threads, "OpenMP threads (0: default)");
    sub->add_flag("--json", c->json, "machine-readable output");
    sub->add_option("--samples-csv", c->samples_csv,
                    "write every random pose (side, y, yaw, load, category, per-sample largest errors, the direct "
                    "solve's forces) to this CSV file");
    sub->callback([c, sub]() {
      std::ofstream samples_csv;
      if (!c->samples_csv.empty()) {  // opened first: a bad path fails before the check runs
        samples_csv.open(c->samples_csv);
        if (!samples_csv) throw InputError("--samples-csv: cannot write '" + c->samples_csv + "'");
      }
      const ContactLut table = LoadContactLut(c->file);
      const auto geometry = c->args.track.make_geometry();
      CheckContactLutGeometry(table, *geometry);
      RequireThreads(c->o.threads, "--threads");
      ContactLutCheckOptions o = c->o;
      o.contact = c->args.options();
      o.evaluation.creep_force = ParseLutCreepForce(c->creep);
      o.speed_m_s = c->args.contact.speed_m_s;
      const auto t0 = std::chrono::steady_clock::now();
      ProgressReporter progress("lut check", 0.0, "", ProgressModeOf(sub), std::cerr);
      o.on_progress = progress.Function();
      const ContactLutCheckResult r = CheckContactLut(table, *geometry, o);
      progress.Finish();
      const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      if (samples_csv.is_open()) {
        WriteContactLutCheckSamplesCsv(samples_csv, r);
        if (!samples_csv.flush()) throw InputError("--samples-csv: cannot write '" + c->samples_csv + "'");
      }
      auto pj = [](const Percentiles& p) {
        return nlohmann::json{{"count", p.count}, {"p50", p.p50}, {"p90", p.p90}, {"p95", p.p95}, {"p99", p.p99},
                              {"max", p.max}, {"worst_side", p.worst_side == 0 ? "left" : "right"},
                              {"worst_y_m", p.worst_y_m}, {"worst_yaw_rad", p.worst_yaw_rad},
                              {"worst_load_N", p.worst_load_N}};
      };
      if (c->json) {
        std::cout << nlohmann::json{{"samples", r.samples}, {"single_topology", r.single_topology},
                                    {"single_topology_mismatch", r.single_topology_mismatch},
                                    {"jump_samples", r.jump_samples}, {"jump_same_topology", r.jump_same_topology},
                                    {"jump_within_one_step", r.jump_within_one_step}, {"jump_outside", r.jump_outside},
                                    {"status_mismatch", r.status_mismatch}, {"both_failed", r.both_failed},
                                    {"lut_errors", r.lut_errors},
                                    {"normal_force_rel", pj(r.normal_force_rel)}, {"fx_rel", pj(r.fx_rel)},
                                    {"fy_rel", pj(r.fy_rel)}, {"rail_y_m", pj(r.rail_y_m)},
                                    {"lateral_force_rel", pj(r.lateral_force_rel)}, {"direct_cpu_s", r.direct_cpu_s},
                                    {"lut_cpu_s", r.lut_cpu_s}, {"wall_s", wall}}
                         .dump(2)
                  << "\n";
        return;
      }
      char line[256];
      std::snprintf(line, sizeof line, "lut check: %d samples (seed %llu), %.1f s wall\n", r.samples,
                    static_cast<unsigned long long>(o.seed), wall);
      std::cout << line;
      std::snprintf(line, sizeof line,
                    "  single-topology cells: %d (direct topology differs in %d)\n"
                    "  cells with a jump: %d: same topology %d, direct topology at a cell corner (within one grid step) "
                    "%d, elsewhere %d\n  status differs: %d, both failed: %d, LUT errors: %d\n",
                    r.single_topology, r.single_topology_mismatch, r.jump_samples, r.jump_same_topology,
                    r.jump_within_one_step, r.jump_outside, r.status_mismatch, r.both_failed, r.lut_errors);
      std::cout << line << "  errors away from jumps (per patch; forces relative to Q and mu Q):\n";
      PrintPercentiles(std::cout, "normal force / Q", r.normal_force_rel, 100.0, "%");
      PrintPercentiles(std::cout, "Fx / (mu Q)", r.fx_rel, 100.0, "%");
      PrintPercentiles(std::cout, "Fy / (mu Q)", r.fy_rel, 100.0, "%");
      PrintPercentiles(std::cout, "rail y", r.rail_y_m, 1e3, "mm");
      PrintPercentiles(std::cout, "wheel lateral / Q", r.lateral_force_rel, 100.0, "%");
      std::snprintf(line, sizeof line, "  CPU per evaluation: direct %.3g ms, LUT %.3g ms\n",
                    1e3 * r.direct_cpu_s / r.samples, 1e3 * r.lut_cpu_s / r.samples);
      std::cout << line;
    });
  }
}

}  // namespace conforma::cli
