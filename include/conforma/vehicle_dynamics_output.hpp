#pragma once
// Time-history output of the time-domain vehicle model (vehicle_dynamics.hpp): one CSV row per output sample.
// Columns: t_s, s_m (leading bogie centre), then per wheelset wsJ_y_mm, wsJ_psi_mrad, per bogie bogieI_y_mm,
// bogieI_psi_mrad, per carbody carbodyK_y_mm, carbodyK_psi_mrad (each in its local track frame), then per wheel
// (J = wheelset, W = L / R) wsJW_Y_N (track frame, + left), wsJW_Q_N, wsJW_YQ (+ towards the track centre),
// wsJW_Tgamma_N (wear number: frictional power / V); the wheel columns are empty for a sample without them.
// scripts/plot_dynamics.py plots it.
#include <ostream>
#include <string>
#include <vector>

#include "conforma/vehicle_dynamics.hpp"

namespace conforma {

std::vector<std::string> DynamicsHistoryColumns(const VehicleDynamicsModel& model);
void WriteDynamicsHistoryCsv(std::ostream& out, const VehicleDynamicsModel& model, const DynamicsResult& result);

}  // namespace conforma
