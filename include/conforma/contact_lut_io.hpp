#pragma once
// HDF5 file of a contact look-up table (contact_lut.hpp), self-describing and readable with h5py:
//   /                      attributes: format "conforma-contact-lut", format_version, wheel_profile, rail_profile,
//                          track, model, shear_modulus_Pa, poisson_ratio, max_touching_contact_angle_rad, kp_strips,
//                          candidate_strip_width_m, patch_combine_distance_m, conformal_variable_penetration,
//                          match_distance_m, rail_origin_eta_m[2], nominal_radius_m[2], conforma_version,
//                          conforma_commit, generation_s, threads, node_order, status_names, model_names
//   /grid/lateral_m, /grid/yaw_rad, /grid/load_N           the axes (attribute "units" on every dataset)
//   /left, /right          per side: node_status, node_vertical_m, node_roll_rad (one per node, load fastest),
//                          node_patch_offset (nodes + 1: patches of node k are rows offset[k] .. offset[k+1]-1),
//                          and one dataset per LutPatch field (one row per patch), creepage_map as rows x 12
// Doubles are stored as IEEE doubles: save then load gives the identical table.
#include <string>

#include "conforma/contact_lut.hpp"

namespace conforma {

// InputError naming the file when it cannot be written.
void SaveContactLut(const ContactLut& lut, const std::string& path);
// InputError naming the file (missing, not HDF5, not a contact LUT, inconsistent sizes).
ContactLut LoadContactLut(const std::string& path);

}  // namespace conforma
