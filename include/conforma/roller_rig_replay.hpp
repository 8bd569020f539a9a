#pragma once
// Replay of a measured roller-rig time series (issue 18, paper 000 §2.2-3, Fig. 3; docs/physics-reference.md §18.5):
// every row of a CSV file is one sample (roller_rig_sample.hpp) processed in order on one rig state, so the profiles
// wear as the measured run goes on.
//
// Input CSV (csv_columns.hpp: '#' comments, named columns in any order):
//   required: t_s, y_m, yaw_rad, omega1_rad_s, omega2_rad_s, load_left_N, load_right_N
//   optional: omega3_rad_s (measured wheelset speed; absent or NaN-free column: used, else the balance is solved),
//             dt_s (step of the row; default: the time to the next row, the last row repeating the previous step, or
//             0.02 s for a single row)
#include <functional>
#include <string>
#include <vector>

#include "conforma/roller_rig_sample.hpp"

namespace conforma {

// InputError "<file>:<line>: ..." for a malformed file, a non-increasing time or a non-positive speed / load.
std::vector<RollerRigSample> ReadRollerRigSamples(const std::string& path);

// One row of the replay output.
struct RollerRigReplayRow {
  RollerRigSample sample;          // the input sample (dt filled in)
  RollerRigSampleResult result;    // forces, creepages, wear, status
};

// Processes the samples in order on `state` (from MakeRollerRigState); each row's result is passed to `row` (may be
// empty) as soon as it is computed. Returns the number of samples whose status was not ok.
long ReplayRollerRigSamples(const RollerRigSampleOptions& options, RollerRigState* state,
                            const std::vector<RollerRigSample>& samples,
                            const std::function<void(const RollerRigReplayRow&)>& row);

}  // namespace conforma
