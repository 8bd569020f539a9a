// HDF5 file of a contact look-up table (contact_lut_io.hpp), written with the HDF5 C library.
#include "conforma/contact_lut_io.hpp"

#include <hdf5.h>

#include <algorithm>
#include <functional>
#include <type_traits>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "conforma/error.hpp"

namespace conforma {

namespace {

constexpr const char* kFormat = "conforma-contact-lut";
// 2: kLutStations = 31 stations per KP patch (1: 12)
constexpr int kFormatVersion = 2;

// The serial HDF5 library is not thread-safe: one process-wide lock around every file operation.
std::mutex& Hdf5Mutex() {
  static std::mutex m;
  return m;
}

struct Handle {  // closes an HDF5 id on scope exit
  hid_t id;
  herr_t (*close)(hid_t);
  ~Handle() {
    if (id >= 0) close(id);
  }
};

[[noreturn]] void Fail(const std::string& path, const std::string& what) {
  throw InputError(path, 0, "contact LUT file: " + what);
}

// An id HDF5 could not open or a read it could not do (a damaged file: the format checksums its headers) is an
// input error naming the object, never a default value read on.
void Require(long long status, const std::string& path, const std::string& what) {
  if (status < 0) Fail(path, what + " cannot be read (damaged file?)");
}
// The attribute `name` of `obj`, opened (close it with H5Aclose): missing or damaged is an error naming it.
hid_t OpenAttribute(hid_t obj, const char* name, const std::string& path) {
  const std::string what = std::string("attribute '") + name + "'";
  const htri_t exists = H5Aexists(obj, name);
  Require(exists, path, what);
  if (exists == 0) Fail(path, what + " missing");
  const hid_t id = H5Aopen(obj, name, H5P_DEFAULT);
  Require(id, path, what);
  return id;
}
// The group or dataset `name` in `group` exists (`what` names it in the error when it is missing or damaged).
void RequireLink(hid_t group, const char* name, const std::string& path, const std::string& what) {
  const htri_t exists = H5Lexists(group, name, H5P_DEFAULT);
  Require(exists, path, what);
  if (exists == 0) Fail(path, what + " missing");
}
// The group `name` of `parent`, opened (close it with H5Gclose).
hid_t OpenGroup(hid_t parent, const char* name, const std::string& path) {
  const std::string what = std::string("group '") + name + "'";
  RequireLink(parent, name, path, what);
  const hid_t id = H5Gopen2(parent, name, H5P_DEFAULT);
  Require(id, path, what);
  return id;
}

// A write HDF5 could not do (disk full, no permission) is an error naming the object, not a file missing it.
void RequireWritten(long long status, const char* name) {
  if (status < 0) throw InputError(std::string("contact LUT file: '") + name + "' cannot be written");
}

void AttrString(hid_t obj, const char* name, const std::string& value) {
  Handle type{H5Tcopy(H5T_C_S1), H5Tclose};
  H5Tset_size(type.id, value.empty() ? 1 : value.size());
  H5Tset_strpad(type.id, H5T_STR_NULLPAD);
  Handle space{H5Screate(H5S_SCALAR), H5Sclose};
  Handle attr{H5Acreate2(obj, name, type.id, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  RequireWritten(attr.id, name);
  RequireWritten(H5Awrite(attr.id, type.id, value.empty() ? "" : value.data()), name);
}

void AttrDoubles(hid_t obj, const char* name, const std::vector<double>& v) {
  const hsize_t n = v.size();
  Handle space{n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &n, nullptr), H5Sclose};
  Handle attr{H5Acreate2(obj, name, H5T_IEEE_F64LE, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  RequireWritten(attr.id, name);
  RequireWritten(H5Awrite(attr.id, H5T_NATIVE_DOUBLE, v.data()), name);
}

void AttrInt(hid_t obj, const char* name, int v) {
  Handle space{H5Screate(H5S_SCALAR), H5Sclose};
  Handle attr{H5Acreate2(obj, name, H5T_STD_I32LE, space.id, H5P_DEFAULT, H5P_DEFAULT), H5Aclose};
  RequireWritten(attr.id, name);
  RequireWritten(H5Awrite(attr.id, H5T_NATIVE_INT, &v), name);
}

std::string ReadAttrString(hid_t obj, const char* name, const std::string& path) {
  const std::string what = std::string("attribute '") + name + "'";
  Handle attr{OpenAttribute(obj, name, path), H5Aclose};
  Handle type{H5Aget_type(attr.id), H5Tclose};
  Require(type.id, path, what);
  if (H5Tget_class(type.id) != H5T_STRING) Fail(path, what + " is not a string");
  if (H5Tis_variable_str(type.id) > 0) {
    char* s = nullptr;
    Handle mem{H5Tcopy(H5T_C_S1), H5Tclose};
    H5Tset_size(mem.id, H5T_VARIABLE);
    Require(H5Aread(attr.id, mem.id, &s), path, what);
    std::string out = s ? s : "";
    H5free_memory(s);
    return out;
  }
  const size_t n = H5Tget_size(type.id);
  std::string s(n, '\0');
  Require(H5Aread(attr.id, type.id, s.data()), path, what);
  s.resize(s.find('\0') == std::string::npos ? n : s.find('\0'));
  return s;
}

std::vector<double> ReadAttrDoubles(hid_t obj, const char* name, const std::string& path) {
  const std::string what = std::string("attribute '") + name + "'";
  Handle attr{OpenAttribute(obj, name, path), H5Aclose};
  Handle space{H5Aget_space(attr.id), H5Sclose};
  Require(space.id, path, what);
  const hssize_t n = H5Sget_simple_extent_npoints(space.id);
  Require(n, path, what);
  std::vector<double> v(n);
  if (!v.empty()) Require(H5Aread(attr.id, H5T_NATIVE_DOUBLE, v.data()), path, what);
  return v;
}
double ReadAttrDouble(hid_t obj, const char* name, const std::string& path) {
  const std::vector<double> v = ReadAttrDoubles(obj, name, path);
  if (v.size() != 1) Fail(path, std::string("attribute '") + name + "' is not a scalar");
  return v[0];
}
int ReadAttrInt(hid_t obj, const char* name, const std::string& path) {
  Handle attr{OpenAttribute(obj, name, path), H5Aclose};
  int v = 0;
  Require(H5Aread(attr.id, H5T_NATIVE_INT, &v), path, std::string("attribute '") + name + "'");
  return v;
}

// A 1-D (columns = 0) or 2-D (rows x columns) dataset of doubles or ints with a "units" attribute.
template <class T>
void WriteData(hid_t group, const char* name, const std::vector<T>& v, const std::string& units, hsize_t columns = 0) {
  const bool is_double = std::is_same<T, double>::value;
  hsize_t dims[2] = {columns ? v.size() / columns : v.size(), columns};
  Handle space{H5Screate_simple(columns ? 2 : 1, dims, nullptr), H5Sclose};
  // every non-empty dataset chunked with a Fletcher-32 checksum (a damaged data block is a read error, not wrong
  // numbers); larger ones also with shuffle + deflate (lossless; h5py reads them as any other)
  Handle create{H5Pcreate(H5P_DATASET_CREATE), H5Pclose};
  if (!v.empty()) {
    hsize_t chunk[2] = {std::min<hsize_t>(dims[0], columns ? std::max<hsize_t>(1, 65536 / columns) : 65536), columns};
    H5Pset_chunk(create.id, columns ? 2 : 1, chunk);
    if (v.size() >= 4096) {
      H5Pset_shuffle(create.id);
      H5Pset_deflate(create.id, 4);
    }
    H5Pset_fletcher32(create.id);
  }
  Handle set{H5Dcreate2(group, name, is_double ? H5T_IEEE_F64LE : H5T_STD_I32LE, space.id, H5P_DEFAULT, create.id,
                        H5P_DEFAULT),
             H5Dclose};
  if (set.id < 0) throw InputError(std::string("contact LUT file: dataset '") + name + "' cannot be created");
  if (!v.empty())
    RequireWritten(H5Dwrite(set.id, is_double ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()),
                   name);
  AttrString(set.id, "units", units);
}

// The dataset `name` of `group`: `expected` values (any number when not given); `folder` prefixes its name in
// messages.
template <class T>
std::vector<T> ReadData(hid_t group, const char* name, const std::string& path,
                        std::optional<size_t> expected = std::nullopt, const char* folder = "") {
  const std::string what = std::string("dataset '") + folder + name + "'";
  RequireLink(group, name, path, what);
  Handle set{H5Dopen2(group, name, H5P_DEFAULT), H5Dclose};
  Require(set.id, path, what);
  Handle space{H5Dget_space(set.id), H5Sclose};
  Require(space.id, path, what);
  const hssize_t n = H5Sget_simple_extent_npoints(space.id);
  Require(n, path, what);
  if (expected && static_cast<size_t>(n) != *expected)
    Fail(path, what + " has " + std::to_string(n) + " values, expected " + std::to_string(*expected));
  std::vector<T> v(n);
  if (n > 0)
    Require(H5Dread(set.id, std::is_same<T, double>::value ? H5T_NATIVE_DOUBLE : H5T_NATIVE_INT, H5S_ALL, H5S_ALL,
                    H5P_DEFAULT, v.data()),
            path, what);
  return v;
}

// Every double field of LutPatch with its dataset name and units (one table drives writing and reading).
struct PatchField {
  const char* name;
  const char* units;
  double LutPatch::*member;
};
const std::vector<PatchField>& PatchFields() {
  static const std::vector<PatchField> fields = {
      {"y_contact_rail_m", "m", &LutPatch::y_contact_rail_m},
      {"z_contact_rail_m", "m", &LutPatch::z_contact_rail_m},
      {"rail_s_m", "m", &LutPatch::rail_s_m},
      {"y_contact_wheel_m", "m", &LutPatch::y_contact_wheel_m},
      {"lead_m", "m", &LutPatch::lead_m},
      {"contact_angle_rad", "rad", &LutPatch::contact_angle_rad},
      {"rolling_radius_m", "m", &LutPatch::rolling_radius_m},
      {"fn_N", "N", &LutPatch::fn_N},
      {"pressure_vertical_N", "N", &LutPatch::pressure_vertical_N},
      {"pressure_lateral_N", "N", &LutPatch::pressure_lateral_N},
      {"pmax_Pa", "Pa", &LutPatch::pmax_Pa},
      {"area_m2", "m^2", &LutPatch::area_m2},
      {"approach_m", "m", &LutPatch::approach_m},
      {"width_m", "m", &LutPatch::width_m},
      {"length_m", "m", &LutPatch::length_m},
      {"a_m", "m", &LutPatch::a_m},
      {"b_m", "m", &LutPatch::b_m},
      {"centre_x_m", "m", &LutPatch::centre_x_m},
      {"centre_s_m", "m", &LutPatch::centre_s_m},
      {"station_s_min_m", "m", &LutPatch::station_s_min_m},
      {"station_s_max_m", "m", &LutPatch::station_s_max_m},
      {"alpha_c_deg", "deg", &LutPatch::alpha_c_deg},
      {"auto_alpha_c_deg", "deg", &LutPatch::auto_alpha_c_deg},
  };
  return fields;
}

constexpr const char* kSideGroups[2] = {"left", "right"};

}  // namespace

void SaveContactLut(const ContactLut& lut, const std::string& path) {
  lut.grid.validate();
  std::lock_guard<std::mutex> lock(Hdf5Mutex());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors are reported as InputError, not printed
  // the HDF5 1.8 file format or later: its object headers carry checksums, so a damaged header is an error when the
  // table is read instead of a crash inside the library (fuzzing, session 24: one changed byte in a dataset's header
  // of a default-format file made the read segfault)
  Handle access{H5Pcreate(H5P_FILE_ACCESS), H5Pclose};
  H5Pset_libver_bounds(access.id, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  Handle file{H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.id), H5Fclose};
  if (file.id < 0) Fail(path, "cannot be created");
  const ContactLutHeader& h = lut.header;
  const hid_t root = file.id;
  AttrString(root, "format", kFormat);
  AttrInt(root, "format_version", kFormatVersion);
  AttrString(root, "wheel_profile", h.wheel_profile);
  AttrString(root, "rail_profile", h.rail_profile);
  AttrString(root, "track", h.track);
  AttrString(root, "model", to_string(h.model));
  AttrDoubles(root, "shear_modulus_Pa", {h.material.shear_modulus_Pa});
  AttrDoubles(root, "poisson_ratio", {h.material.poisson_ratio});
  AttrDoubles(root, "density_kg_m3", {h.material.density_kg_m3});
  AttrDoubles(root, "max_touching_contact_angle_rad", {h.max_touching_contact_angle_rad});
  AttrInt(root, "kp_strips", h.kp_strips);
  AttrDoubles(root, "candidate_strip_width_m", {h.candidate_strip_width_m});
  AttrDoubles(root, "patch_combine_distance_m", {h.patch_combine_distance_m});
  AttrInt(root, "conformal_variable_penetration", h.conformal_variable_penetration ? 1 : 0);
  AttrDoubles(root, "match_distance_m", {h.match_distance_m});
  AttrDoubles(root, "rail_origin_eta_m", {h.rail_origin_eta_m[0], h.rail_origin_eta_m[1]});
  AttrDoubles(root, "nominal_radius_m", {h.nominal_radius_m[0], h.nominal_radius_m[1]});
  if (!h.geometry_digest.empty()) AttrString(root, "geometry_digest", h.geometry_digest);
  AttrString(root, "conforma_version", h.conforma_version);
  AttrString(root, "conforma_commit", h.conforma_commit);
  AttrDoubles(root, "generation_s", {h.generation_s});
  AttrInt(root, "threads", h.threads);
  AttrString(root, "node_order", "node k = (i_lateral * n_yaw + i_yaw) * n_load + i_load");
  AttrString(root, "status_names", "0 ok, 1 no_contact, 2 not_converged, 3 no_rigid_equilibrium");
  AttrString(root, "model_names", "0 hertz, 1 kp, 2 kpec, 3 conformal, 4 exact (ContactModel)");
  AttrString(root, "stations",
             "KP patches: rows = patches, " + std::to_string(kLutStations) + " lateral stations x " +
                 std::to_string(kLutStationFields) + " values: half-length c [m], strip centre x [m], "
             "peak pressure [Pa], normal rotation alpha [rad], rigid slip map 3 x 4 (w_x [-], w_s at x = 0 [-], "
             "dw_s/dx [1/m]; columns as creepage_map), over [station_s_min_m, station_s_max_m]");
  AttrString(root, "slip_map",
             "KP patches, rows c0..c7 of w_x = c0 + c1 sigma + c2 sigma^2, w_s = c3 + c4 sigma + c5 sigma^2 + "
             "(c6 + c7 sigma) x' (sigma = s - centre_s_m, x' = x - centre_x_m [m]); columns as creepage_map");
  AttrString(root, "creepage_map",
             "rows xi, eta, phi [1/m]; columns multiply (1, v_lateral/V, yaw_rate/V, axle_rate/V) [-, -, 1/m, 1/m]");
  {
    Handle grid{H5Gcreate2(root, "grid", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
    RequireWritten(grid.id, "grid");
    WriteData(grid.id, "lateral_m", lut.grid.lateral_m, "m");
    WriteData(grid.id, "yaw_rad", lut.grid.yaw_rad, "rad");
    WriteData(grid.id, "load_N", lut.grid.load_N, "N");
  }
  for (int s = 0; s < 2; ++s) {
    const std::vector<LutNode>& nodes = lut.nodes[s];
    if (nodes.size() != lut.grid.nodes()) Fail(path, "the table's node count does not match its grid");
    Handle g{H5Gcreate2(root, kSideGroups[s], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose};
    RequireWritten(g.id, kSideGroups[s]);
    std::vector<int> status, offset{0}, model;
    std::vector<double> vertical, roll, map, slip, stations;
    for (const LutNode& n : nodes) {
      status.push_back(n.status);
      vertical.push_back(n.vertical_m);
      roll.push_back(n.roll_rad);
      offset.push_back(offset.back() + static_cast<int>(n.patches.size()));
      for (const LutPatch& p : n.patches) {
        model.push_back(p.model);
        map.insert(map.end(), p.creepage_map.begin(), p.creepage_map.end());
        slip.insert(slip.end(), p.slip_map.begin(), p.slip_map.end());
        stations.insert(stations.end(), p.stations.begin(), p.stations.end());
      }
    }
    WriteData(g.id, "node_status", status, "-");
    WriteData(g.id, "node_vertical_m", vertical, "m");
    WriteData(g.id, "node_roll_rad", roll, "rad");
    WriteData(g.id, "node_patch_offset", offset, "-");
    WriteData(g.id, "model", model, "-");
    for (const PatchField& f : PatchFields()) {
      std::vector<double> v;
      for (const LutNode& n : nodes)
        for (const LutPatch& p : n.patches) v.push_back(p.*f.member);
      WriteData(g.id, f.name, v, f.units);
    }
    WriteData(g.id, "creepage_map", map, "see root attribute creepage_map", 12);
    WriteData(g.id, "slip_map", slip, "see root attribute slip_map", 32);
    WriteData(g.id, "stations", stations, "see root attribute stations", kLutStations * kLutStationFields);
  }
  if (H5Fflush(file.id, H5F_SCOPE_GLOBAL) < 0) Fail(path, "cannot be written");
}

ContactLut LoadContactLut(const std::string& path) {
  std::lock_guard<std::mutex> lock(Hdf5Mutex());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  if (H5Fis_hdf5(path.c_str()) <= 0) Fail(path, "not found or not an HDF5 file");
  Handle file{H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose};
  if (file.id < 0) Fail(path, "cannot be opened");
  const hid_t root = file.id;
  if (ReadAttrString(root, "format", path) != kFormat) Fail(path, "not a Conforma contact LUT (attribute format)");
  const int version = ReadAttrInt(root, "format_version", path);
  if (version != kFormatVersion)
    Fail(path, "format_version " + std::to_string(version) + " is not this version's " +
                   std::to_string(kFormatVersion) + " (version 1 kept 12 stations per KP patch): build the table again");
  ContactLut lut;
  ContactLutHeader& h = lut.header;
  h.wheel_profile = ReadAttrString(root, "wheel_profile", path);
  h.rail_profile = ReadAttrString(root, "rail_profile", path);
  h.track = ReadAttrString(root, "track", path);
  h.model = ParseContactModel(ReadAttrString(root, "model", path));
  h.material.shear_modulus_Pa = ReadAttrDouble(root, "shear_modulus_Pa", path);
  h.material.poisson_ratio = ReadAttrDouble(root, "poisson_ratio", path);
  h.material.density_kg_m3 = ReadAttrDouble(root, "density_kg_m3", path);
  h.max_touching_contact_angle_rad = ReadAttrDouble(root, "max_touching_contact_angle_rad", path);
  h.kp_strips = ReadAttrInt(root, "kp_strips", path);
  h.candidate_strip_width_m = ReadAttrDouble(root, "candidate_strip_width_m", path);
  h.patch_combine_distance_m = ReadAttrDouble(root, "patch_combine_distance_m", path);
  h.conformal_variable_penetration = ReadAttrInt(root, "conformal_variable_penetration", path) != 0;
  h.match_distance_m = ReadAttrDouble(root, "match_distance_m", path);
  const std::vector<double> eta = ReadAttrDoubles(root, "rail_origin_eta_m", path);
  const std::vector<double> r0 = ReadAttrDoubles(root, "nominal_radius_m", path);
  if (eta.size() != 2 || r0.size() != 2) Fail(path, "rail_origin_eta_m / nominal_radius_m need 2 values");
  h.rail_origin_eta_m = {eta[0], eta[1]};
  h.nominal_radius_m = {r0[0], r0[1]};
  // (optional: tables written before the digest; a damaged one is an error, not a table without it)
  const htri_t has_digest = H5Aexists(root, "geometry_digest");
  Require(has_digest, path, "attribute 'geometry_digest'");
  if (has_digest > 0) h.geometry_digest = ReadAttrString(root, "geometry_digest", path);
  h.conforma_version = ReadAttrString(root, "conforma_version", path);
  h.conforma_commit = ReadAttrString(root, "conforma_commit", path);
  h.generation_s = ReadAttrDouble(root, "generation_s", path);
  h.threads = ReadAttrInt(root, "threads", path);
  {
    Handle grid{OpenGroup(root, "grid", path), H5Gclose};
    lut.grid.lateral_m = ReadData<double>(grid.id, "lateral_m", path, std::nullopt, "grid/");
    lut.grid.yaw_rad = ReadData<double>(grid.id, "yaw_rad", path, std::nullopt, "grid/");
    lut.grid.load_N = ReadData<double>(grid.id, "load_N", path, std::nullopt, "grid/");
  }
  try {
    lut.grid.validate();
  } catch (const InputError& e) {
    Fail(path, e.what());
  }
  const size_t nodes = lut.grid.nodes();
  for (int s = 0; s < 2; ++s) {
    Handle g{OpenGroup(root, kSideGroups[s], path), H5Gclose};
    const std::vector<int> status = ReadData<int>(g.id, "node_status", path, nodes);
    const std::vector<double> vertical = ReadData<double>(g.id, "node_vertical_m", path, nodes);
    const std::vector<double> roll = ReadData<double>(g.id, "node_roll_rad", path, nodes);
    const std::vector<int> offset = ReadData<int>(g.id, "node_patch_offset", path, nodes + 1);
    if (offset[0] != 0) Fail(path, "node_patch_offset must start at 0");
    for (size_t k = 0; k < nodes; ++k)
      if (offset[k + 1] < offset[k]) Fail(path, "node_patch_offset must not decrease");
    const size_t patches = static_cast<size_t>(offset[nodes]);
    const std::vector<int> model = ReadData<int>(g.id, "model", path, patches);
    std::vector<std::vector<double>> fields;
    for (const PatchField& f : PatchFields()) fields.push_back(ReadData<double>(g.id, f.name, path, patches));
    const std::vector<double> map = ReadData<double>(g.id, "creepage_map", path, 12 * patches);
    const std::vector<double> slip = ReadData<double>(g.id, "slip_map", path, 32 * patches);
    constexpr size_t kS = kLutStations * kLutStationFields;
    const std::vector<double> stations = ReadData<double>(g.id, "stations", path, kS * patches);
    std::vector<LutNode>& out = lut.nodes[s];
    out.resize(nodes);
    for (size_t k = 0; k < nodes; ++k) {
      LutNode& n = out[k];
      n.status = status[k];
      n.vertical_m = vertical[k];
      n.roll_rad = roll[k];
      for (int r = offset[k]; r < offset[k + 1]; ++r) {
        LutPatch p;
        p.model = model[r];
        for (size_t f = 0; f < fields.size(); ++f) p.*(PatchFields()[f].member) = fields[f][r];
        std::copy(map.begin() + 12 * r, map.begin() + 12 * (r + 1), p.creepage_map.begin());
        std::copy(slip.begin() + 32 * r, slip.begin() + 32 * (r + 1), p.slip_map.begin());
        std::copy(stations.begin() + kS * r, stations.begin() + kS * (r + 1), p.stations.begin());
        n.patches.push_back(p);
      }
    }
  }
  return lut;
}

}  // namespace conforma
