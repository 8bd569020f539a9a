// Replay of a measured roller-rig time series (roller_rig_replay.hpp).
#include "conforma/roller_rig_replay.hpp"

#include <cmath>

#include "conforma/csv_columns.hpp"
#include "conforma/error.hpp"
#include "conforma/geometry.hpp"

namespace conforma {

namespace {
constexpr double kMaxRigLateralShift_m = 0.1;
}  // namespace

std::vector<RollerRigSample> ReadRollerRigSamples(const std::string& path) {
  const std::vector<std::string> names = {"t_s",         "y_m",         "yaw_rad",      "omega1_rad_s", "omega2_rad_s",
                                          "load_left_N", "load_right_N", "omega3_rad_s", "dt_s"};
  const CsvColumns c = ReadCsvColumns(path, names, 7);
  if (c.rows() == 0) throw InputError(path + ": no samples");
  std::vector<RollerRigSample> out(c.rows());
  for (size_t i = 0; i < c.rows(); ++i) {
    const std::string where = path + ":" + std::to_string(c.line[i]);
    RollerRigSample& s = out[i];
    s.time_s = c.values[0][i];
    s.lateral_m = c.values[1][i];
    s.yaw_rad = c.values[2][i];
    s.roller_speed_rad_s = {c.values[3][i], c.values[4][i]};
    s.wheel_load_N = {c.values[5][i], c.values[6][i]};
    if (c.present[7]) s.wheelset_speed_rad_s = c.values[7][i];
    RequireWheelsetYaw(s.yaw_rad, where + ": yaw_rad");  // (3 rad ran to exit 5: fuzzing, session 25)
    if (!(std::fabs(s.lateral_m) <= kMaxRigLateralShift_m))
      throw InputError(where + ": y_m beyond +-0.1 m: not a wheelset on rollers (unit?)");
    if (!(s.roller_speed_rad_s[0] > 0.0 && s.roller_speed_rad_s[1] > 0.0))
      throw InputError(where + ": omega1_rad_s and omega2_rad_s must be > 0");
    if (!(s.wheel_load_N[0] >= 0.0 && s.wheel_load_N[1] >= 0.0))
      throw InputError(where + ": load_left_N and load_right_N must be >= 0");
    if (i > 0 && !(s.time_s > out[i - 1].time_s)) throw InputError(where + ": t_s must increase");
    if (c.present[8]) {
      s.duration_s = c.values[8][i];
      if (!(s.duration_s > 0.0)) throw InputError(where + ": dt_s must be > 0");
    }
  }
  if (!c.present[8]) {
    for (size_t i = 0; i + 1 < out.size(); ++i) out[i].duration_s = out[i + 1].time_s - out[i].time_s;
    out.back().duration_s = out.size() > 1 ? out[out.size() - 2].duration_s : 0.02;
  }
  return out;
}

long ReplayRollerRigSamples(const RollerRigSampleOptions& options, RollerRigState* state,
                            const std::vector<RollerRigSample>& samples,
                            const std::function<void(const RollerRigReplayRow&)>& row) {
  long failed = 0;
  for (const RollerRigSample& s : samples) {
    RollerRigReplayRow r;
    r.sample = s;
    r.result = ProcessRigSample(options, state, s);
    if (r.result.status != RollerRigSampleStatus::Ok) ++failed;
    if (row) row(r);
  }
  return failed;
}

}  // namespace conforma
