// Plain two-column profile files (.txt .dat .csv): "y z" per line, separated by commas, semicolons, tabs or
// spaces; '#' starts a comment; non-numeric lines before the first data line are header lines.
#include <algorithm>
#include <regex>
#include <sstream>

#include "conforma/error.hpp"
#include "profile_io_internal.hpp"

namespace conforma {

namespace profile_io {

namespace {
// "-7,00 9,51" or "-7,00;9,51": two tokens separated by whitespace or a semicolon, each a number once its one comma
// is a point (fuzzing, sessions 24-25: such a file was read as four columns, y and z taken from the integer parts)
bool DecimalCommas(std::string line) {
  std::replace(line.begin(), line.end(), ';', ' ');
  std::istringstream in(line);
  std::string token;
  int count = 0;
  while (in >> token) {
    if (std::count(token.begin(), token.end(), ',') != 1) return false;
    std::replace(token.begin(), token.end(), ',', '.');
    double v;
    if (!parse_number(token, v)) return false;
    ++count;
  }
  return count == 2;
}
// A token written as a decimal number ("-1.5", "1e400", 400 digits) whether or not it fits a double.
bool NumberShaped(const std::string& token) {
  static const std::regex number(R"([+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)");
  return std::regex_match(token, number);
}
}  // namespace

ProfilePoints read_columns(const std::string& path, const ProfileReadOptions& options) {
  if (!options.kind)
    throw InputError(path, 0,
                     "plain column profile files do not say wheel or rail: give the kind (command line: --wheel FILE "
                     "or --rail FILE, `profile info --kind wheel|rail`; Python/C++: ProfileReadOptions::kind)");
  const auto lines = read_lines(path);
  ProfilePoints out;
  out.source = path;
  out.kind = *options.kind;
  const double u = options.length_unit_m;
  const double sy = u, sz = u;  // mirror_y / mirror_z: applied by ReadProfilePoints for every format
  bool in_data = false;
  for (size_t li = 0; li < lines.size(); ++li) {
    const int ln = static_cast<int>(li) + 1;
    std::string t = lines[li];
    if (li == 0 && t.rfind("\xEF\xBB\xBF", 0) == 0) t = t.substr(3);  // a UTF-8 byte order mark (dropped the point)
    if (const auto h = t.find('#'); h != std::string::npos) t = t.substr(0, h);
    t = trim(t);
    if (t.empty()) continue;
    const auto f = split_fields(t);
    double y, z;
    const bool ok_y = parse_number(f[0], y);
    if (!in_data && !ok_y && NumberShaped(f[0]))  // (1e400 on the first line was dropped as a header line)
      throw InputError(path, ln, "'" + f[0] + "' is not a finite number");
    if (!in_data && !ok_y) {  // header line (e.g. "y_mm,z_mm")
      out.header["header." + std::to_string(ln)] = t;
      continue;
    }
    in_data = true;
    if (!ok_y) throw InputError(path, ln, "non-numeric value '" + f[0] + "'");
    if (f.size() < 2) throw InputError(path, ln, "expected two columns 'y z', found '" + t + "'");
    if (!parse_number(f[1], z)) throw InputError(path, ln, "non-numeric value '" + f[1] + "'");
    if (f.size() == 4 && DecimalCommas(t))
      throw InputError(path, ln,
                       "'" + t + "' reads as four numbers: decimal commas? (use a decimal point; commas, semicolons, "
                       "tabs and spaces all separate columns)");
    out.points_m.emplace_back(sy * y, sz * z);
    out.lines.push_back(ln);
  }
  if (out.points_m.empty()) throw InputError(path, 0, "no profile points found");
  return out;
}

}  // namespace profile_io

}  // namespace conforma
