// The worn heavy-haul pair of issue 15 (worn_heavy_haul_track.hpp).
#include "conforma/validation/worn_heavy_haul_track.hpp"

#include "conforma/profile_io.hpp"

namespace conforma {

TrackSetup WornHeavyHaulTrack(const std::string& shared_data_dir) {
  ProfileReadOptions wheel_read, rail_read;
  wheel_read.kind = ProfileKind::Wheel;
  rail_read.kind = ProfileKind::Rail;
  const std::string bank = shared_data_dir + "/profiles/contact/testbank/profiles/";
  TrackSetup setup = MakeSymmetricTrack(LoadProfile(bank + "worn_high_mileage.prw", wheel_read),
                                        LoadProfile(bank + "site_b_hr.prr", rail_read), 0.0);
  setup.gauge_m = 1.43510;
  setup.gauge_height_m = 15.875e-3;
  setup.flange_back_distance_m = 1.34740;
  setup.flange_back_position_m = 0.0;
  setup.nominal_radius_m = {0.444, 0.444};
  return setup;
}

}  // namespace conforma
