#pragma once
// Unknown keys in the YAML input files are errors, not silently ignored: the scenario reader (scenario.cpp) and the
// roller-rig scenario reader (roller_rig_plan.cpp) check every map against the keys they read.
#include <yaml-cpp/yaml.h>

#include <set>
#include <string>

namespace conforma {

// InputError "<source>: <where>: unknown key '<key>'" for the first key of `map` not in `allowed`, and
// "<source>: <where>: expected a map" when `map` is not a map.
void CheckYamlKeys(const YAML::Node& map, const std::string& source, const std::string& where,
                   const std::set<std::string>& allowed);

}  // namespace conforma
