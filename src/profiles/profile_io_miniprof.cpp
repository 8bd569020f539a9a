// MiniProf .ban (rail) / .whl (wheel) files, new style (Key=Value header, ColumnDef) and old style
// (MINIPROF / #MINIWHEELPROF header with an "Sd Sh qR (Sd/Sh/qR)" line); docs/profiles-and-formats.md §2.2.
// Values are in mm. Orientation is decided from the data (see profile_io.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "conforma/error.hpp"
#include "profile_io_internal.hpp"

namespace conforma {

namespace profile_io {

namespace {

// |dz/dy| of the chord through the points about 1 mm before and after point i along the curve.
double local_slope(const std::vector<Eigen::Vector2d>& p, size_t i) {
  size_t a = i, b = i;
  while (a > 0 && (p[i] - p[a]).norm() < 1.0) --a;
  while (b + 1 < p.size() && (p[i] - p[b]).norm() < 1.0) ++b;
  const Eigen::Vector2d d = p[b] - p[a];
  return std::abs(d.y()) / std::max(std::abs(d.x()), 1e-12);
}

constexpr double kMiniProfFlangeBackTolerance_mm = 10.0;

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

}  // namespace

ProfilePoints read_miniprof(const std::string& path, const ProfileReadOptions& options) {
  const auto lines = read_lines(path);
  ProfilePoints out;
  out.source = path;
  const std::string ext = extension_of(path);
  out.kind = ext == "whl" ? ProfileKind::Wheel : ProfileKind::Rail;
  if (ext != "whl" && ext != "ban") {
    if (!options.kind) throw InputError(path, 0, "a MiniProf file without .whl/.ban extension: give the kind");
    out.kind = *options.kind;
  }
  if (options.kind && *options.kind != out.kind)
    throw InputError(path, 0, std::string("expected a ") + to_string(*options.kind) + " profile, a ." +
                                  extension_of(path) + " file holds a " + to_string(out.kind) + " profile");
  bool old_style = false, in_data = false, first = true;
  size_t ix = 0, iy = 1;  // column indices of X (lateral) and Y (vertical)
  std::vector<Eigen::Vector2d> mm;  // file coordinates [mm]
  std::string prev_header_line;
  for (size_t li = 0; li < lines.size(); ++li) {
    const int ln = static_cast<int>(li) + 1;
    std::string t = lines[li];
    t.erase(std::remove(t.begin(), t.end(), '"'), t.end());  // stray quotes (MBench_UIC60_v3.ban)
    t = trim(t);
    if (first && !t.empty()) {
      first = false;
      const std::string u = lower(t);
      old_style = u.rfind("miniprof", 0) == 0 || u.rfind("#miniwheelprof", 0) == 0;
    }
    if (!in_data) {
      if (old_style) {
        if (t.find("(Sd/Sh/qR)") != std::string::npos) {
          std::string nums = trim(t.substr(0, t.find("(Sd/Sh/qR)")));
          if (nums.empty()) nums = prev_header_line;
          const auto f = split_fields(nums);
          double v[3];
          if (f.size() == 3 && parse_number(f[0], v[0]) && parse_number(f[1], v[1]) && parse_number(f[2], v[2])) {
            out.header["Sd"] = f[0];
            out.header["Sh"] = f[1];
            out.header["qR"] = f[2];
          }
        }
        if (!t.empty()) prev_header_line = t;
        if (t.empty() && ln > 1) in_data = true;  // old style: header ends at the first blank line
        continue;
      }
      if (t.empty()) continue;
      const auto eq = t.find('=');
      if (eq != std::string::npos) {
        const std::string key = trim(t.substr(0, eq)), value = trim(t.substr(eq + 1));
        out.header[key] = value;
        if (lower(key) == "columndef") {
          std::vector<std::string> cols;
          std::stringstream ss(value);
          std::string c;
          while (std::getline(ss, c, ',')) cols.push_back(lower(trim(c)));
          const auto fx = std::find(cols.begin(), cols.end(), "x"), fy = std::find(cols.begin(), cols.end(), "y");
          if (fx == cols.end() || fy == cols.end())
            throw InputError(path, ln, "ColumnDef '" + value + "' has no X and Y columns");
          ix = fx - cols.begin();
          iy = fy - cols.begin();
        }
        continue;
      }
      double v;
      const auto f = split_fields(t);
      if (f.empty() || !parse_number(f[0], v)) continue;  // free header text
      in_data = true;
    }
    if (t.empty()) continue;
    const auto f = split_fields(t);
    if (f.size() <= std::max(ix, iy))
      throw InputError(path, ln, "expected at least " + std::to_string(std::max(ix, iy) + 1) + " columns, found '" + t + "'");
    double x, y;
    if (!parse_number(f[ix], x)) throw InputError(path, ln, "non-numeric value '" + f[ix] + "'");
    if (!parse_number(f[iy], y)) throw InputError(path, ln, "non-numeric value '" + f[iy] + "'");
    mm.emplace_back(x, y);
    out.lines.push_back(ln);
  }
  out.header["format"] = old_style ? "MiniProf old style" : "MiniProf new style";
  // New style: XYPoints gives the number of data rows; fewer rows means a truncated file (more: an edited file, noted).
  if (auto it = out.header.find("XYPoints"); it != out.header.end()) {
    double count;
    if (!parse_number(it->second, count) || !(count >= 1) || count != std::floor(count))
      throw InputError(path, 0, "XYPoints=" + it->second + " is not a number of data rows (a whole number >= 1)");
    if (static_cast<double>(mm.size()) < count)
      throw InputError(path, out.lines.empty() ? 0 : out.lines.back(),
                       "XYPoints=" + it->second + " but the file has only " + std::to_string(mm.size()) +
                           " data rows: truncated file?");
    if (static_cast<double>(mm.size()) > count)
      out.notes.push_back("XYPoints=" + it->second + " but the file has " + std::to_string(mm.size()) + " data rows");
  }
  if (mm.size() < 4) throw InputError(path, 0, "no profile points found (" + std::to_string(mm.size()) + " data rows)");
  std::vector<double> zs(mm.size()), ys(mm.size());
  for (size_t i = 0; i < mm.size(); ++i) { ys[i] = mm[i].x(); zs[i] = mm[i].y(); }
  const size_t imax = std::max_element(zs.begin(), zs.end()) - zs.begin();
  const size_t imin = std::min_element(zs.begin(), zs.end()) - zs.begin();
  double sy = 1.0, sz = 1.0, y_shift = 0.0;
  if (out.kind == ProfileKind::Rail) {
    sy = -1.0;  // MiniProf rails have the track centre at +y
    out.notes.push_back("rail: y mirrored (MiniProf convention)");
    if (local_slope(mm, imin) < local_slope(mm, imax)) {
      sz = -1.0;
      out.notes.push_back("rail: z mirrored (the flat crown was the z minimum)");
    }
  } else {
    // The flange tip is a flat z-extreme; the other extreme is usually at the end of a steep face (rim face,
    // flange back). If both or neither are flat, the extreme farther from the median (tread level) is the tip.
    const double zm = median(zs);
    const bool flat_max = local_slope(mm, imax) < 1.0, flat_min = local_slope(mm, imin) < 1.0;
    const bool tip_is_min = flat_max != flat_min ? flat_min : zm - zs[imin] > zs[imax] - zm;
    const size_t itip = tip_is_min ? imin : imax;
    if (tip_is_min) {
      sz = -1.0;
      out.notes.push_back("wheel: z mirrored (the flange tip was the z minimum)");
    }
    if (ys[itip] > median(ys)) {
      sy = -1.0;
      out.notes.push_back("wheel: y mirrored (the flange was at the large-y end)");
    }
    double taping = 70.0;  // MiniProf wheels: flange back at y = 0, taping line 70 mm from it
    auto it = out.header.find("WheelDiameterTaperline");
    if (it != out.header.end()) {
      double v;
      if (!parse_number(it->second, v) || !(v > 0 && v < 200))
        throw InputError(path, 0, "WheelDiameterTaperline=" + it->second +
                                      " is not a taping-line distance from the flange back (0-200 mm)");
      taping = v;
    }
    y_shift = -taping;
    // MiniProf wheels start at the flange back, X = 0 (the measured files: -0.24 ... 1.6 mm). A profile whose
    // flange-back end lies elsewhere is in other coordinates (fuzzing, session 25: S1002 with the taping line at
    // X = 0 put the wheel 70 mm off and solved a contact on the flange, exit 0).
    double back = sy * mm.front().x();
    for (const auto& q : mm) back = std::min(back, sy * q.x());
    if (std::abs(back) > kMiniProfFlangeBackTolerance_mm) {
      std::ostringstream m;
      m << "MiniProf wheel: the profile's flange-back end lies at X = " << sy * back
        << " mm, but MiniProf wheels have the flange back at X = 0 (the taping line " << taping
        << " mm from it, WheelDiameterTaperline); the file is in other coordinates (a profile with the taping line "
           "at y = 0: read it as plain columns, --wheel-format columns)";
      throw InputError(path, 0, m.str());
    }
    std::ostringstream m;
    m << "wheel: y shifted by " << -taping << " mm (flange back at y_file = 0, taping line at y = 0)";
    out.notes.push_back(m.str());
  }
  for (const auto& q : mm) out.points_m.emplace_back((sy * q.x() + y_shift) * 1e-3, sz * q.y() * 1e-3);
  if (out.kind == ProfileKind::Wheel) {
    // z relative to the taping line point: z(0) = 0 (interpolated on the first tread segment crossing y = 0)
    for (size_t i = 0; i + 1 < out.points_m.size(); ++i) {
      const auto &a = out.points_m[i], &b = out.points_m[i + 1];
      if ((a.x() <= 0) != (b.x() <= 0) && std::abs(b.x() - a.x()) > 1e-9) {
        const double z0 = a.y() + (b.y() - a.y()) * (0 - a.x()) / (b.x() - a.x());
        if (std::abs(b.y() - a.y()) > 5.0 * std::abs(b.x() - a.x())) continue;  // steep: flange back, not tread
        for (auto& p : out.points_m) p.y() -= z0;
        std::ostringstream m;
        m << "wheel: z shifted by " << -z0 * 1e3 << " mm so that z(taping line) = 0";
        out.notes.push_back(m.str());
        break;
      }
    }
  }
  return out;
}

}  // namespace profile_io

}  // namespace conforma
