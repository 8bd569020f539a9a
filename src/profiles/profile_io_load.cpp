// Profile file dispatch by extension, common ordering/validation of the points, and the CSV writer.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <numeric>
#include <sstream>

#include "conforma/error.hpp"
#include "profile_io_internal.hpp"

namespace conforma {

namespace profile_io {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  return lower(path.substr(dot + 1));
}

std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, "cannot open profile file");
  std::vector<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

bool parse_number(const std::string& token, double& value) {
  if (token.empty()) return false;
  const char* b = token.c_str();
  char* e = nullptr;
  value = std::strtod(b, &e);
  return e == b + token.size() && std::isfinite(value);
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : line) {
    if (c == ' ' || c == '\t' || c == ',' || c == ';') {
      if (!cur.empty()) out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) out.push_back(cur);
  return out;
}

namespace {

double mm(double v_m) { return v_m * 1e3; }

std::string where(const ProfilePoints& p, size_t i) {
  std::ostringstream s;
  s << "(y = " << std::fixed << std::setprecision(3) << mm(p.points_m[i].x()) << " mm, z = " << mm(p.points_m[i].y()) << " mm)";
  return s.str();
}

double path_length(const std::vector<Eigen::Vector2d>& v) {
  double L = 0;
  for (size_t i = 1; i < v.size(); ++i) L += (v[i] - v[i - 1]).norm();
  return L;
}

}  // namespace

void finish_points(ProfilePoints& p, const ProfileFitOptions& fit) {
  if (p.points_m.empty()) throw InputError(p.source, 0, "no profile points found");
  auto& pts = p.points_m;
  auto& lines = p.lines;
  if (pts.size() >= 2 && pts.front().x() > pts.back().x()) {  // curve order from small to large y
    std::reverse(pts.begin(), pts.end());
    std::reverse(lines.begin(), lines.end());
  }
  // A fold is the curve running back in y by more than 0.05 mm. Measured files show undercuts outside the
  // running surface (flange back, rim face, underside of the rail head): tolerated when the backward run is steep
  // (|dz| > 3 |dy| measured from the point of largest y so far) or lies well below the running surface (rail:
  // more than 30 mm below its highest point; wheel: more than 5 mm below the median height, the tread level).
  constexpr double kFoldTol = 0.05e-3, kSteep = 3.0;
  double z_low = -1e300;
  if (!pts.empty()) {
    std::vector<double> zs(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) zs[i] = pts[i].y();
    if (p.kind == ProfileKind::Rail) {
      z_low = *std::max_element(zs.begin(), zs.end()) - 30e-3;
    } else {
      std::nth_element(zs.begin(), zs.begin() + zs.size() / 2, zs.end());
      z_low = zs[zs.size() / 2] - 5e-3;
    }
  }
  if (fit.function_of_y) {
    size_t first_back = 0;
    double run_max = -1e300;
    size_t i_max = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
      if (pts[i].x() < run_max - kFoldTol) {
        const double dy = run_max - pts[i].x(), dz = std::abs(pts[i].y() - pts[i_max].y());
        if (!(dz > kSteep * dy) && pts[i].y() > z_low) { first_back = i; break; }
      }
      if (pts[i].x() >= run_max) { run_max = pts[i].x(); i_max = i; }
    }
    if (first_back) {
      // Either an unordered point cloud (sort it) or an ordered curve that folds back (keep its order: the
      // profile is parametrised by arc length, and the geometry tabulates its longest function-like part).
      std::vector<size_t> idx(pts.size());
      std::iota(idx.begin(), idx.end(), 0);
      std::stable_sort(idx.begin(), idx.end(), [&](size_t a, size_t b) { return pts[a].x() < pts[b].x(); });
      std::vector<Eigen::Vector2d> sorted(pts.size());
      std::vector<int> sorted_lines(pts.size());
      for (size_t i = 0; i < idx.size(); ++i) {
        sorted[i] = pts[idx[i]];
        sorted_lines[i] = lines[idx[i]];
      }
      if (path_length(pts) <= 1.5 * path_length(sorted)) {
        std::ostringstream m;
        m << "line " << lines[first_back] << ": the curve folds back (y decreases by " << std::setprecision(3)
          << mm(run_max - pts[first_back].x()) << " mm " << where(p, first_back)
          << "); kept in file order and parametrised by arc length";
        p.notes.push_back(m.str());
      } else {
        pts.swap(sorted);
        lines.swap(sorted_lines);
        p.notes.push_back("points were not ordered along the curve; sorted by y");
      }
    }
  }
  // drop exact repeats of the previous point (common at the ends of measured files)
  std::vector<Eigen::Vector2d> kept;
  std::vector<int> kept_lines;
  for (size_t i = 0; i < pts.size(); ++i)
    if (kept.empty() || (pts[i] - kept.back()).norm() > 1e-9) {
      kept.push_back(pts[i]);
      kept_lines.push_back(lines[i]);
    }
  if (kept.size() < pts.size())
    p.notes.push_back(std::to_string(pts.size() - kept.size()) + " repeated point(s) dropped");
  pts.swap(kept);
  lines.swap(kept_lines);
  if (pts.size() < 4)
    throw InputError(p.source, lines.empty() ? 0 : lines.back(),
                     "a profile needs at least 4 distinct points, found " + std::to_string(pts.size()));
  if (p.kind == ProfileKind::Wheel && pts.front().x() > -0.060) {
    std::ostringstream m;
    m << "wheel: the profile starts at y = " << std::setprecision(4) << mm(pts.front().x())
      << " mm, not near the flange back at -70 mm; its y origin may not be the taping line";
    p.notes.push_back(m.str());
  }
  if (auto hit = find_self_intersection(pts)) {
    std::ostringstream m;
    m << "profile self-intersects: the segment starting at line " << lines[hit->first] << " " << where(p, hit->first)
      << " crosses the segment starting at line " << lines[hit->second] << " " << where(p, hit->second);
    throw InputError(p.source, lines[hit->second], m.str());
  }
}

}  // namespace profile_io

const char* to_string(ProfileFormat format) {
  switch (format) {
    case ProfileFormat::Auto: return "auto";
    case ProfileFormat::Simpack: return "simpack";
    case ProfileFormat::MiniProf: return "miniprof";
    case ProfileFormat::Columns: return "columns";
  }
  return "?";
}

ProfileFormat ParseProfileFormat(const std::string& name) {
  for (ProfileFormat f : {ProfileFormat::Auto, ProfileFormat::Simpack, ProfileFormat::MiniProf, ProfileFormat::Columns})
    if (profile_io::lower(name) == to_string(f)) return f;
  throw InputError("unknown profile file format '" + name + "' (auto, simpack, miniprof, columns)");
}

bool HasFileReadOptions(const ProfileReadOptions& o) {
  return o.mirror_y || o.mirror_z || o.z_shift_m != 0.0 || o.length_unit_m != 1e-3 || o.format != ProfileFormat::Auto ||
         o.fit.smoothing_rms_m != 0.0;
}

ProfilePoints ReadProfilePoints(const std::string& path, const ProfileReadOptions& options) {
  require_positive(options.length_unit_m, "length_unit_m");
  require_finite(options.z_shift_m, "z_shift_m");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, 0, "is a directory, not a profile file");
  const std::string ext = profile_io::extension_of(path);
  ProfileFormat format = options.format;
  if (format == ProfileFormat::Auto) {
    if (ext == "prw" || ext == "prr") format = ProfileFormat::Simpack;
    else if (ext == "whl" || ext == "ban") format = ProfileFormat::MiniProf;
    else if (ext == "txt" || ext == "dat" || ext == "csv") format = ProfileFormat::Columns;
    else
      throw InputError(path, 0, "unknown profile file type '." + ext +
                                    "' (expected .prw .prr .ban .whl .txt .dat .csv; command line: --wheel-format or "
                                    "--rail-format simpack|miniprof|columns)");
  }
  if (format != ProfileFormat::Columns && options.length_unit_m != 1e-3)
    throw InputError(path, 0, std::string("the length unit is set by the ") + to_string(format) +
                                  " file itself; --wheel-units/--rail-units apply to plain column files only");
  ProfilePoints p;
  if (format == ProfileFormat::Simpack) p = profile_io::read_simpack(path, options);
  else if (format == ProfileFormat::MiniProf) p = profile_io::read_miniprof(path, options);
  else p = profile_io::read_columns(path, options);
  profile_io::check_last_line(path, p.lines);
  if (options.mirror_y || options.mirror_z) {
    for (auto& q : p.points_m) {
      if (options.mirror_y) q.x() = -q.x();
      if (options.mirror_z) q.y() = -q.y();
    }
    p.notes.push_back(std::string("mirrored") + (options.mirror_y ? " in y" : "") +
                      (options.mirror_y && options.mirror_z ? " and" : "") + (options.mirror_z ? " in z" : "") +
                      " as asked");
  }
  if (options.z_shift_m != 0.0) {
    for (auto& q : p.points_m) q.y() += options.z_shift_m;
    p.notes.push_back("z shifted by " + std::to_string(options.z_shift_m * 1e3) + " mm as asked");
  }
  profile_io::finish_points(p, options.fit);
  profile_io::check_points(p, options);
  return p;
}

Profile LoadProfile(const std::string& path, const ProfileReadOptions& options) {
  ProfilePoints p = ReadProfilePoints(path, options);
  ProfileFitOptions fit = options.fit;
  fit.function_of_y = false;  // the points are in validated curve order now
  return Profile::FromPoints(std::move(p.points_m), p.kind, fit, path);
}

Profile ProfileFromCheckedPoints(std::vector<Eigen::Vector2d> points_m, ProfileKind kind, const ProfileFitOptions& fit,
                                 const std::string& source) {
  ProfilePoints p;
  p.source = source;
  p.kind = kind;
  p.points_m = std::move(points_m);
  p.lines.resize(p.points_m.size());
  std::iota(p.lines.begin(), p.lines.end(), 1);
  ProfileReadOptions options;
  options.kind = kind;
  options.fit = fit;
  profile_io::finish_points(p, options.fit);
  profile_io::check_points(p, options);
  ProfileFitOptions ordered = fit;
  ordered.function_of_y = false;  // the points are in validated curve order now (as LoadProfile)
  return Profile::FromPoints(std::move(p.points_m), kind, ordered, source);
}

void SaveProfileCsv(const Profile& profile, const std::string& path, double spacing_m) {
  require_positive(spacing_m, "spacing_m");
  if (profile.empty()) throw InputError(path, 0, "cannot save an empty profile");
  std::ofstream out(path);
  if (!out) throw InputError(path, 0, "cannot open for writing");
  out << "# " << to_string(profile.kind()) << " profile from " << profile.source()
      << "; Conforma convention: y towards the field side, "
      << (profile.kind() == ProfileKind::Wheel ? "z towards a larger wheel radius" : "z up") << "\n";
  out << "y_mm,z_mm\n" << std::setprecision(10);
  for (const auto& q : profile.sample(spacing_m)) out << q.x() * 1e3 << "," << q.y() * 1e3 << "\n";
  if (!out) throw InputError(path, 0, "write failed");
}

}  // namespace conforma
