#pragma once
// Private to the pipeline: the two stages of SolveWheelContact (wheel_contact.cpp) and what the first hands to the
// second: stage 1 (wheel_normal_stage.cpp) candidates, model per patch, normal problem and load control; stage 2
// (wheel_tangential_stage.cpp) creepages and the tangential problem patch by patch.
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "conforma/contact_candidates.hpp"
#include "conforma/patch_solver.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {
namespace wheel_contact_detail {

struct PatchFrame {  // patch reference frame in the side frame (x, eta, z)
  Eigen::Vector3d normal, tangent;
  Eigen::Vector3d longitudinal = Eigen::Vector3d::UnitX();  // the rolling direction (fx)
};

// Everything the normal problem of one wheel produces (stage 1 of SolveWheelContact): what the tangential stage
// needs, and what WheelContactCache keeps between calls at one pose.
struct NormalStage {
  WheelContactReport report;  // side, model, pose, load iterations, NotConverged; no patches yet
  bool finished = false;      // the report is final (unloaded, no contact, no load bracket)
  CandidateResult candidates;
  std::vector<RigidContactPoint> hertz_points;
  std::vector<size_t> hertz_region;  // hertz model: the index of each point's region in the candidate search's list
  std::vector<ContactModel> patch_model;
  std::vector<double> auto_alpha_c_deg;
  std::vector<PatchFrame> frames;
  std::vector<PatchNormalSolution> normal;
  // Total-force load control (LoadBalance::Total): the report of the tangential stage at the final push-down,
  // solved together with the normal problem (then the stage depends on the velocity and the tangential options)
  std::shared_ptr<const WheelContactReport> coupled;
};

// Stage 1 (options validated by the caller).
NormalStage SolveNormalStage(const WheelsetTrackGeometry& geometry, Side side, const WheelsetPose& pose,
                             const WheelsetVelocity& velocity, const WheelContactOptions& options);

// Stage 2: creepages and the tangential problem, patch by patch, on a solved normal stage.
WheelContactReport SolveTangentialStage(const NormalStage& stage, const WheelsetTrackGeometry& geometry, Side side,
                                        const WheelsetVelocity& velocity, const WheelContactOptions& options);

// Stage 2 (or the coupled report of a total-force balance) and the plausibility warnings of the finished report.
WheelContactReport FinishWheelContact(const NormalStage& stage, const WheelsetTrackGeometry& geometry, Side side,
                                      const WheelsetVelocity& velocity, const WheelContactOptions& options);

}  // namespace wheel_contact_detail
}  // namespace conforma
