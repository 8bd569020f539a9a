#pragma once
// Command-line options shared by the subcommands: profiles (built-in names or files), track, material, model.
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "conforma/geometry.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma::cli {

struct TrackArgs {
  std::string wheel = "S1002";     // built-in name or a profile file
  std::string rail = "60E1";       // 60E1 | 54E1 | 50E6 | 50E4 or a profile file
  std::string inclination = "";    // "1:40", "1:20", "0"; default 1:40 for built-in rails, 0 for files
  double gauge_mm = 1435.0, gauge_height_mm = 14.0, flange_back_mm = 1360.0, flange_back_position_mm = -70.0;
  double nominal_radius_mm = 460.0;
  // How a profile file is read (--wheel-mirror, --wheel-z-down, --wheel-units, --wheel-smooth-mm, --wheel-format
  // and the same for --rail); profile_io.hpp.
  struct FileOptions {
    bool mirror = false, z_down = false;  // y := -y, z := -z after the format's own conversion
    double z_shift_mm = 0.0;              // z := z + shift after the mirroring [mm] (--wheel-z-shift-mm)
    std::string units = "mm";             // plain column files: mm or m
    double smooth_mm = 0.0;               // RMS smoothing of noisy points [mm], 0 = interpolate
    std::string format = "auto";          // auto (extension), simpack, miniprof, columns
    ProfileReadOptions read_options() const;  // InputError for a bad unit or smoothing value
  };
  FileOptions wheel_file, rail_file;
  void add_to(CLI::App* app);
  // Throws InputError for an unknown name, unreadable profile or bad inclination.
  std::unique_ptr<WheelsetTrackGeometry> make_geometry() const;
};

struct ContactArgs {
  std::string model = "hertz";
  double load_N = 10e3;           // vertical load per wheel; < 0 = pose given (approach mode)
  double speed_m_s = 2.0;
  double friction = 0.3;
  double shear_modulus_GPa = 82.0, poisson = 0.28;
  int grid = kDefaultFastsimElements;
  double exact_element_mm = WheelContactOptions{}.exact_element_size_m * 1e3;  // --exact-element-mm
  double combine_mm = WheelContactOptions{}.patch_combine_distance_m * 1e3;  // --combine-mm
  std::string penetration = "variable";  // conformal model: variable (KPEC rule) or constant (eps = 0.55)
  std::string load_balance = "total";    // --load-balance: total (pressure + creep forces), pressure, total-consistent (LoadBalance)
  // Slip-dependent friction law (friction_law.hpp, docs/physics-reference.md §7.4): constant (mu = --mu),
  // exponential (paper 002 f1a), piecewise-linear (f1b), static-dynamic (f2); the paper's names are accepted too.
  // --mu is the static value mu(0) of every law; the other parameters only where the law has them.
  std::string friction_law = "constant";
  std::optional<double> mu_dynamic;     // mu_d: piecewise-linear, static-dynamic
  std::optional<double> mu_ratio;       // alpha = mu(infinity) / mu_o, in [0, 1]: exponential
  std::optional<double> slip_decay;     // per unit slip: beta of exponential, alpha of static-dynamic
  std::optional<double> slip_rise;      // per unit slip: beta of static-dynamic
  std::optional<double> critical_slip;  // gamma_c > 0: piecewise-linear
  void add_to(CLI::App* app);
  // Throws InputError naming the option for a bad value or a parameter the chosen friction law does not have.
  WheelContactOptions options() const;
  FrictionLaw friction_law_from_options() const;  // the law of --friction-law and its parameters (validated)
  // Pure rolling at the nominal radius r0 at --speed, no lateral or yaw velocity.
  WheelsetVelocity rolling_velocity(double nominal_radius_m) const {
    return {speed_m_s, 0.0, 0.0, speed_m_s / nominal_radius_m};
  }
};

// Parses "1:40", "1/40", "0", "none" or a decimal angle in radians.
double ParseInclination(const std::string& text);
// "a,b,c" -> {"a", "b", "c"}; "" -> {}; an empty item ("a,,c", "a,") or one given twice is an InputError naming
// `option`: the --models and --sets lists.
std::vector<std::string> SplitCommaList(const std::string& text, const std::string& option);

}  // namespace conforma::cli
