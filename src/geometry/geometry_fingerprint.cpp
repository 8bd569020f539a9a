// The numbers that define a wheelset-track geometry (geometry.hpp, GeometryFingerprint).
#include "conforma/geometry.hpp"

namespace conforma {

std::vector<double> GeometryFingerprint(const WheelsetTrackGeometry& g) {
  const TrackSetup& s = g.setup();
  std::vector<double> k{s.gauge_m, s.gauge_height_m, s.flange_back_distance_m, s.flange_back_position_m,
                        s.nominal_radius_m[0], s.nominal_radius_m[1], s.rail_inclination_rad, s.roller_radius_m[0],
                        s.roller_radius_m[1]};
  for (const std::array<Profile, 2>* pair : {&s.wheel, &s.rail})
    for (const Profile& p : *pair) {
      k.push_back(static_cast<double>(p.sample_count()));
      for (size_t i = 0; i < p.sample_count(); ++i) {
        const Eigen::Vector2d q = p.sample_at(i);
        k.push_back(q.x());
        k.push_back(q.y());
      }
    }
  return k;
}

}  // namespace conforma
