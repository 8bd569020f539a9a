// Wheelset kinematics CSV import/export (kinematics_import.hpp).
#include "conforma/kinematics_import.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "conforma/csv_columns.hpp"
#include "conforma/error.hpp"

namespace conforma {

namespace {

enum Column {
  kTime, kWheelset, kY, kZ, kRoll, kYaw, kDy, kDyaw, kSpeed, kOmega, kLoadLeft, kLoadRight, kWeight, kCurvature,
  kColumnCount
};
constexpr int kRequiredCount = kWeight;  // columns before kWeight are required
const std::array<const char*, kColumnCount> kNames = {
    "time_s",     "wheelset",    "y_m",         "z_m",          "roll_rad", "yaw_rad",        "dy_m_s",
    "dyaw_rad_s", "speed_m_s",   "omega_rad_s", "load_left_N", "load_right_N", "weight", "curvature_per_m"};

}  // namespace

KinematicsSeries ImportKinematicsCsv(const std::string& path) {
  const CsvColumns table = ReadCsvColumns(path, std::vector<std::string>(kNames.begin(), kNames.end()), kRequiredCount);
  KinematicsSeries series;
  series.source = path;
  const bool have_weight = table.present[kWeight];
  for (size_t row = 0; row < table.rows(); ++row) {
    const int line_no = table.line[row];
    std::array<double, kColumnCount> v{};
    for (int c = 0; c < kColumnCount; ++c)
      if (table.present[c]) v[c] = table.values[c][row];
    if (v[kWheelset] < 0.0 || v[kWheelset] != std::floor(v[kWheelset]) || v[kWheelset] > 1e6)
      throw InputError(path, line_no, "column 'wheelset' must be a non-negative integer");
    if (v[kLoadLeft] < 0.0) throw InputError(path, line_no, "column 'load_left_N' must be >= 0");
    if (v[kLoadRight] < 0.0) throw InputError(path, line_no, "column 'load_right_N' must be >= 0");
    if (have_weight && v[kWeight] < 0.0) throw InputError(path, line_no, "column 'weight' must be >= 0");
    KinematicsSample s;
    s.wheelset = static_cast<int>(v[kWheelset]);
    s.time_s = v[kTime];
    s.weight = have_weight ? v[kWeight] : 1.0;
    s.pose.lateral_m = v[kY];
    s.pose.vertical_m = v[kZ];
    s.pose.roll_rad = v[kRoll];
    s.pose.yaw_rad = v[kYaw];
    s.velocity.forward_speed_m_s = v[kSpeed];
    s.velocity.lateral_velocity_m_s = v[kDy];
    s.velocity.yaw_rate_rad_s = v[kDyaw];
    s.velocity.axle_angular_velocity_rad_s = v[kOmega];
    s.vertical_load_N[0] = v[kLoadLeft];
    s.vertical_load_N[1] = v[kLoadRight];
    s.track_curvature_per_m = table.present[kCurvature] ? v[kCurvature] : 0.0;
    series.samples.push_back(s);
  }
  if (!have_weight) {  // equal weights per wheelset
    std::map<int, int> count;
    for (const KinematicsSample& s : series.samples) ++count[s.wheelset];
    for (KinematicsSample& s : series.samples) s.weight = 1.0 / count[s.wheelset];
  }
  return series;
}

void ExportKinematicsCsv(const KinematicsSeries& series, const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw InputError(path, 0, "cannot write kinematics file");
  std::string source = series.source;
  for (char& ch : source)
    if (ch == '\n' || ch == '\r') ch = ' ';
  std::fprintf(f, "# conforma wheelset kinematics; source: %s\n", source.c_str());
  for (int c = 0; c < kColumnCount; ++c) std::fprintf(f, "%s%s", c ? "," : "", kNames[c]);
  std::fprintf(f, "\n");
  for (const KinematicsSample& s : series.samples) {
    const double v[kColumnCount] = {s.time_s,
                                    static_cast<double>(s.wheelset),
                                    s.pose.lateral_m,
                                    s.pose.vertical_m,
                                    s.pose.roll_rad,
                                    s.pose.yaw_rad,
                                    s.velocity.lateral_velocity_m_s,
                                    s.velocity.yaw_rate_rad_s,
                                    s.velocity.forward_speed_m_s,
                                    s.velocity.axle_angular_velocity_rad_s,
                                    s.vertical_load_N[0],
                                    s.vertical_load_N[1],
                                    s.weight,
                                    s.track_curvature_per_m};
    for (int c = 0; c < kColumnCount; ++c) std::fprintf(f, "%s%.17g", c ? "," : "", v[c]);
    std::fprintf(f, "\n");
  }
  const bool ok = std::ferror(f) == 0;
  if (std::fclose(f) != 0 || !ok) throw InputError(path, 0, "error while writing kinematics file");
}

}  // namespace conforma
