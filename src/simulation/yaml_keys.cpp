// Unknown YAML keys as input errors (yaml_keys.hpp).
#include "conforma/yaml_keys.hpp"

#include "conforma/error.hpp"

namespace conforma {

void CheckYamlKeys(const YAML::Node& map, const std::string& source, const std::string& where,
                   const std::set<std::string>& allowed) {
  if (!map.IsMap()) throw InputError(source + ": " + where + ": expected a map");
  std::set<std::string> seen;
  for (const auto& kv : map) {
    const std::string key = kv.first.as<std::string>();
    if (!allowed.count(key)) throw InputError(source + ": " + where + ": unknown key '" + key + "'");
    // a key given twice: YAML reads the first value only, the later one would be silently ignored
    if (!seen.insert(key).second)
      throw InputError(source + ": " + where + ": key '" + key + "' is given twice (line " +
                       std::to_string(kv.first.Mark().line + 1) + ")");
  }
}

}  // namespace conforma
