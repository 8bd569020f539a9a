// conforma profile info FILE|S1002|60E1...: size, reference dimensions; conforma profile write DIR: standard files.
#include <filesystem>
#include <cstdio>
#include <iostream>

#include "commands.hpp"
#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/wheel_dimensions.hpp"

namespace conforma::cli {

void RegisterProfileCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("profile", "profile tools");
  sub->require_subcommand(1);
  auto path = std::make_shared<std::string>();
  auto kind = std::make_shared<std::string>("auto");
  CLI::App* info = sub->add_subcommand("info", "read a profile, report its extent and (wheels) Sd, Sh, qR");
  info->add_option("profile", *path, "profile file, or S1002")->required();
  info->add_option("--kind", *kind, "wheel, rail or auto (from the file)")->check(CLI::IsMember({"wheel", "rail", "auto"}));
  info->callback([path, kind]() {
    Profile p;
    if (*path == "S1002") {
      p = MakeS1002();
    } else {
      ProfileReadOptions o;
      if (*kind == "wheel") o.kind = ProfileKind::Wheel;
      if (*kind == "rail") o.kind = ProfileKind::Rail;
      p = LoadProfile(*path, o);
    }
    std::printf("%s: %s profile, arc length %.3f mm, y from %.3f to %.3f mm\n", path->c_str(), to_string(p.kind()),
                p.length() * 1e3, p.y_min() * 1e3, p.y_max() * 1e3);
    if (p.kind() == ProfileKind::Wheel) {
      const WheelDimensions d = MeasureWheelDimensions(p);
      std::printf("Sd = %.3f mm, Sh = %.3f mm, qR = %.3f mm\n", d.sd_m * 1e3, d.sh_m * 1e3, d.qr_m * 1e3);
    }
  });
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
