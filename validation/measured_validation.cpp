// Measured wheel reference dimensions against km: reading, interpolation of the simulated series between wear steps,
// per-point errors and their RMS (measured_validation.hpp).
#include "conforma/validation/measured_validation.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(ReferenceDimension dimension) {
  switch (dimension) {
    case ReferenceDimension::Sd: return "Sd";
    case ReferenceDimension::Sh: return "Sh";
    case ReferenceDimension::qR: return "qR";
  }
  return "?";
}

double DimensionValue(const WheelDimensions& d, ReferenceDimension dimension) {
  switch (dimension) {
    case ReferenceDimension::Sd: return d.sd_m;
    case ReferenceDimension::Sh: return d.sh_m;
    case ReferenceDimension::qR: return d.qr_m;
  }
  return 0.0;
}

const char* to_string(InterpolationStatus status) {
  return status == InterpolationStatus::Interpolated ? "interpolated" : "beyond_simulation";
}

namespace {

std::string Trim(const std::string& s) {
  size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string Lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::vector<std::string> SplitFields(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::stringstream ss(line);
  while (std::getline(ss, field, ',')) out.push_back(Trim(field));
  if (!line.empty() && line.back() == ',') out.push_back("");  // getline drops a trailing empty field
  return out;
}

// Column role: -1 km, 0..2 ReferenceDimension, -2 ignored.
// plausible measured values of Sd, Sh, qR, mm (wide around EN 15313's limits; a worn or re-profiled wheel included)
constexpr double kDimensionRange_mm[3][2] = {{10.0, 50.0}, {10.0, 60.0}, {2.0, 30.0}};

int ColumnRole(const std::string& name) {
  const std::string n = Lower(name);
  if (n == "km") return -1;
  if (n == "ft_mm" || n == "sd_mm") return static_cast<int>(ReferenceDimension::Sd);
  if (n == "fh_mm" || n == "sh_mm") return static_cast<int>(ReferenceDimension::Sh);
  if (n == "qr_mm") return static_cast<int>(ReferenceDimension::qR);
  return -2;
}

double ParseNumber(const std::string& field, const std::string& column, const std::string& source, int line) {
  if (field.empty()) throw InputError(source, line, "missing value in column '" + column + "'");
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(field.c_str(), &end);
  if (end == field.c_str() || *end != '\0' || errno == ERANGE)
    throw InputError(source, line, "column '" + column + "': '" + field + "' is not a number");
  if (!std::isfinite(v)) throw InputError(source, line, "column '" + column + "': '" + field + "' is not finite");
  return v;
}

}  // namespace

MeasuredDimensions ParseMeasuredDimensions(const std::string& text, const std::string& source) {
  MeasuredDimensions out;
  out.source = source;
  std::istringstream in(text);
  std::string raw;
  int line = 0, header_line = 0;
  std::vector<std::string> header;
  std::vector<int> role;
  int km_column = -1;
  std::array<int, 3> dim_column{-1, -1, -1};
  while (std::getline(in, raw)) {
    ++line;
    if (!raw.empty() && raw.back() == '\r') raw.pop_back();
    const std::string t = Trim(raw);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> fields = SplitFields(t);
    if (header.empty()) {
      header = fields;
      header_line = line;
      for (size_t c = 0; c < header.size(); ++c) {
        const int r = ColumnRole(header[c]);
        if (header[c].empty()) throw InputError(source, line, "empty column name in the header (column " +
                                                                  std::to_string(c + 1) + ")");
        if (r == -1) {
          if (km_column >= 0) throw InputError(source, line, "column 'km' given twice");
          km_column = static_cast<int>(c);
        } else if (r >= 0) {
          if (dim_column[r] >= 0)
            throw InputError(source, line, std::string("two columns for ") + to_string(static_cast<ReferenceDimension>(r)) +
                                               ": '" + header[dim_column[r]] + "' and '" + header[c] + "'");
          dim_column[r] = static_cast<int>(c);
        } else {
          out.ignored_columns.push_back(header[c]);
        }
      }
      if (km_column < 0) throw InputError(source, line, "missing column 'km' in the header '" + t + "'");
      if (std::all_of(dim_column.begin(), dim_column.end(), [](int c) { return c < 0; }))
        throw InputError(source, line,
                         "no dimension column in the header '" + t +
                             "' (expected FT_mm or sd_mm for Sd, FH_mm or sh_mm for Sh, QR_mm or qr_mm for qR)");
      for (int d = 0; d < 3; ++d) out.has[d] = dim_column[d] >= 0;
      continue;
    }
    if (fields.size() != header.size())
      throw InputError(source, line, "missing column: " + std::to_string(fields.size()) + " fields where the header (line " +
                                         std::to_string(header_line) + ") has " + std::to_string(header.size()));
    MeasuredDimensionPoint p;
    p.line = line;
    p.km = ParseNumber(fields[km_column], header[km_column], source, line);
    if (p.km < 0.0) throw InputError(source, line, "km must be >= 0, got " + fields[km_column]);
    if (!out.points.empty() && !(p.km > out.points.back().km))
      throw InputError(source, line, "km must increase strictly: " + fields[km_column] + " after " +
                                         MessageNumber(out.points.back().km) + " (line " +
                                         std::to_string(out.points.back().line) + ")");
    for (int d = 0; d < 3; ++d) {
      if (dim_column[d] < 0) continue;
      const double v = ParseNumber(fields[dim_column[d]], header[dim_column[d]], source, line);
      if (!(v > 0.0)) throw InputError(source, line, "column '" + header[dim_column[d]] + "' must be > 0 mm");
      // a wheel's dimension in mm (EN 15313: Sd 22-33, Sh 27.5-36, qR >= 6.5): far outside, another unit
      if (v < kDimensionRange_mm[d][0] || v > kDimensionRange_mm[d][1]) {
        std::ostringstream what;
        what << "column '" << header[dim_column[d]] << "' = " << fields[dim_column[d]] << ": implausible for "
             << to_string(static_cast<ReferenceDimension>(d)) << " in mm (expected " << kDimensionRange_mm[d][0]
             << " ... " << kDimensionRange_mm[d][1] << " mm; metres or inches?)";
        throw InputError(source, line, what.str());
      }
      p.value_m[d] = v * 1e-3;  // file in mm
    }
    out.points.push_back(p);
  }
  if (header.empty()) throw InputError(source, 0, "no header line (expected e.g. km,QR_mm,FH_mm,FT_mm)");
  if (out.points.empty()) throw InputError(source, header_line, "no data rows after the header");
  return out;
}

MeasuredDimensions ReadMeasuredDimensions(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the measured dimension file");
  std::ostringstream text;
  text << in.rdbuf();
  return ParseMeasuredDimensions(text.str(), path);
}

SimulatedDimensionSeries DimensionSeriesOf(const WearSimulationResult& result) {
  SimulatedDimensionSeries s;
  s.step.push_back(0);
  s.km.push_back(0.0);
  s.dimensions.push_back(result.initial_dimensions);
  const int last_rail = result.steps.empty() ? 0 : result.steps.back().rail_step;
  for (const WearStepRecord& r : result.steps) {
    if (r.rail_step != last_rail) continue;
    if (!(r.km > s.km.back())) continue;  // a zero-length step adds no information
    s.step.push_back(r.step);
    s.km.push_back(r.km);
    s.dimensions.push_back(r.dimensions);
  }
  return s;
}

StepBracket BracketKm(const std::vector<double>& km_list, double km) {
  if (km_list.empty()) throw InputError("BracketKm: empty simulated series");
  if (!std::isfinite(km) || km < 0.0)
    throw InputError("BracketKm: km must be finite and >= 0, got " + MessageNumber(km));
  StepBracket b;
  const double last = km_list.back();
  if (km > last * (1.0 + 1e-9) + 1e-12) {
    b.status = InterpolationStatus::BeyondSimulation;
    b.before = b.after = km_list.size() - 1;
    return b;
  }
  const auto it = std::lower_bound(km_list.begin(), km_list.end(), km);
  if (it == km_list.end()) {  // within the slack after the last step
    b.before = b.after = km_list.size() - 1;
    return b;
  }
  const size_t j = static_cast<size_t>(it - km_list.begin());
  if (*it == km || j == 0) {
    b.before = b.after = j;
    return b;
  }
  b.before = j - 1;
  b.after = j;
  b.weight = (km - km_list[j - 1]) / (km_list[j] - km_list[j - 1]);
  return b;
}

InterpolatedDimension InterpolateDimension(const SimulatedDimensionSeries& series, ReferenceDimension dimension,
                                           double km) {
  InterpolatedDimension out;
  out.bracket = BracketKm(series.km, km);
  if (out.bracket.status == InterpolationStatus::BeyondSimulation) return out;
  const double a = DimensionValue(series.dimensions[out.bracket.before], dimension);
  const double b = DimensionValue(series.dimensions[out.bracket.after], dimension);
  out.value_m = (1.0 - out.bracket.weight) * a + out.bracket.weight * b;
  return out;
}

DimensionErrorSummary SummariseDimensionErrors(const std::vector<DimensionComparisonPoint>& points,
                                               ReferenceDimension dimension) {
  DimensionErrorSummary s;
  double sum2 = 0.0, sum = 0.0;
  for (const DimensionComparisonPoint& p : points) {
    if (p.dimension != dimension) continue;
    if (p.bracket.status != InterpolationStatus::Interpolated) {
      ++s.beyond_simulation;
      continue;
    }
    ++s.points;
    sum2 += p.error_m * p.error_m;
    sum += p.error_m;
    s.max_abs_error_m = std::max(s.max_abs_error_m, std::abs(p.error_m));
  }
  if (s.points > 0) {
    s.rms_error_m = std::sqrt(sum2 / s.points);
    s.mean_error_m = sum / s.points;
  }
  return s;
}

DimensionComparison CompareDimensions(const SimulatedDimensionSeries& simulated, const MeasuredDimensions& measured) {
  DimensionComparison out;
  for (const MeasuredDimensionPoint& m : measured.points) {
    for (ReferenceDimension d : kReferenceDimensions) {
      const int k = static_cast<int>(d);
      if (!m.value_m[k]) continue;
      DimensionComparisonPoint p;
      p.km = m.km;
      p.line = m.line;
      p.dimension = d;
      p.measured_m = *m.value_m[k];
      const InterpolatedDimension sim = InterpolateDimension(simulated, d, m.km);
      p.bracket = sim.bracket;
      p.step_before = simulated.step[sim.bracket.before];
      p.step_after = simulated.step[sim.bracket.after];
      if (sim.bracket.status == InterpolationStatus::Interpolated) {
        p.simulated_m = sim.value_m;
        p.error_m = p.simulated_m - p.measured_m;
      }
      out.points.push_back(p);
    }
  }
  for (ReferenceDimension d : kReferenceDimensions)
    out.summary[static_cast<int>(d)] = SummariseDimensionErrors(out.points, d);
  return out;
}

}  // namespace conforma
