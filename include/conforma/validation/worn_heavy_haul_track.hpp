// The worn heavy-haul wheel/rail pair of issue 15 with its measured track: worn_high_mileage.prw on site_b_hr.prr
// (CONTACT's test bank), gauge 1435.10 mm measured 15.875 mm below the rail top, flange-back distance 1347.40 mm
// at wheel-profile y = 0, r0 = 444 mm, no rail inclination. Shifted 15.0–15.5 mm towards one rail the wheel's
// worn flange face and gauge corner touch the rail's gauge corner: the conformal gauge-corner contact.
#pragma once

#include <string>

#include "conforma/geometry.hpp"

namespace conforma {

// shared_data_dir: the shared data folder (profiles/contact/testbank/profiles/ inside); InputError if unreadable.
TrackSetup WornHeavyHaulTrack(const std::string& shared_data_dir);

}  // namespace conforma
