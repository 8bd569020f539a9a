// conforma profile info FILE|S1002|60E1...: size, reference dimensions; conforma profile write DIR: standard files.
#include <filesystem>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "conforma/error.hpp"
#include "conforma/profile_by_name.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_dimensions.hpp"

namespace conforma::cli {

namespace {

struct InfoArgs {
  std::string path, kind = "auto", units = "mm", format = "auto";
  bool mirror = false, z_down = false;
  double smooth_mm = 0.0;
};

void RunProfileInfo(const InfoArgs& a) {
  Profile p;
  RailSection section;
  ProfileReadOptions o;
  o.mirror_y = a.mirror;
  o.mirror_z = a.z_down;
  o.length_unit_m = a.units == "m" ? 1.0 : 1e-3;
  if (!(std::isfinite(a.smooth_mm) && a.smooth_mm >= 0 && a.smooth_mm <= 1.0))
    throw InputError("option --smooth-mm: must be between 0 and 1 mm (the noise level of the points)");
  o.fit.smoothing_rms_m = a.smooth_mm * 1e-3;
  o.format = ParseProfileFormat(a.format);
  if (IsBuiltInWheel(a.path) || FindBuiltInRail(a.path, &section)) {  // built-in names (rails uninclined)
    const bool wheel = IsBuiltInWheel(a.path);
    if (a.kind != "auto" && (a.kind == "wheel") != wheel)
      throw InputError("profile info: " + a.path + " is a built-in " + (wheel ? "wheel" : "rail") + " profile");
    p = wheel ? WheelProfileByNameOrFile(a.path, "profile", {}, o) : RailProfileByNameOrFile(a.path, nullptr, "profile", {}, o);
  } else {
    if (a.kind == "wheel") o.kind = ProfileKind::Wheel;
    if (a.kind == "rail") o.kind = ProfileKind::Rail;
    for (const std::string& note : ReadProfilePoints(a.path, o).notes) std::printf("note: %s\n", note.c_str());
    p = LoadProfile(a.path, o);
  }
  std::printf("%s: %s profile, arc length %.3f mm, y from %.3f to %.3f mm\n", a.path.c_str(), to_string(p.kind()),
              p.length() * 1e3, p.y_min() * 1e3, p.y_max() * 1e3);
  if (p.kind() == ProfileKind::Wheel) {
    const WheelDimensions d = MeasureWheelDimensions(p);
    std::printf("Sd = %.3f mm, Sh = %.3f mm, qR = %.3f mm\n", d.sd_m * 1e3, d.sh_m * 1e3, d.qr_m * 1e3);
  }
}

}  // namespace

void RegisterProfileCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("profile", "profile tools");
  sub->require_subcommand(1);
  auto args = std::make_shared<InfoArgs>();
  CLI::App* info = sub->add_subcommand("info", "read a profile, report its extent and (wheels) Sd, Sh, qR");
  info->add_option("profile", args->path, std::string("profile file, S1002 or a built-in rail (") + BuiltInRailNames() + ")")
      ->required();
  info->add_option("--kind", args->kind, "wheel, rail or auto (from the file; plain column files need wheel or rail)")
      ->check(CLI::IsMember({"wheel", "rail", "auto"}));
  info->add_flag("--mirror", args->mirror, "file stored mirrored in y: y := -y");
  info->add_flag("--z-down", args->z_down, "file with z pointing the other way: z := -z");
  info->add_option("--units", args->units, "plain column file: length unit")->check(CLI::IsMember({"mm", "m"}));
  info->add_option("--smooth-mm", args->smooth_mm, "smooth noisy points: RMS distance of the fit to the points [mm]");
  info->add_option("--format", args->format, "file format instead of the extension's")
      ->check(CLI::IsMember({"auto", "simpack", "miniprof", "columns"}));
  info->callback([args]() { RunProfileInfo(*args); });
  auto dir = std::make_shared<std::string>("profiles");
  CLI::App* write = sub->add_subcommand("write", "write the standard profiles (S1002, 60E1, 54E1, 50E6, 50E4)");
  write->add_option("dir", *dir, "output folder");
  write->callback([dir]() {
    std::error_code ec;
    std::filesystem::create_directories(*dir, ec);
    if (ec) throw InputError("profile write: cannot create folder '" + *dir + "': " + ec.message());
    WriteStandardProfiles(*dir);
    std::cout << "standard profiles written to " << *dir << "\n";
  });
}

}  // namespace conforma::cli
