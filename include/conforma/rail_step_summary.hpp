#pragma once
// What each rail step of a wear run did (paper 003 §6 and Fig. 11; docs/physics-reference.md §8.8, §8.10):
// the rail's removed area and depth per side, the area identity of the averaging, the wheel sequence behind it.
//
// Areas are measured on the profiles, along the normals of the rail before the step (MeasureRemovedAlongNormals,
// first order in the depth): A_k = area from r_k to r_{k+1}, A_k^j = area from r_k to the virtual rail r_k^j.
// r_{k+1} is the weighted normal average of the r_k^j (UpdateRail), and the area is linear in the depth, so
// A_k = sum_j w_j A_k^j up to the refit of the averaged rail (Profile::FromPoints resampling): area_residual is
// |A_k - sum_j w_j A_k^j| / (sum_j w_j A_k^j).
#include <array>
#include <string>
#include <vector>

#include "conforma/rail_update.hpp"
#include "conforma/wear_simulation.hpp"

namespace conforma {

struct RailSideStepSummary {
  ProfileUpdateStatus status = ProfileUpdateStatus::NoWear;  // of UpdateRail
  bool valid = false;                     // the new rail passed the validity check (status Updated)
  double max_abs_curvature_1_m = 0.0;     // of the new rail
  RemovedAlongNormals removed;            // r_{k+1} against r_k
  RemovedAlongNormals cumulative;         // r_{k+1} against r_0 (the rail's wear so far)
  std::vector<RemovedAlongNormals> virtual_removed;  // r_k^j against r_k, one per wheel profile
  std::vector<double> weights;            // of the virtual rails (share of the wheel sequence's km)
  double virtual_mean_area_m2 = 0.0;      // sum_j w_j A_k^j [m^2]
  double area_residual = 0.0;             // relative, see above (0 when nothing was removed)
  double passages = 0.0;                  // wheel passages the rail step represents (RailStepResult::passages_step)
};

struct RailStepSummary {
  int rail_step = 0;                      // k (0-based): r_k -> r_{k+1}
  int wheel_steps = 0;                    // wheel steps of the sequence run on r_k
  double wheel_km = 0.0;                  // distance of that sequence, km
  bool wheels_valid = true;               // every wheel profile of the sequence passed its validity check
  // last wheel of the sequence against the scenario's wheel w_0 (every rail step restarts from w_0)
  RemovedAlongNormals wheel_removed;
  double tread_wear_m = 0.0, flange_wear_m = 0.0;  // WearStepRecord of the last wheel step
  std::array<RailSideStepSummary, 2> side;          // [Left, Right]
};

// r_k, the rail of side (0 left, 1 right) during rail step k (0-based): the initial rail, or the result of step k-1.
const Profile& RailBeforeStep(const WearSimulationResult& result, size_t k, int side);

// One entry per rail step whose two rails were both computed (empty with a fixed rail).
std::vector<RailStepSummary> SummariseRailSteps(const WearSimulationResult& result);

}  // namespace conforma
