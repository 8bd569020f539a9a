#pragma once
// Reading and writing wheel/rail profile files. Every reader converts to the conventions of profile.hpp
// (metres; y towards the field side; rail z up; wheel z towards a larger radius, flange at negative y).
//
// Formats (chosen by the file extension, case-insensitive):
//  .prw / .prr   Simpack rail-wheel profile (docs/profiles-and-formats.md §2.1). Keywords applied in CONTACT's order:
//                point.dist.min, shift.y/z, rotate (refused unless 0), bound.y.*, bound.z.*, mirror.y, mirror.z,
//                units.len.f, inversion. After that a Simpack wheel is in our convention as it stands (flange
//                at negative y, z towards the flange tip); a Simpack rail has z DOWN, so z_ours = -z_file.
//                Profile kind from the header `type` (0 rail, 1 wheel); must agree with the extension.
//  .ban / .whl   MiniProf (§2.2), new style (Key=Value header, blank line, columns per ColumnDef) and old style
//                (MINIPROF / #MINIWHEELPROF header with an "Sd Sh qR" line). Stray '"' are ignored. Units mm.
//                Orientation is taken from the data:
//                  rail : y_ours = -y_file (MiniProf has the track centre on the other side); z is flipped when
//                         the flat z-extreme (the crown) is the minimum, so the crown ends up on top.
//                  wheel: z is flipped if the flange tip (largest z excursion from the median) is a minimum; y is
//                         mirrored if the flange is at the larger-y end. MiniProf wheel data are referenced to the
//                         flange back (y_file = 0); we shift to y_ours = y_file - T, T = WheelDiameterTaperline
//                         header value or 70 mm, and shift z so that z(taping line) = 0.
//  .txt .dat .csv  plain two-column y z (comma, semicolon, tab or space separated; '#' comments; an optional
//                non-numeric header line before the data). Values in units of length_unit_m; mirror_y/mirror_z
//                applied; kind must be given in ProfileReadOptions::kind.
// Errors: InputError "<file>:<line>: <what>" for no points, non-numeric data, self-intersection, and a fold
// (y running backwards by more than 0.05 mm) when options.fit.function_of_y is true. rotate != 0 is refused.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conforma/profile.hpp"

namespace conforma {

struct ProfileReadOptions {
  std::optional<ProfileKind> kind;  // required for plain column files; checked against Simpack/MiniProf files
  // Fit of the loaded points (profile.hpp): smoothing and resampling (LoadProfile); function_of_y also makes the
  // readers refuse a curve folding back in y
  ProfileFitOptions fit;
  bool mirror_y = false;         // plain column files: y := -y
  bool mirror_z = false;         // plain column files: z := -z
  double length_unit_m = 1e-3;   // plain column files: file length unit in metres
};

// Points of a profile file converted to our convention (metres), in curve order from small to large y.
struct ProfilePoints {
  std::string source;                    // file path
  ProfileKind kind = ProfileKind::Rail;
  std::vector<Eigen::Vector2d> points_m;
  std::vector<int> lines;                // 1-based file line of each point
  std::map<std::string, std::string> header;  // MiniProf Key=Value header (old style: Sd, Sh, qR); Simpack keywords
  std::vector<std::string> notes;        // orientation decisions taken from the data
};

ProfilePoints ReadProfilePoints(const std::string& path, const ProfileReadOptions& options = {});
Profile LoadProfile(const std::string& path, const ProfileReadOptions& options = {});

// Simpack .prw (wheel) / .prr (rail) file, mm, points spaced spacing_m in arc length. Rails are written with
// z down (Simpack convention); reading the file back with LoadProfile gives the same curve.
void SaveProfileSimpack(const Profile& profile, const std::string& path, double spacing_m = 0.1e-3);
// Comma separated "y_mm,z_mm" with a '#' comment line naming kind and conventions.
void SaveProfileCsv(const Profile& profile, const std::string& path, double spacing_m = 0.1e-3);

}  // namespace conforma
