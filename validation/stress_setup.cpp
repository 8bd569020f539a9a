// Profile pairs of the stress suite (stress.hpp): new, worn and noisy.
#include <random>

#include "conforma/error.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/validation/stress.hpp"

namespace conforma {

void StressOptions::validate() const {
  if (cases < 0 || first_case < 0) throw InputError("stress: the case count and the first case must be >= 0");
  if (continuity_every < 0) throw InputError("stress: continuity_every must be >= 0");
  require_positive(continuity_step_m, "continuity_step_m");
  require_positive(continuity_bound_fraction, "continuity_bound_fraction");
  require_positive(jump_distance_m, "jump_distance_m");
  if (threads < 0) throw InputError("stress: threads must be >= 0");
}

StressSetup StressSetup::Make(const std::string& shared_data_dir, std::uint64_t noise_seed) {
  StressSetup s;
  const Profile rail60 = MakeRail(RailSection::R60E1, 0.0);
  const Profile s1002 = MakeS1002();
  s.new_pair = std::make_unique<WheelsetTrackGeometry>(MakeSymmetricTrack(s1002, rail60, rail_inclination_1in40()));
  ProfileReadOptions w, r;
  w.kind = ProfileKind::Wheel;
  r.kind = ProfileKind::Rail;
  const std::string bank = shared_data_dir + "/profiles/contact/testbank/profiles/";
  s.worn_pair = std::make_unique<WheelsetTrackGeometry>(MakeSymmetricTrack(
      LoadProfile(bank + "worn_high_mileage.prw", w), LoadProfile(bank + "site_b_hr.prr", r), 0.0));
  // S1002 measured with 30 um Gaussian noise on z every 0.5 mm, smoothed back by the profile fit.
  std::mt19937_64 rng(noise_seed);
  std::normal_distribution<double> noise(0.0, 30e-6);
  std::vector<Eigen::Vector2d> points;
  for (double y = s1002.y_min(); y <= s1002.y_max(); y += 0.5e-3) {
    const auto z = s1002.height_at(y);
    if (z) points.emplace_back(y, *z + noise(rng));
  }
  ProfileFitOptions fit;
  fit.smoothing_rms_m = 30e-6;
  s.noisy_pair = std::make_unique<WheelsetTrackGeometry>(
      MakeSymmetricTrack(Profile::FromPoints(points, ProfileKind::Wheel, fit, "S1002 + 30 um noise"), rail60,
                         rail_inclination_1in40()));
  return s;
}

}  // namespace conforma
