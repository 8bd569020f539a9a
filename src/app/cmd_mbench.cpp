// conforma mbench: the Manchester benchmark (left wheel, 21 cases) against CONTACT, per model.
#include <cmath>
#include <cstdio>
#include <iostream>

#include "cli_setup.hpp"
#include "commands.hpp"
#include "conforma/error.hpp"
#include "progress.hpp"
#include "conforma/validation/validation_manchester.hpp"

namespace conforma::cli {

void RegisterMbenchCommand(CLI::App& app) {
  auto models = std::make_shared<std::string>("hertz,kp,kpec,conformal");
  auto data = std::make_shared<std::string>();
  auto kinematics = std::make_shared<bool>(false);
  auto origin = std::make_shared<std::string>("ours");
  auto spin_centre = std::make_shared<bool>(false);
  auto local_flex = std::make_shared<bool>(false);
  auto load_balance = std::make_shared<std::string>("total");
  CLI::App* sub = app.add_subcommand("mbench", "Manchester benchmark A-2.2 (left wheel) against CONTACT");
  sub->add_option("--models", *models, "comma-separated models");
  sub->add_option("--data", *data, kDataHelp);
  sub->add_flag("--kinematic-creepages", *kinematics, "creepages from the kinematics instead of the file's");
  sub->add_option("--creepage-origin", *origin,
                  "where the file's creepages apply: ours (at our contact reference point, default) or contact (moved "
                  "from CONTACT's reference point y_cp to ours, xi' = xi + phi (y_cp,ours - y_cp,CONTACT))")
      ->check(CLI::IsMember({"ours", "contact"}));
  AddKpFastsimFlags(sub, spin_centre.get(), local_flex.get());
  sub->add_option("--load-balance", *load_balance,
                  "load control: total (default), pressure or total-consistent (docs/physics-reference.md §3.6.1)")
      ->check(CLI::IsMember({"total", "pressure", "total-consistent"}));
  sub->callback([models, data, kinematics, origin, spin_centre, local_flex, load_balance, sub]() {
    const std::vector<std::string> names = SplitCommaList(*models, "--models");  // (an empty list: exit 0, nothing)
    if (names.empty()) throw InputError("option --models: no contact model given");
    for (const std::string& name : names) ParseContactModel(name);  // every name before the first run
    for (const std::string& name : names) {
      ManchesterOptions o;
      o.model = ParseContactModel(name);
      o.creepages_from_file = !*kinematics;
      o.kp_spin_about_patch_centre = *spin_centre;
      o.kp_local_flexibilities = *local_flex;
      o.load_balance = ParseLoadBalance(*load_balance);
      o.creepage_origin = *origin == "contact" ? ManchesterCreepageOrigin::ContactReferencePoint
                                               : ManchesterCreepageOrigin::OurReferencePoint;
      ProgressReporter progress("mbench " + name, 0.0, "", ProgressModeOf(sub), std::cerr);
      o.on_progress = progress.Function();
      const auto rows = RunManchesterA22(DataDirOr(*data), o);
      progress.Finish();
      std::printf("\nmodel %s (errors vs CONTACT: relative for Fn, pmax, area; absolute N for Fx, Fs)\n", name.c_str());
      std::printf("case  y_ws  n  y_cp[mm] (ref)    Fn[N]   dFn    pmax (ref)    dpmax   area (ref)   darea"
                  "    Fx (ref)      dFx     Fs (ref)      dFs\n");
      double worst_p = 0.0, worst_a = 0.0, worst_fn = 0.0;
      int fx_ok = 0, fs_ok = 0, both_ok = 0;
      for (const auto& r : rows) {
        const auto& c = r.reference;
        std::printf("%3d %5.1f %2d %7.3f (%6.3f) %7.0f %+6.2f%% %6.1f (%6.1f) %+6.1f%% %6.2f (%6.2f) %+6.1f%% %7.0f (%6.0f) %+6.0f %7.0f (%6.0f) %+6.0f\n",
                    c.id, c.y_ws_mm, r.patches, r.y_cp_mm, c.y_cp_rail_mm, r.fn_N, 100 * r.err_fn, r.pmax_MPa,
                    c.p_max_MPa, 100 * r.err_pmax, r.area_mm2, c.area_mm2, 100 * r.err_area, r.fx_N, c.fx_N, r.err_fx_N,
                    r.fs_N, c.fs_N, r.err_fs_N);
        if (c.id >= 2) worst_p = std::max(worst_p, std::fabs(r.err_pmax));
        worst_a = std::max(worst_a, std::fabs(r.err_area));
        worst_fn = std::max(worst_fn, std::fabs(r.err_fn));
        const bool ok_x = std::fabs(r.err_fx_N) <= std::max(150.0, 0.2 * std::fabs(c.fx_N));
        const bool ok_s = std::fabs(r.err_fs_N) <= std::max(150.0, 0.2 * std::fabs(c.fs_N));
        fx_ok += ok_x, fs_ok += ok_s, both_ok += ok_x && ok_s;
      }
      std::printf("summary %s: max |dFn| %.2f%%, max |dpmax| (cases 2-21) %.1f%%, y=0 dpmax %+.1f%%, max |darea| %.1f%%, "
                  "Fx and Fs within 20%% or 150 N: %d/%zu cases (Fx %d, Fs %d)\n",
                  name.c_str(), 100 * worst_fn, 100 * worst_p, rows.empty() ? 0.0 : 100 * rows[0].err_pmax, 100 * worst_a,
                  both_ok, rows.size(), fx_ok, fs_ok);
      std::fflush(stdout);  // this model's table before the next model's progress on stderr (one log for both)
    }
  });
}

}  // namespace conforma::cli
