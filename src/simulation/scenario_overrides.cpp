// Reading a scenario file, with the command line's overrides (`--set key.path=value`, scenario.hpp LoadScenario):
// the file's YAML with nodes replaced before it is read, so that a study can vary one key without a copy of the file.
#include <yaml-cpp/yaml.h>

#include <fstream>
#include <sstream>

#include "conforma/error.hpp"
#include "conforma/scenario.hpp"

namespace conforma {

namespace {

// The file's YAML with every override applied; `described` gets " (with --set a=b, ...)".
std::string OverriddenYaml(const std::string& path, const std::string& text, const std::vector<std::string>& overrides,
                           std::string* described) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path + ": YAML: " + e.what());
  }
  if (!root.IsMap()) throw InputError(path + ": the scenario is not a YAML map");
  for (const std::string& item : overrides) {
    const auto eq = item.find('=');
    const std::string what = "--set '" + item + "'";
    if (eq == std::string::npos || eq == 0) throw InputError(what + ": expected KEY=VALUE, KEY a dotted path");
    const std::string key = item.substr(0, eq), value_text = item.substr(eq + 1);
    if (value_text.empty()) throw InputError(what + ": the value is empty");
    YAML::Node value;
    try {
      value = YAML::Load(value_text);
    } catch (const YAML::Exception& e) {
      throw InputError(what + ": the value is not YAML: " + e.what());
    }
    std::vector<std::string> parts;
    std::stringstream split(key);
    for (std::string part; std::getline(split, part, '.');) {
      if (part.empty()) throw InputError(what + ": empty part in the key '" + key + "'");
      parts.push_back(part);
    }
    if (key.back() == '.') throw InputError(what + ": empty part in the key '" + key + "'");
    YAML::Node node;
    node.reset(root);
    std::string reached;
    for (size_t i = 0; i + 1 < parts.size(); ++i) {
      reached += (i ? "." : "") + parts[i];
      if (!node[parts[i]]) node[parts[i]] = YAML::Node(YAML::NodeType::Map);
      YAML::Node child = node[parts[i]];
      if (!child.IsMap()) throw InputError(what + ": '" + reached + "' is not a map in " + path);
      node.reset(child);
    }
    node[parts.back()] = value;
    *described += (described->empty() ? " (with --set " : ", --set ") + item;
  }
  if (!described->empty()) *described += ")";
  YAML::Emitter out;
  out << root;
  return out.c_str();
}

}  // namespace

Scenario LoadScenario(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open scenario file");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string described;  // the file's own text when nothing is overridden
  const std::string text = overrides.empty() ? ss.str() : OverriddenYaml(path, ss.str(), overrides, &described);
  std::string dir = ".";
  const auto slash = path.find_last_of('/');
  if (slash != std::string::npos) dir = path.substr(0, slash);
  if (dir.empty()) dir = "/";
  return ParseScenario(text, path + described, dir);
}

}  // namespace conforma
