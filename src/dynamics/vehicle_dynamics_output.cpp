// Time-history CSV of the time-domain vehicle model (vehicle_dynamics_output.hpp).
#include "conforma/vehicle_dynamics_output.hpp"

#include <cstdio>

namespace conforma {

std::vector<std::string> DynamicsHistoryColumns(const VehicleDynamicsModel& m) {
  std::vector<std::string> c{"t_s", "s_m"};
  for (int j = 0; j < m.wheelset_count(); ++j)
    for (const char* q : {"_y_mm", "_psi_mrad"}) c.push_back("ws" + std::to_string(j) + q);
  for (int i = 0; i < m.bogie_count(); ++i)
    for (const char* q : {"_y_mm", "_psi_mrad"}) c.push_back("bogie" + std::to_string(i) + q);
  for (int k = 0; k < m.carbody_count(); ++k)
    for (const char* q : {"_y_mm", "_psi_mrad"}) c.push_back("carbody" + std::to_string(k) + q);
  for (int j = 0; j < m.wheelset_count(); ++j)
    for (const char* w : {"L", "R"})
      for (const char* q : {"_Y_N", "_Q_N", "_YQ", "_Tgamma_N"}) c.push_back("ws" + std::to_string(j) + w + q);
  return c;
}

void WriteDynamicsHistoryCsv(std::ostream& f, const VehicleDynamicsModel& m, const DynamicsResult& r) {
  const std::vector<std::string> columns = DynamicsHistoryColumns(m);
  for (size_t i = 0; i < columns.size(); ++i) f << (i ? "," : "") << columns[i];
  f << "\n";
  char buf[96];
  for (const DynamicsSample& s : r.history) {
    std::snprintf(buf, sizeof buf, "%.5f,%.4f", s.time_s, s.station_m);
    f << buf;
    for (int q = 0; q < m.position_count(); ++q) {
      std::snprintf(buf, sizeof buf, ",%.6f", s.state[q]);
      f << buf;
    }
    for (int j = 0; j < m.wheelset_count(); ++j)
      for (int w = 0; w < 2; ++w) {
        if (s.wheels.empty()) {
          f << ",,,,";
          continue;
        }
        const WheelDynamicsSample& x = s.wheels[j][w];
        std::snprintf(buf, sizeof buf, ",%.2f,%.2f,%.5f,%.4f", x.lateral_force_N, x.vertical_load_N, x.y_over_q,
                      x.wear_number_N);
        f << buf;
      }
    f << "\n";
  }
}

}  // namespace conforma
