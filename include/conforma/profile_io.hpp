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
//                non-numeric header line before the data). Values in units of length_unit_m; kind must be given
//                in ProfileReadOptions::kind (command line: --wheel/--rail set it; `profile info --kind`).
// ProfileReadOptions::format overrides the extension. mirror_y / mirror_z are applied to every format after its
// own conversion (a wheel or rail file stored the other way round).
// A curve that folds back in y (measured flange tips, undercut gauge faces) is kept in its file order and
// parametrised by arc length (a note says where); an unordered point cloud is sorted by y.
// Validation shared by every entry point (docs/profiles-and-formats.md §3): the file must be complete (Simpack
// point/spline blocks closed, MiniProf XYPoints count, no truncated last line), the points distinct and spaced at
// most 2 mm on the running surface without reversals, the orientation right (wheel flange, when there is one,
// pointing to +z at negative y; rail head on top), and the points not noisy unless smoothing is asked for.
// Errors: InputError "<file>:<line>: <what>" naming the command-line flag that fixes it where there is one
// (--wheel-mirror, --wheel-z-down, --wheel-smooth-mm, --rail-...). rotate != 0 is refused.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "conforma/profile.hpp"

namespace conforma {

// File format of a profile file.
enum class ProfileFormat {
  Auto,      // from the extension (.prw .prr: Simpack; .whl .ban: MiniProf; .txt .dat .csv: columns)
  Simpack,   // Simpack rail-wheel profile (§2.1)
  MiniProf,  // MiniProf new or old style (§2.2)
  Columns    // plain two columns y z
};
// "auto", "simpack", "miniprof", "columns"; ParseProfileFormat throws InputError for other names.
const char* to_string(ProfileFormat format);
ProfileFormat ParseProfileFormat(const std::string& name);

struct ProfileReadOptions {
  std::optional<ProfileKind> kind;  // required for plain column files; checked against Simpack/MiniProf files
  // Fit of the loaded points (profile.hpp): smoothing and resampling (LoadProfile); function_of_y also makes the
  // readers refuse a curve folding back in y
  ProfileFitOptions fit;
  bool mirror_y = false;         // every format, after its own conversion: y := -y (command line --wheel-mirror)
  bool mirror_z = false;         // every format, after its own conversion: z := -z (command line --wheel-z-down)
  // every format, after the mirroring: z := z + z_shift_m, m, finite (command line --wheel-z-shift-mm): puts a
  // wheel profile's z origin at the taping line (a measured profile whose z = 0 lies elsewhere gets the rolling
  // radius r0 + z wrong; the nominal_radius warning of contact_plausibility.hpp measures the shift)
  double z_shift_m = 0.0;
  double length_unit_m = 1e-3;   // plain column files: file length unit in metres (other formats: must stay 1e-3)
  ProfileFormat format = ProfileFormat::Auto;  // file format; Auto: from the extension
  // Refuse noisy points (profile_checks) unless fit.smoothing_rms_m > 0; false only for tests of the raw reader
  bool check_noise = true;
};

// True when `options` differ from the defaults in a way that only makes sense for a profile file (mirroring,
// units, smoothing, format): built-in profile names refuse them.
bool HasFileReadOptions(const ProfileReadOptions& options);

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
// Points given in memory (Python's profile_from_points), in metres and our convention: ordered and checked as a
// file's points are (docs/profiles-and-formats.md §3; `source`:N in a message is the N-th point, 1-based), then fitted.
// A self-intersecting curve was silently re-sorted by y before (fuzzing, session 25).
Profile ProfileFromCheckedPoints(std::vector<Eigen::Vector2d> points_m, ProfileKind kind, const ProfileFitOptions& fit,
                                 const std::string& source);

// Simpack .prw (wheel) / .prr (rail) file, mm, points spaced spacing_m in arc length. Rails are written with
// z down (Simpack convention); reading the file back with LoadProfile gives the same curve.
void SaveProfileSimpack(const Profile& profile, const std::string& path, double spacing_m = 0.1e-3);
// Comma separated "y_mm,z_mm" with a '#' comment line naming kind and conventions.
void SaveProfileCsv(const Profile& profile, const std::string& path, double spacing_m = 0.1e-3);

}  // namespace conforma
