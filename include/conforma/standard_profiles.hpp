#pragma once
// Standard wheel and rail profiles generated from their exact geometric definitions
// (docs/profiles-and-formats.md §1.1 S1002, §1.2 EN 13674 rail heads), in the conventions of profile.hpp.
#include <cmath>
#include <string>

#include "conforma/profile.hpp"

namespace conforma {

// Rail inclination in track (cant of the rail towards the track centre) [rad].
inline double rail_inclination_1in20() { return std::atan(1.0 / 20.0); }
inline double rail_inclination_1in40() { return std::atan(1.0 / 40.0); }

// S1002 wheel (EN 13715 / UIC 510-2) from the piecewise DLR definition, sections A..H (§1.1):
// y = S (taping line at 0, flange back at -70 mm), z = F(S) (positive = larger radius), y in [-70, 60] mm.
Profile MakeS1002(const ProfileFitOptions& options = {});
// The exact F(S) of §1.1 [mm] for S in [-70, 60] mm (section by section, no smoothing of the 1e-4 mm steps).
double S1002Height_mm(double S_mm);

// EN 13674-1 rail sections, by name: R60E1 "60E1" (alias UIC60), R54E1 "54E1", R50E6 "50E6", R50E4 "50E4" (alias
// UIC50; profile_by_name.hpp).
enum class RailSection { R60E1, R54E1, R50E6, R50E4 };
const char* to_string(RailSection section);  // "60E1", "54E1", ...

// Rail head from the EN 13674 arc definitions (§1.2): crown arc, R80/R60 arc, R13 arc (tangent continuous),
// 1:20 head flank down to 30 mm below the top, symmetric. The rail is then canted towards the track centre
// (towards -y) by inclination_rad and shifted so that its highest point is the origin (as MBench_UIC60_v3.prr).
// With inclination 0 the origin is the top of the head on its symmetry axis.
Profile MakeRail(RailSection section, double inclination_rad, const ProfileFitOptions& options = {});

// Writes S1002.prw and, for each rail section X in {60E1, 54E1, 50E6, 50E4}: X.prr (vertical), X_1in40.prr,
// X_1in20.prr into dir (Simpack format, 0.1 mm point spacing). Throws InputError if a file cannot be written.
void WriteStandardProfiles(const std::string& dir);

}  // namespace conforma
