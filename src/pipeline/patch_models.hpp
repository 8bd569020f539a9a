#pragma once
// The solve functions of the contact models (one file each: patch_model_*.cpp), registered in patch_solver.cpp.
#include "conforma/patch_solver.hpp"

namespace conforma {

// Tangential solves: without options.keep_fields a model may leave the element field empty (the KP models; hertz
// and exact fill it anyway, their totals come from it).

PatchNormalSolution SolveHertzPatchNormal(ContactModel model, const PatchInput& input, double approach_m,
                                          const WheelContactOptions& options);
PatchTangentialSolution SolveHertzPatchTangential(ContactModel model, const PatchNormalSolution& normal,
                                                  const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                                  const WheelContactOptions& options);
double HertzPatchPressureAt(const PatchNormalSolution& normal, double x_m, double s_m);

PatchNormalSolution SolveKpPatchNormal(ContactModel model, const PatchInput& input, double approach_m,
                                       const WheelContactOptions& options);
PatchTangentialSolution SolveKpPatchTangential(ContactModel model, const PatchNormalSolution& normal,
                                               const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                               const WheelContactOptions& options);
double KpPatchPressureAt(const PatchNormalSolution& normal, double x_m, double s_m);
std::vector<FastsimCreepages> KpStripCreepages(const PatchNormalSolution& normal, const RigidBodyMotion& motion,
                                               const PatchReferenceFrame& reference);

// Sets out's totals (fx, fy, mz, adhesion and slip areas, frictional power) from those of its element field.
void CopyFieldTotals(PatchTangentialSolution& out);

PatchNormalSolution SolveReferencePatchNormal(ContactModel model, const PatchInput& input, double approach_m,
                                              const WheelContactOptions& options);
PatchTangentialSolution SolveExactPatchTangential(ContactModel model, const PatchNormalSolution& normal,
                                                  const PatchCreepages& creepages, double rolling_speed_m_per_s,
                                                  const WheelContactOptions& options);
double ExactPatchPressureAt(const PatchNormalSolution& normal, double x_m, double s_m);
std::vector<FastsimCreepages> ExactColumnCreepages(const PatchNormalSolution& normal, const RigidBodyMotion& motion,
                                                   const PatchReferenceFrame& reference);

}  // namespace conforma
