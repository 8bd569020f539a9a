// Wear-law files: the small CSV format described in wear_law.hpp.
#include <cmath>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "conforma/error.hpp"
#include "conforma/wear_law.hpp"

namespace conforma {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string f;
  while (std::getline(ss, f, ',')) out.push_back(trim(f));
  return out;
}

double parse_number(const std::string& text, const std::string& source, int line, const std::string& what) {
  if (text == "inf" || text == "+inf" || text == "Inf") return std::numeric_limits<double>::infinity();
  size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || std::isnan(v))
    throw InputError(source, line, what + " is not a number: '" + text + "'");
  return v;
}

void require_fields(const std::vector<std::string>& f, size_t n, const std::string& source, int line) {
  if (f.size() != n)
    throw InputError(source, line, "'" + f[0] + "' expects " + std::to_string(n - 1) + " value(s), got " +
                                       std::to_string(f.size() - 1));
}

}  // namespace

WearLaw ParseWearLaw(const std::string& text, const std::string& source) {
  WearLaw law;
  law.wear_index = WearIndexLaw{};
  law.archard = ArchardMap{};
  law.archard.name.clear();
  bool have_kind = false;
  std::string name;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const auto hash = raw.find('#');
    const std::string content = trim(hash == std::string::npos ? raw : raw.substr(0, hash));
    if (content.empty()) continue;
    const auto f = split_fields(content);
    const std::string& key = f[0];
    if (key == "kind") {
      require_fields(f, 2, source, line);
      if (have_kind) throw InputError(source, line, "'kind' given twice");
      if (f[1] == "wear_index") law.kind = WearLawKind::WearIndex;
      else if (f[1] == "archard") law.kind = WearLawKind::Archard;
      else throw InputError(source, line, "unknown kind '" + f[1] + "' (expected wear_index or archard)");
      have_kind = true;
      continue;
    }
    if (!have_kind) throw InputError(source, line, "the first entry must be 'kind,wear_index' or 'kind,archard'");
    if (key == "name") {
      // the name may contain commas: take the rest of the line after the first comma
      name = trim(content.substr(content.find(',') + 1));
    } else if (key == "point" && law.kind == WearLawKind::WearIndex) {
      require_fields(f, 3, source, line);
      law.wear_index.points.push_back({parse_number(f[1], source, line, "wear index"),
                                       parse_number(f[2], source, line, "wear rate")});
    } else if (key == "hardness_Pa" && law.kind == WearLawKind::Archard) {
      require_fields(f, 2, source, line);
      law.archard.hardness_Pa = parse_number(f[1], source, line, "hardness_Pa");
    } else if (key == "severe_pressure_ratio" && law.kind == WearLawKind::Archard) {
      require_fields(f, 2, source, line);
      law.archard.severe_pressure_ratio = parse_number(f[1], source, line, "severe_pressure_ratio");
    } else if (key == "bin" && law.kind == WearLawKind::Archard) {
      require_fields(f, 4, source, line);
      law.archard.bins.push_back({parse_number(f[1], source, line, "velocity limit"),
                                  parse_number(f[2], source, line, "k_mild"),
                                  parse_number(f[3], source, line, "k_severe")});
    } else {
      throw InputError(source, line, "unknown entry '" + key + "' for a " + to_string(law.kind) + " law");
    }
  }
  if (!have_kind) throw InputError(source, 0, "empty wear-law file (no 'kind' entry)");
  if (name.empty()) name = source;
  law.wear_index.name = name;
  law.archard.name = name;
  try {
    law.validate();
  } catch (const InputError& e) {
    throw InputError(source, 0, e.what());
  }
  return law;
}

WearLaw LoadWearLaw(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw InputError(path, 0, "cannot open wear-law file");
  std::stringstream buffer;
  buffer << file.rdbuf();
  return ParseWearLaw(buffer.str(), path);
}

std::string FormatWearLaw(const WearLaw& law) {
  std::ostringstream out;
  out << std::setprecision(17);
  out << "# Conforma wear law (format: include/conforma/wear_law.hpp)\n";
  out << "kind," << to_string(law.kind) << "\n";
  out << "name," << law.name() << "\n";
  if (law.kind == WearLawKind::WearIndex) {
    out << "# point,wear_index_N_mm2,wear_rate_ug_m_mm2\n";
    for (const auto& p : law.wear_index.points) out << "point," << p.wear_index_N_mm2 << "," << p.rate_ug_m_mm2 << "\n";
  } else {
    out << "hardness_Pa," << law.archard.hardness_Pa << "\n";
    out << "severe_pressure_ratio," << law.archard.severe_pressure_ratio << "\n";
    out << "# bin,velocity_upper_m_s,k_mild,k_severe\n";
    for (const auto& b : law.archard.bins) {
      out << "bin,";
      if (std::isinf(b.velocity_upper_m_s)) out << "inf";
      else out << b.velocity_upper_m_s;
      out << "," << b.k_mild << "," << b.k_severe << "\n";
    }
  }
  return out.str();
}

}  // namespace conforma
