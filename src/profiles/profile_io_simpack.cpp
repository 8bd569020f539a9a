// Simpack rail-wheel profile files .prw / .prr (docs/profiles-and-formats.md §2.1): reader and writer.
#include <cmath>
#include <algorithm>
#include <fstream>
#include <iomanip>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "conforma/error.hpp"
#include "profile_io_internal.hpp"

namespace conforma {

namespace profile_io {

namespace {

// Removes a '!' or '%' comment that is not inside single quotes ('%' comments out points in CONTACT's
// test files, e.g. circ_r300.prr).
std::string strip_comment(const std::string& line) {
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'') quoted = !quoted;
    else if ((line[i] == '!' || line[i] == '%') && !quoted) return line.substr(0, i);
  }
  return line;
}

struct RawPoint {
  double y, z;
  int line;
};

}  // namespace

ProfilePoints read_simpack(const std::string& path, const ProfileReadOptions& options) {
  const auto lines = read_lines(path);
  const std::string ext = extension_of(path);
  ProfilePoints out;
  out.source = path;
  enum class Block { None, Header, Spline, Points } block = Block::None;
  std::map<std::string, std::pair<double, int>> num;  // numeric keywords with their line
  std::optional<int> header_type;
  int header_type_line = 0;
  std::vector<RawPoint> raw;
  bool saw_points_block = false;
  // line of each *.begin whose *.end has not come yet (0: closed); a truncated file ends inside a block
  int header_open = 0, spline_open = 0, point_open = 0;
  for (size_t li = 0; li < lines.size(); ++li) {
    const int ln = static_cast<int>(li) + 1;
    const std::string t = trim(strip_comment(lines[li]));
    if (t.empty()) continue;
    const std::string tl = lower(t);
    if (tl == "header.begin") { block = Block::Header; header_open = ln; continue; }
    if (tl == "spline.begin") { block = Block::Spline; spline_open = ln; continue; }
    if (tl == "point.begin") { block = Block::Points; saw_points_block = true; point_open = ln; continue; }
    if (tl == "point.end") { block = Block::Spline; point_open = 0; continue; }
    if (tl == "header.end") { block = Block::None; header_open = 0; continue; }
    if (tl == "spline.end") { block = Block::None; spline_open = 0; continue; }
    const auto eq = t.find('=');
    if (block != Block::Points && eq != std::string::npos) {
      const std::string key = lower(trim(t.substr(0, eq)));
      const std::string value = trim(t.substr(eq + 1));
      out.header[key] = value;
      static const char* const kNumeric[] = {"version", "approx.smooth", "point.dist.min", "shift.y", "shift.z",
                                             "rotate", "bound.y.min", "bound.y.max", "bound.z.min", "bound.z.max",
                                             "mirror.y", "mirror.z", "inversion", "units.len.f", "units.ang.f"};
      bool numeric = key == "type";
      for (const char* k : kNumeric) numeric = numeric || key == k;
      if (!numeric) continue;  // file, comment, units names ...: informative only
      double v;
      if (!parse_number(value, v)) throw InputError(path, ln, "non-numeric value '" + value + "' for keyword " + key);
      if (key == "type") {
        if (block == Block::Header) { header_type = static_cast<int>(v); header_type_line = ln; }
        continue;  // spline.type = original data file type: ignored
      }
      num[key] = {v, ln};
      continue;
    }
    if (block == Block::Points || (!saw_points_block && block != Block::Header)) {
      const auto f = split_fields(t);
      double y, z, w;
      if (f.size() < 2 || f.size() > 3)
        throw InputError(path, ln, "expected 'y z [weight]' but found '" + t + "'");
      for (const auto& tok : f)
        if (!parse_number(tok, w)) throw InputError(path, ln, "non-numeric value '" + tok + "'");
      parse_number(f[0], y);
      parse_number(f[1], z);
      raw.push_back({y, z, ln});
      continue;
    }
    throw InputError(path, ln, "unexpected line '" + t + "'");
  }
  for (const auto& [open, name] : {std::pair<int, const char*>{point_open, "point"}, {spline_open, "spline"},
                                    {header_open, "header"}})
    if (open)
      throw InputError(path, static_cast<int>(lines.size()),
                       std::string("the file ends inside the ") + name + ".begin block of line " +
                           std::to_string(open) + " (no " + name + ".end): truncated file?");
  // profile kind: header type (0 rail, 1 wheel) must agree with the extension (another extension: the kind asked
  // for, else the header type)
  const bool known_ext = ext == "prw" || ext == "prr";
  ProfileKind ext_kind = ext == "prw" ? ProfileKind::Wheel : ProfileKind::Rail;
  if (!known_ext) {
    if (options.kind) ext_kind = *options.kind;
    else if (header_type) ext_kind = *header_type == 1 ? ProfileKind::Wheel : ProfileKind::Rail;
    else throw InputError(path, 0, "a Simpack file without header type and without .prw/.prr extension: give the kind");
  }
  if (header_type) {
    if (*header_type != 0 && *header_type != 1)
      throw InputError(path, header_type_line, "header type must be 0 (rail) or 1 (wheel)");
    const ProfileKind k = *header_type == 1 ? ProfileKind::Wheel : ProfileKind::Rail;
    if (k != ext_kind && known_ext)
      throw InputError(path, header_type_line, std::string("header type says ") + to_string(k) +
                                                   " but the extension ." + ext + " means " + to_string(ext_kind));
  }
  out.kind = ext_kind;
  if (options.kind && *options.kind != out.kind)
    throw InputError(path, 0, std::string("expected a ") + to_string(*options.kind) + " profile, file holds a " +
                                  to_string(out.kind) + " profile");
  if (raw.empty()) throw InputError(path, 0, "no profile points found");
  auto get = [&](const char* k, double def) { auto it = num.find(k); return it == num.end() ? def : it->second.first; };
  auto line_of = [&](const char* k) { auto it = num.find(k); return it == num.end() ? 0 : it->second.second; };
  // Processing in CONTACT's order (read_simpack_profile): 1 point.dist.min, 2 shift, 3 rotate, 4 bound.y,
  // 5 bound.z (clip), 7 mirror.y, 8 mirror.z, 10 units, 9 inversion (order is normalised later anyway).
  const double dmin = get("point.dist.min", 0.0);
  if (dmin < 0) throw InputError(path, line_of("point.dist.min"), "point.dist.min must be >= 0");
  if (dmin > 0) {
    std::vector<RawPoint> kept{raw.front()};
    for (size_t i = 1; i < raw.size(); ++i)
      if (std::hypot(raw[i].y - kept.back().y, raw[i].z - kept.back().z) >= dmin) kept.push_back(raw[i]);
    raw.swap(kept);
  }
  const double sy = get("shift.y", 0.0), sz = get("shift.z", 0.0);
  for (auto& r : raw) { r.y += sy; r.z += sz; }
  if (get("rotate", 0.0) != 0.0)
    throw InputError(path, line_of("rotate"), "rotate != 0 is not supported (rotate the profile points instead)");
  const double bymin = get("bound.y.min", 1.0), bymax = get("bound.y.max", 0.0);
  if (bymin < bymax) {
    std::vector<RawPoint> kept;
    for (const auto& r : raw)
      if (r.y >= bymin && r.y <= bymax) kept.push_back(r);
    raw.swap(kept);
  }
  const double bzmin = get("bound.z.min", 1.0), bzmax = get("bound.z.max", 0.0);
  if (bzmin < bzmax)
    for (auto& r : raw) r.z = std::min(std::max(r.z, bzmin), bzmax);
  const bool my = get("mirror.y", 0.0) != 0.0, mz = get("mirror.z", 0.0) != 0.0;
  const double f = get("units.len.f", 1000.0);
  if (!(f > 0)) throw InputError(path, line_of("units.len.f"), "units.len.f must be > 0");
  // Simpack rails have z downwards; wheels z towards the flange tip (= larger radius) as we do.
  const double zsign = out.kind == ProfileKind::Rail ? -1.0 : 1.0;
  for (const auto& r : raw) {
    out.points_m.emplace_back((my ? -r.y : r.y) / f, zsign * (mz ? -r.z : r.z) / f);
    out.lines.push_back(r.line);
  }
  if (get("inversion", 0.0) != 0.0) {
    std::reverse(out.points_m.begin(), out.points_m.end());
    std::reverse(out.lines.begin(), out.lines.end());
  }
  if (out.points_m.empty()) throw InputError(path, 0, "no profile points left after applying bound.y.min/max");
  return out;
}

}  // namespace profile_io

void SaveProfileSimpack(const Profile& profile, const std::string& path, double spacing_m) {
  require_positive(spacing_m, "spacing_m");
  if (profile.empty()) throw InputError(path, 0, "cannot save an empty profile");
  const bool wheel = profile.kind() == ProfileKind::Wheel;
  const std::string ext = profile_io::extension_of(path);
  if (ext != (wheel ? "prw" : "prr"))
    throw InputError(path, 0, std::string("a ") + to_string(profile.kind()) + " profile must be saved as ." + (wheel ? "prw" : "prr"));
  std::ofstream out(path);
  if (!out) throw InputError(path, 0, "cannot open for writing");
  std::string comment = profile.source();
  for (auto& c : comment)
    if (c == '\'' || c == '!') c = ' ';
  out << "! ***        SIMPACK Rail-Wheel Profile         ***\n"
      << "! written by Conforma. " << (wheel ? "Wheel: y towards the field side (flange at negative y), z towards a larger radius."
                                               : "Rail: y towards the field side, z DOWN (Simpack), origin at the rail top.")
      << "\n  header.begin\n    version       =  1\n    type          =  " << (wheel ? 1 : 0)
      << "                       ! 0=rail profile, 1=wheel profile\n  header.end\n  spline.begin\n"
      << "    approx.smooth  = +0.000000000000000e+00\n    comment        = '" << comment << "'\n"
      << "    type           =  0                       ! Original data file type\n"
      << "    point.dist.min = +0.000000000000000e+00\n    shift.y        = +0.000000000000000e+00\n"
      << "    shift.z        = +0.000000000000000e+00\n    rotate         = +0.000000000000000e+00\n"
      << "    bound.y.min    = +1.000000000000000e+00\n    bound.y.max    = +0.000000000000000e+00\n"
      << "    bound.z.min    = +1.000000000000000e+00\n    bound.z.max    = +0.000000000000000e+00\n"
      << "    mirror.y       =  0\n    mirror.z       =  0\n    inversion      =  0\n"
      << "    units.len.f    = +1.000000000000000e+03   ! lengths in mm\n"
      << "    units.ang.f    = +1.000000000000000e+00\n    point.begin\n";
  out << std::scientific << std::setprecision(9);
  const double zsign = wheel ? 1.0 : -1.0;
  for (const auto& q : profile.sample(spacing_m)) out << q.x() * 1e3 << "\t" << zsign * q.y() * 1e3 << "\n";
  out << "    point.end\n  spline.end\n";
  if (!out) throw InputError(path, 0, "write failed");
}

}  // namespace conforma
