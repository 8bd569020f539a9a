#pragma once
// Profiles named by a built-in name or a file: one rule for every entry point (command line --wheel/--rail,
// scenario files, the C API and Python).
//   wheel: "S1002" (MakeS1002);  rails: "60E1" (alias "UIC60"), "54E1", "50E6", "50E4" (alias "UIC50"), uninclined
//   (MakeRail); anything else is a profile file (profile_io.hpp), read with the kind set.
#include <functional>
#include <string>

#include "conforma/profile.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma {

// The built-in rail of `name` (aliases included); false when `name` is no built-in rail.
bool FindBuiltInRail(const std::string& name, RailSection* section);
bool IsBuiltInWheel(const std::string& name);
// "60E1 (UIC60), 54E1, 50E6, 50E4 (UIC50)" for messages and help texts.
const char* BuiltInRailNames();

// `resolve_file` maps a file name to the path to read (e.g. relative to a scenario file); default: as given.
// `what` names the setting in errors ("option --rail", "track.rail", ...). InputError when the name is neither
// built in nor an existing file, or when the file is malformed (profile_io.hpp: the checks shared by every
// entry point). `read` applies to files (its kind is set here); a built-in name with file options (mirroring,
// units, smoothing, format: HasFileReadOptions) is an InputError.
using FileResolver = std::function<std::string(const std::string&)>;
Profile WheelProfileByNameOrFile(const std::string& name_or_file, const std::string& what = "wheel profile",
                                 const FileResolver& resolve_file = {}, const ProfileReadOptions& read = {});
Profile RailProfileByNameOrFile(const std::string& name_or_file, bool* built_in = nullptr,
                                const std::string& what = "rail profile", const FileResolver& resolve_file = {},
                                const ProfileReadOptions& read = {});

}  // namespace conforma
