// Validation of profile points shared by every reader (docs/profiles-and-formats.md §3): a truncated last line,
// spacing and reversals on the running surface, orientation (wheel flange, rail head) and noise. Every entry point
// that reads a profile file (command line, scenario files, Python, C API) goes through ReadProfilePoints and so
// through these checks; the messages name the command-line flag that fixes the input.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <iterator>

#include "conforma/error.hpp"
#include "profile_io_internal.hpp"

namespace conforma {

namespace profile_io {

namespace {

constexpr double kMaxSpacing_m = 2e-3;        // largest point distance on the running surface
constexpr double kFlangeHeight_m = 10e-3;     // a wheel flange rises at least this much above the tread
constexpr double kPeakMargin_m = 3e-3;        // an extreme is a flange (not a profile end) if both ends lie this far away
constexpr double kRailFlatWidth_m = 25e-3;    // crown of a rail head: this wide with |slope| < kFlatSlope
constexpr double kFlatSlope = 0.25;
constexpr double kMinProfileWidth_m = 1e-3;  // narrowest lateral extent (CONTACT's test bank: a 10 mm circle, 19.8 mm)
constexpr double kMinRailWidth_m = 20e-3;    // a rail narrower than this and higher than wide: columns swapped
constexpr double kRailCrownDepth_m = 5e-3;    // a rail head is at least kRailCrownWidth_m wide this far below its top
constexpr double kRailCrownWidth_m = 30e-3;   // (worn 50E4 ... 60E1 heads: 50-70 mm; a wheel flange: ~15 mm)
// Noise: the median jump of the curvature between consecutive point triples on the running surface above 1/this
// is noise. Measured on the shared reference profiles (smooth: 1/16 mm and less, most below 1/80 mm) and on S1002
// with added normal noise at 0.1 mm spacing (0.5 um: 1/7.4 mm, 1 um: 1/3.8 mm); already 0.5 um of noise at 0.1 mm
// spacing splits the S1002/60E1 contact into ten patches at 1-2.3 GPa, because the interpolating fit follows it.
constexpr double kNoiseRadius_m = 10e-3;

struct TokenShape {
  int fraction_digits = 0;  // digits after the decimal point (of the mantissa)
  int exponent_digits = -1;  // digits of the exponent, -1 without exponent
};

TokenShape shape_of(const std::string& token) {
  TokenShape s;
  const auto e = token.find_first_of("eE");
  const std::string mantissa = token.substr(0, e);
  const auto dot = mantissa.find('.');
  if (dot != std::string::npos) s.fraction_digits = static_cast<int>(mantissa.size() - dot - 1);
  if (e != std::string::npos) {
    s.exponent_digits = 0;
    for (size_t i = e + 1; i < token.size(); ++i)
      if (std::isdigit(static_cast<unsigned char>(token[i]))) ++s.exponent_digits;
  }
  return s;
}

std::vector<std::string> data_fields(std::string line) {
  const auto c = line.find_first_of("#!%");
  if (c != std::string::npos) line = line.substr(0, c);
  line.erase(std::remove(line.begin(), line.end(), '"'), line.end());
  return split_fields(line);
}

double median_of(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::string mm(double v_m, int digits = 3) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v_m * 1e3;
  return s.str();
}

std::string at(const ProfilePoints& p, size_t i) {
  return "(y = " + mm(p.points_m[i].x()) + " mm, z = " + mm(p.points_m[i].y()) + " mm)";
}

// "--wheel-mirror" / "--rail-z-down" ...
std::string flag(ProfileKind kind, const char* what) { return std::string("--") + to_string(kind) + "-" + what; }

// "add --wheel-mirror" or "remove --wheel-mirror" (when the option is already set and caused the problem).
std::string toggle(ProfileKind kind, const char* what, bool set) {
  return std::string(set ? "remove " : "add ") + flag(kind, what);
}

// The size of the curve (fuzzing, session 25): a profile in metres read as millimetres spans a fraction of a mm and
// was refused later as "no function-like part to tabulate"; a wheel file with its two columns swapped is taller than
// wide and found no contact at all.
void check_extent(const ProfilePoints& p, const std::vector<double>& ys, const std::vector<double>& zs) {
  const auto [y_lo, y_hi] = std::minmax_element(ys.begin(), ys.end());
  const auto [z_lo, z_hi] = std::minmax_element(zs.begin(), zs.end());
  const double width = *y_hi - *y_lo, height = *z_hi - *z_lo;
  const std::string what = std::string(to_string(p.kind)) + " profile";
  if (width < kMinProfileWidth_m)
    throw InputError(p.source, 0,
                     "the " + what + " spans only " + mm(width) + " mm across (y) and " + mm(height) +
                         " mm in height (z); a wheel or rail profile spans 50-150 mm: wrong length unit (a file in "
                         "metres read as millimetres: --" + to_string(p.kind) + "-units m, or the file's own unit) "
                         "or the columns swapped");
  if ((p.kind == ProfileKind::Wheel || width < kMinRailWidth_m) && height > width)
    throw InputError(p.source, 0,
                     "the " + what + " is " + mm(height, 1) + " mm high (z) and only " + mm(width, 1) +
                         " mm wide (y); a wheel profile is wider than high (tread and flange ~130-150 mm, flange "
                         "~30 mm high), a rail head is 50-75 mm wide: are the y and z columns swapped (MiniProf: "
                         "ColumnDef)?");
}

// A rail's running surface is a head at least kRailCrownWidth_m wide kRailCrownDepth_m below its top; a wheel profile
// given as a rail (fuzzing, session 25) puts its narrow flange tip there and found "contact" on it.
void check_rail_crown(const ProfilePoints& p, const std::vector<double>& ys, const std::vector<double>& zs, size_t i_max) {
  const double level = zs[i_max] - kRailCrownDepth_m;
  size_t a = i_max, b = i_max;
  while (a > 0 && zs[a - 1] > level) --a;
  while (b + 1 < zs.size() && zs[b + 1] > level) ++b;
  const double width = std::abs(ys[b] - ys[a]);
  const bool open = (a == 0) || (b + 1 == zs.size());  // the head runs off the end of the measured curve
  if (width < kRailCrownWidth_m && !open)
    throw InputError(p.source, p.lines[i_max],
                     "the rail profile's top " + at(p, i_max) + " is only " + mm(width, 1) + " mm wide " +
                         mm(kRailCrownDepth_m, 0) + " mm below it; a rail head is " + mm(kRailCrownWidth_m, 0) +
                         "-75 mm wide there: is it a wheel profile (--wheel) or a spike in the points?");
}

}  // namespace

void check_last_line(const std::string& path, const std::vector<int>& data_lines) {
  if (data_lines.size() < 6) return;
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.empty() || text.back() == '\n') return;  // a complete last line ends with a line break
  const auto lines = read_lines(path);
  std::vector<int> dl = data_lines;
  std::sort(dl.begin(), dl.end());
  const int last = dl.back();
  if (last != static_cast<int>(lines.size())) return;  // the unterminated line is no data line
  const auto f_last = data_fields(lines[last - 1]);
  // The five data lines before it must agree on the number of columns and the digits of each column.
  std::vector<std::vector<std::string>> before;
  for (size_t k = dl.size() - 1; k-- > 0 && before.size() < 5;) before.push_back(data_fields(lines[dl[k] - 1]));
  for (const auto& b : before)
    if (b.size() != before.front().size()) return;
  const size_t columns = before.front().size();
  auto refuse = [&](const std::string& why) {
    throw InputError(path, last,
                     "the last line looks cut short (" + why +
                         ") and the file does not end with a line break: truncated file? (if the line is complete, "
                         "end the file with a line break)");
  };
  if (f_last.size() < columns)
    refuse(std::to_string(f_last.size()) + " columns where the lines before have " + std::to_string(columns));
  for (size_t c = 0; c < columns; ++c) {
    const TokenShape ref = shape_of(before.front()[c]);
    bool consistent = true;
    for (const auto& b : before) {
      const TokenShape s = shape_of(b[c]);
      consistent = consistent && s.fraction_digits == ref.fraction_digits && s.exponent_digits == ref.exponent_digits;
    }
    if (!consistent) continue;
    const TokenShape s = shape_of(f_last[c]);
    if (s.fraction_digits < ref.fraction_digits || s.exponent_digits < ref.exponent_digits)
      refuse("'" + f_last[c] + "' has fewer digits than column " + std::to_string(c + 1) + " of the lines before it");
  }
}

void check_points(ProfilePoints& p, const ProfileReadOptions& options) {
  const auto& pts = p.points_m;
  const size_t n = pts.size();
  // Coordinates beyond kMaxProfileCoordinate_m first (as Profile::FromPoints): a mm file read as metres otherwise met
  // the spacing check below and was told to "give a finer profile" (fuzzing, session 24)
  for (size_t i = 0; i < n; ++i)
    if (pts[i].allFinite() && pts[i].cwiseAbs().maxCoeff() > kMaxProfileCoordinate_m)
      throw InputError(p.source, i < p.lines.size() ? p.lines[i] : 0,
                       "point (" + mm(pts[i].x(), 1) + ", " + mm(pts[i].y(), 1) +
                           ") mm lies more than 10 m from the origin: wrong length unit (the file's or the "
                           "--*-units option) or a malformed number");
  if (n < 4) return;
  const ProfileKind kind = p.kind;
  const bool wheel = kind == ProfileKind::Wheel;
  std::vector<double> ys(n), zs(n);
  for (size_t i = 0; i < n; ++i) { ys[i] = pts[i].x(); zs[i] = pts[i].y(); }
  check_extent(p, ys, zs);
  const size_t i_max = std::max_element(zs.begin(), zs.end()) - zs.begin();
  const size_t i_min = std::min_element(zs.begin(), zs.end()) - zs.begin();
  const double z_max = zs[i_max], z_min = zs[i_min];
  const double z_end_high = std::max(zs.front(), zs.back()), z_end_low = std::min(zs.front(), zs.back());
  // An extreme lying clearly inside the curve (both ends farther than kPeakMargin): a flange tip or a crown.
  const bool peak_up = z_max - z_end_high > kPeakMargin_m, peak_down = z_end_low - z_min > kPeakMargin_m;

  // --- orientation ---------------------------------------------------------------------------------------------
  size_t i_tip = n;  // wheel flange tip in our orientation (n: no flange)
  if (wheel) {
    const double z_tread = median_of(zs), y_mid = median_of(ys);
    const double up = z_max - z_tread, down = z_tread - z_min;
    const bool flange_up = peak_up && up > kFlangeHeight_m, flange_down = peak_down && down > kFlangeHeight_m;
    if (flange_up || flange_down) {
      const bool z_wrong = flange_down && (!flange_up || down > up);
      const size_t i_flange = z_wrong ? i_min : i_max;
      const bool y_wrong = ys[i_flange] > y_mid + 5e-3;
      if (z_wrong || y_wrong) {
        std::ostringstream m;
        m << "wheel orientation: the flange tip " << at(p, i_flange) << " ";
        if (z_wrong) m << "points to -z (the flange must rise towards a larger radius, z up)";
        if (z_wrong && y_wrong) m << " and ";
        if (y_wrong) m << "lies on the positive-y side (the flange must be at negative y, towards the track centre)";
        m << "; the file is stored the other way round: ";
        if (z_wrong) m << toggle(kind, "z-down", options.mirror_z);
        if (z_wrong && y_wrong) m << " and ";
        if (y_wrong) m << toggle(kind, "mirror", options.mirror_y);
        m << " (scenario: profiles.wheel_" << (z_wrong ? "z_down" : "mirror")
          << "; C++/Python: ProfileReadOptions::mirror_" << (z_wrong ? "z" : "y") << ")";
        throw InputError(p.source, p.lines[i_flange], m.str());
      }
      i_tip = i_max;
    }
  } else if (peak_up) {
    check_rail_crown(p, ys, zs, i_max);
  }
  if (!wheel && peak_down && !peak_up && z_end_low - z_min > kFlangeHeight_m) {
    // Rail head upside down: a wide flat valley at the bottom (the crown) with the flanks rising on both sides.
    // A groove (a concave running surface a few mm wide) is not mistaken for it.
    auto slope = [&](size_t i) {
      const Eigen::Vector2d d = pts[std::min(i + 1, n - 1)] - pts[i ? i - 1 : 0];
      return std::abs(d.y()) / std::max(std::abs(d.x()), 1e-12);
    };
    size_t a = i_min, b = i_min;
    while (a > 0 && slope(a - 1) < kFlatSlope) --a;
    while (b + 1 < n && slope(b + 1) < kFlatSlope) ++b;
    if (ys[b] - ys[a] > kRailFlatWidth_m) {
      throw InputError(p.source, p.lines[i_min],
                       "rail orientation: the rail head is upside down (its flat crown " + at(p, i_min) +
                           " is the lowest point and the flanks rise " + mm(z_end_low - z_min, 1) +
                           " mm on both sides); the file has z pointing down: " +
                           toggle(kind, "z-down", options.mirror_z) +
                           " (scenario: profiles.rail_z_down; C++/Python: ProfileReadOptions::mirror_z)");
    }
  }

  // --- running surface: wheel on the field side of the flange tip up to 70 % of the flange height; rail the top
  // 15 mm; a flangeless wheel everywhere ----------------------------------------------------------------------------
  std::vector<char> running(n, 1);
  if (wheel && i_tip < n) {
    const double z_tread = median_of(zs);
    for (size_t i = 0; i < n; ++i) running[i] = i > i_tip && zs[i] < z_tread + 0.7 * (z_max - z_tread);
  } else if (!wheel) {
    for (size_t i = 0; i < n; ++i) running[i] = zs[i] > z_max - 15e-3;
  }

  std::vector<double> seg(n - 1);
  for (size_t i = 0; i + 1 < n; ++i) seg[i] = (pts[i + 1] - pts[i]).norm();
  const double h_median = median_of(seg);
  // --- noise ---------------------------------------------------------------------------------------------------------
  // Signed Menger curvature of each triple of consecutive points; on a smooth curve it changes little from one
  // triple to the next (even on a small circle), with noise it jumps: the median jump |kappa_i+1 - kappa_i|
  // measures the noise (for normal noise sigma at spacing h about 2.5 sigma / h^2).
  std::vector<double> kappa_signed(n, 0.0), dev;
  std::vector<char> has_kappa(n, 0);
  for (size_t i = 1; i + 1 < n; ++i) {
    if (!(running[i - 1] && running[i] && running[i + 1])) continue;
    const Eigen::Vector2d a = pts[i] - pts[i - 1], c = pts[i + 1] - pts[i - 1];
    const double chord = c.norm();
    if (!(chord > 0 && seg[i - 1] > 0 && seg[i] > 0)) continue;
    const double cross = a.x() * c.y() - a.y() * c.x();
    dev.push_back(std::abs(cross) / chord);                                  // distance of p_i from the chord
    kappa_signed[i] = 2.0 * cross / (seg[i - 1] * seg[i] * chord);  // Menger curvature of the triple
    has_kappa[i] = 1;
  }
  std::vector<double> kappa;
  for (size_t i = 1; i + 1 < n; ++i)
    if (has_kappa[i] && has_kappa[i + 1]) kappa.push_back(std::abs(kappa_signed[i + 1] - kappa_signed[i]));
  const double k_median = std::max(median_of(kappa), 1e-12);
  if (kappa.size() >= 20) {
    std::ostringstream note;
    note << "running surface: " << kappa.size() + 2 << " points, median spacing " << std::setprecision(3)
         << h_median * 1e3 << " mm, 1 / median curvature jump between point triples " << std::setprecision(3) << 1e3 / k_median << " mm";
    p.notes.push_back(note.str());
  }
  if (options.check_noise && options.fit.smoothing_rms_m == 0 && kappa.size() >= 20 && k_median > 1.0 / kNoiseRadius_m) {
    // For independent normal noise sigma the chord deviation has median about 0.83 sigma. The suggested smoothing
    // is twice that, rounded up to one significant digit: measured noise is not white (avg_low2.ban: 4.5 um
    // estimated, 0.02 mm needed for a single patch).
    const double sigma = 1.2 * median_of(dev);
    const double decade = std::pow(10.0, std::floor(std::log10(std::max(2.0 * sigma, 1e-6))));
    const double suggest_mm = std::ceil(2.0 * sigma / decade) * decade * 1e3;
    std::ostringstream m;
    m << "the points are noisy: the curvature of consecutive point triples on the running surface jumps by 1/("
      << std::setprecision(2) << 1e3 / k_median << " mm) in the median (smooth profiles: less than 1/("
      << kNoiseRadius_m * 1e3 << " mm)), noise about "
      << std::setprecision(2) << sigma * 1e6 << " um at " << std::setprecision(2) << h_median * 1e3
      << " mm spacing; contact stresses would follow the noise. Smooth the points, e.g. --" << to_string(kind)
      << "-smooth-mm " << std::setprecision(2) << suggest_mm
      << " (raise it until the result stops changing; scenario: profiles."
      << to_string(kind) << "_smoothing_mm; C++/Python: ProfileFitOptions::smoothing_rms_m)";
    throw InputError(p.source, 0, m.str());
  }

  // --- spacing and reversals on the running surface -----------------------------------------------------------------
  for (size_t i = 0; i + 1 < n; ++i) {
    if (!(running[i] && running[i + 1])) continue;
    if (seg[i] > kMaxSpacing_m) {
      throw InputError(p.source, p.lines[i + 1],
                       "points " + mm(seg[i]) + " mm apart on the running surface between lines " +
                           std::to_string(p.lines[i]) + " " + at(p, i) + " and " + std::to_string(p.lines[i + 1]) +
                           " " + at(p, i + 1) + ": the spacing must be at most " + mm(kMaxSpacing_m, 0) +
                           " mm there (the fit between the points would be a guess); give a finer profile");
    }
    if (i + 2 < n && running[i + 2] && options.fit.smoothing_rms_m == 0) {  // smoothing removes spikes
      const Eigen::Vector2d d0 = pts[i + 1] - pts[i], d1 = pts[i + 2] - pts[i + 1];
      const double floor_m = std::max(1e-6, 0.05 * h_median);
      if (seg[i] > floor_m && seg[i + 1] > floor_m && d0.dot(d1) < -0.5 * seg[i] * seg[i + 1]) {
        throw InputError(p.source, p.lines[i + 1],
                         "the curve turns back on itself at " + at(p, i + 1) + " (lines " + std::to_string(p.lines[i]) +
                             ", " + std::to_string(p.lines[i + 1]) + ", " + std::to_string(p.lines[i + 2]) +
                             "): points out of order, duplicated with a change, or a measurement spike on the running "
                             "surface");
      }
    }
  }
}

}  // namespace profile_io

}  // namespace conforma
