// Profiles by built-in name or file (profile_by_name.hpp).
#include "conforma/profile_by_name.hpp"

#include <filesystem>
#include <map>

#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"

namespace conforma {

bool FindBuiltInRail(const std::string& name, RailSection* section) {
  static const std::map<std::string, RailSection> kRails = {{"60E1", RailSection::R60E1}, {"UIC60", RailSection::R60E1},
                                                            {"54E1", RailSection::R54E1}, {"50E6", RailSection::R50E6},
                                                            {"50E4", RailSection::R50E4}, {"UIC50", RailSection::R50E4}};
  const auto it = kRails.find(name);
  if (it == kRails.end()) return false;
  *section = it->second;
  return true;
}

bool IsBuiltInWheel(const std::string& name) { return name == "S1002"; }

const char* BuiltInRailNames() { return "60E1 (UIC60), 54E1, 50E6, 50E4 (UIC50)"; }

namespace {
void RefuseFileOptions(const std::string& name, const std::string& what, const ProfileReadOptions& read) {
  if (HasFileReadOptions(read))
    throw InputError(what + ": '" + name + "' is a built-in profile; mirroring, units, smoothing and format options " +
                     "apply to profile files only");
}

Profile ProfileFile(const std::string& name, ProfileKind kind, const std::string& what, const std::string& built_in,
                    const FileResolver& resolve_file, const ProfileReadOptions& read) {
  const std::string path = resolve_file ? resolve_file(name) : name;
  std::error_code ec;  // (a 5000-character name threw "File name too long" as an internal error: fuzzing, session 25)
  if (!std::filesystem::exists(path, ec))
    throw InputError(what + ": '" + (name.size() > 200 ? name.substr(0, 200) + "...'" : name + "'") + " is neither " +
                     built_in + " nor a file" + (ec ? " (" + ec.message() + ")" : std::string()) +
                     (path != name && path.size() <= 200 ? " (looked for " + path + ")" : std::string()));
  ProfileReadOptions o = read;
  o.kind = kind;
  return LoadProfile(path, o);
}
}  // namespace

Profile WheelProfileByNameOrFile(const std::string& name_or_file, const std::string& what,
                                 const FileResolver& resolve_file, const ProfileReadOptions& read) {
  if (IsBuiltInWheel(name_or_file)) {
    RefuseFileOptions(name_or_file, what, read);
    return MakeS1002();
  }
  return ProfileFile(name_or_file, ProfileKind::Wheel, what, "the built-in wheel S1002", resolve_file, read);
}

Profile RailProfileByNameOrFile(const std::string& name_or_file, bool* built_in, const std::string& what,
                                const FileResolver& resolve_file, const ProfileReadOptions& read) {
  RailSection section;
  const bool named = FindBuiltInRail(name_or_file, &section);
  if (built_in != nullptr) *built_in = named;
  if (named) {
    RefuseFileOptions(name_or_file, what, read);
    return MakeRail(section, 0.0);
  }
  return ProfileFile(name_or_file, ProfileKind::Rail, what,
                     std::string("a built-in rail (") + BuiltInRailNames() + ")", resolve_file, read);
}

}  // namespace conforma
