// Python module `conforma._core` (pybind11): profiles, track, one wheelset contact with per-cell fields as NumPy
// arrays, the Manchester A-2.2 runner. The package python/conforma/__init__.py re-exports it.
// conforma::InputError becomes conforma.InputError (a ValueError) with the C++ message unchanged.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <tuple>
#include <string>
#include <type_traits>
#include <vector>

#include "conforma/contact_lut.hpp"
#include "conforma/contact_lut_io.hpp"
#include "conforma/data_paths.hpp"
#include "conforma/error.hpp"
#include "conforma/profile_by_name.hpp"
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "conforma/validation/validation_manchester.hpp"
#include "conforma/wheel_contact.hpp"
#include "conforma/wheel_contact_fields.hpp"
#include "conforma/wheel_dimensions.hpp"
#include "interop.hpp"
#include "module_parts.hpp"

namespace py = pybind11;
using namespace conforma;

namespace conforma::python {

py::array_t<double> Column(const std::vector<double>& values) {
  py::array_t<double> a(static_cast<py::ssize_t>(values.size()));
  auto view = a.mutable_unchecked<1>();
  for (size_t i = 0; i < values.size(); ++i) view(static_cast<py::ssize_t>(i)) = values[i];
  return a;
}

py::array_t<double> PointsArray(const std::vector<Eigen::Vector2d>& points) {
  py::array_t<double> a({static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(2)});
  auto view = a.mutable_unchecked<2>();
  for (size_t i = 0; i < points.size(); ++i) {
    view(static_cast<py::ssize_t>(i), 0) = points[i].x();
    view(static_cast<py::ssize_t>(i), 1) = points[i].y();
  }
  return a;
}

py::dict DimensionsDict(const WheelDimensions& d) {
  py::dict out;
  out["sd_m"] = d.sd_m, out["sh_m"] = d.sh_m, out["qr_m"] = d.qr_m;
  out["sd_mm"] = d.sd_m * 1e3, out["sh_mm"] = d.sh_m * 1e3, out["qr_mm"] = d.qr_m * 1e3;
  out["p0_m"] = std::vector<double>{d.p0.x(), d.p0.y()};
  out["tip_m"] = std::vector<double>{d.tip.x(), d.tip.y()};
  out["sd_point_m"] = std::vector<double>{d.sd_point.x(), d.sd_point.y()};
  out["qr_point_m"] = std::vector<double>{d.qr_point.x(), d.qr_point.y()};
  return out;
}

ProfileKind KindFrom(const std::string& name) {
  if (name == "wheel") return ProfileKind::Wheel;
  if (name == "rail") return ProfileKind::Rail;
  throw InputError("profile kind must be 'wheel' or 'rail', not '" + name + "'");
}

}  // namespace conforma::python

namespace {

using conforma::python::Column;

// Per-cell fields of a patch as NumPy arrays (grid coordinates and the solution on them).
py::dict FieldsDict(const PatchReport& p) {
  const size_t n = p.cells.size();
  std::vector<double> x(n), s(n), rail_s(n), wheel_y(n), area(n), dx(n), pressure(n), tx(n), ts(n), sx(n), ss(n),
      wear_index(n);
  py::array_t<bool> adhesion(static_cast<py::ssize_t>(n));
  auto adh = adhesion.mutable_unchecked<1>();
  for (size_t i = 0; i < n; ++i) {
    const ContactCell& c = p.cells[i];
    x[i] = c.x_m, s[i] = c.s_m, rail_s[i] = c.rail_s_m, wheel_y[i] = c.wheel_y_m, area[i] = c.area_m2;
    dx[i] = c.length_x_m, pressure[i] = c.pressure_Pa, tx[i] = c.traction_x_Pa, ts[i] = c.traction_s_Pa;
    sx[i] = c.slip_x, ss[i] = c.slip_s;
    // wear index per unit area: frictional work per unit rolled distance and area, |p_t . s| (T gamma / A)
    wear_index[i] = std::fabs(c.traction_x_Pa * c.slip_x + c.traction_s_Pa * c.slip_s);
    adh(static_cast<py::ssize_t>(i)) = !c.in_slip;
  }
  py::dict f;
  f["x_m"] = Column(x), f["s_m"] = Column(s), f["rail_s_m"] = Column(rail_s), f["wheel_y_m"] = Column(wheel_y);
  f["area_m2"] = Column(area), f["length_x_m"] = Column(dx), f["pressure_Pa"] = Column(pressure);
  f["traction_x_Pa"] = Column(tx), f["traction_s_Pa"] = Column(ts), f["slip_x"] = Column(sx), f["slip_s"] = Column(ss);
  f["adhesion"] = adhesion;
  f["wear_index_Pa"] = Column(wear_index);
  return f;
}

// The keys of `conforma contact --json` (the field tables, conforma/wheel_contact_fields.hpp), plus "fields" when
// they were kept.
py::dict PatchDict(const PatchReport& p, bool with_fields) {
  py::dict d;
  VisitPatchFields(p, [&d](const char* key, const auto& value) { d[key] = value; });
  if (with_fields) d["fields"] = FieldsDict(p);
  return d;
}

py::dict WheelDict(const WheelsetTrackGeometry& geometry, const WheelContactReport& r, bool with_fields) {
  py::list patches;
  for (const PatchReport& p : r.patches) {
    py::dict d = PatchDict(p, with_fields);
    const interop::TrackFramePatch t = interop::ToTrackFrame(geometry, r.side, p);
    d["force_track_N"] = std::vector<double>{t.force_N.x(), t.force_N.y(), t.force_N.z()};
    d["contact_point_track_m"] = std::vector<double>{t.point_m.x(), t.point_m.y(), t.point_m.z()};
    patches.append(d);
  }
  py::dict d;
  VisitWheelReportFields(r, [&d](const char* key, const auto& value) {
    if constexpr (std::is_same_v<std::decay_t<decltype(value)>, WheelsetPose>) {
      py::dict pose;
      VisitPoseFields(value, [&pose](const char* pose_key, double x) { pose[pose_key] = x; });
      d[key] = pose;
    } else {
      d[key] = value;
    }
  });
  d["patches"] = patches;
  return d;
}

// A track: the geometry of S1002-type wheels on two rails (interop::MakeTrackGeometry, as the command line).
struct Track {
  std::shared_ptr<const WheelsetTrackGeometry> geometry;
  // ContactLutGeometryDigest of the geometry, computed at its first table evaluation (under the GIL)
  mutable std::string lut_digest;
};

Track MakeTrack(const py::object& wheel, const py::object& rail, std::optional<double> inclination_rad,
                double gauge_m, double gauge_height_m, double flange_back_distance_m, double flange_back_position_m,
                double nominal_radius_m) {
  interop::TrackSpec spec;
  spec.inclination_rad = inclination_rad;
  spec.gauge_m = gauge_m, spec.gauge_height_m = gauge_height_m;
  spec.flange_back_distance_m = flange_back_distance_m, spec.flange_back_position_m = flange_back_position_m;
  spec.nominal_radius_m = nominal_radius_m;
  const bool wheel_is_name = py::isinstance<py::str>(wheel), rail_is_name = py::isinstance<py::str>(rail);
  // (Track(5) raised pybind's bare "Unable to cast Python instance to C++ type": fuzzing, session 25)
  for (const auto& [value, is_name, name] : {std::tuple{&wheel, wheel_is_name, "wheel"}, {&rail, rail_is_name, "rail"}})
    if (!is_name && !py::isinstance<Profile>(*value))
      throw py::type_error(std::string("Track: ") + name + " must be a profile name, a file path or a Profile, not " +
                           py::str(py::type::of(*value).attr("__name__")).cast<std::string>());
  if (wheel_is_name && rail_is_name) {
    spec.wheel = wheel.cast<std::string>(), spec.rail = rail.cast<std::string>();
    py::gil_scoped_release release;
    return Track{interop::MakeTrackGeometry(spec), {}};
  }
  Profile w = wheel_is_name ? WheelProfileByNameOrFile(wheel.cast<std::string>()) : wheel.cast<Profile>();
  bool built_in = false;
  Profile r = rail_is_name ? RailProfileByNameOrFile(rail.cast<std::string>(), &built_in) : rail.cast<Profile>();
  if (w.kind() != ProfileKind::Wheel) throw InputError("Track: the wheel profile is a rail profile");
  if (r.kind() != ProfileKind::Rail) throw InputError("Track: the rail profile is a wheel profile");
  const double incl = inclination_rad ? *inclination_rad : built_in ? rail_inclination_1in40() : 0.0;
  py::gil_scoped_release release;
  return Track{interop::MakeTrackGeometry(w, r, incl, spec), {}};
}

WheelContactOptions ContactOptions(const std::string& model, double load_N, double mu, double shear_modulus_Pa,
                                   double poisson_ratio, int grid, bool fields, double exact_element_m) {
  WheelContactOptions o;
  o.model = ParseContactModel(model);
  o.vertical_load_N = load_N;
  o.friction_coefficient = mu;
  o.material.shear_modulus_Pa = shear_modulus_Pa;
  o.material.poisson_ratio = poisson_ratio;
  o.fastsim_elements = grid;
  o.exact_element_size_m = exact_element_m;
  o.keep_fields = fields;
  o.validate();
  return o;
}

py::list Contact(const Track& track, double lateral_m, double yaw_rad, std::optional<double> roll_rad,
                 const std::string& model, double load_N, double speed_m_s, double mu, double shear_modulus_Pa,
                 double poisson_ratio, int grid, double approach_m, const std::string& side, std::optional<double> xi,
                 std::optional<double> eta, std::optional<double> phi_per_m, bool fields, double exact_element_m) {
  WheelContactOptions o =
      ContactOptions(model, load_N, mu, shear_modulus_Pa, poisson_ratio, grid, fields, exact_element_m);
  if (xi || eta || phi_per_m) {
    o.creepages_given = true;
    o.creepages = {xi.value_or(0.0), eta.value_or(0.0), phi_per_m.value_or(0.0)};
    o.validate();
  }
  interop::CliContactInput in;
  in.lateral_m = lateral_m, in.yaw_rad = yaw_rad, in.roll_rad = roll_rad, in.approach_m = approach_m;
  in.speed_m_s = speed_m_s;
  if (side == "left") in.sides = {Side::Left};
  else if (side == "right") in.sides = {Side::Right};
  else if (side != "both") throw InputError("side must be 'left', 'right' or 'both', not '" + side + "'");
  std::vector<WheelContactReport> reports;
  {
    py::gil_scoped_release release;
    reports = interop::SolveLikeCli(*track.geometry, in, o);
  }
  py::list out;
  for (const WheelContactReport& r : reports) out.append(WheelDict(*track.geometry, r, fields));
  return out;
}

py::dict ContactAtPose(const Track& track, const std::string& side, double lateral_m, double vertical_m,
                       double roll_rad, double yaw_rad, double speed_m_s, double lateral_velocity_m_s,
                       double yaw_rate_rad_s, std::optional<double> axle_angular_velocity_rad_s,
                       const std::string& model, double load_N, double mu, double shear_modulus_Pa,
                       double poisson_ratio, int grid, bool fields, double exact_element_m) {
  const WheelContactOptions o =
      ContactOptions(model, load_N, mu, shear_modulus_Pa, poisson_ratio, grid, fields, exact_element_m);
  require_finite(lateral_m, "lateral_m");
  require_finite(vertical_m, "vertical_m");
  require_finite(roll_rad, "roll_rad");
  RequireWheelsetYaw(yaw_rad, "yaw_rad");
  Side s = Side::Left;
  if (side == "right") s = Side::Right;
  else if (side != "left") throw InputError("side must be 'left' or 'right', not '" + side + "'");
  const double r0 = track.geometry->setup().nominal_radius_m[0];
  const WheelsetVelocity v{speed_m_s, lateral_velocity_m_s, yaw_rate_rad_s,
                           axle_angular_velocity_rad_s.value_or(speed_m_s / r0)};
  RequireRollingVelocity(v, r0, "velocity");
  WheelContactReport r;
  {
    py::gil_scoped_release release;
    r = SolveWheelContact(*track.geometry, s, WheelsetPose{lateral_m, vertical_m, roll_rad, yaw_rad}, v, o);
  }
  return WheelDict(*track.geometry, r, fields);
}

// One wheel from a contact look-up table (contact_lut.hpp) at (lateral_m, yaw_rad) and load_N: model, material and
// elastic flange are the table's; track must be the table's (InputError otherwise).
py::dict LutEvaluate(const ContactLut& lut, const Track& track, const std::string& side, double lateral_m,
                     double yaw_rad, double load_N, double speed_m_s, double lateral_velocity_m_s,
                     double yaw_rate_rad_s, std::optional<double> axle_angular_velocity_rad_s, double mu, int grid,
                     const std::string& load_balance, const std::string& creep_force) {
  Side s = Side::Left;
  if (side == "right") s = Side::Right;
  else if (side != "left") throw InputError("side must be 'left' or 'right', not '" + side + "'");
  WheelContactOptions o;
  o.model = lut.header.model;
  o.material = lut.header.material;
  o.max_touching_contact_angle_rad = lut.header.max_touching_contact_angle_rad;
  o.vertical_load_N = load_N;
  o.friction_coefficient = mu;
  o.fastsim_elements = grid;
  o.load_balance = ParseLoadBalance(load_balance);
  const double r0 = track.geometry->setup().nominal_radius_m[0];
  const WheelsetVelocity v{speed_m_s, lateral_velocity_m_s, yaw_rate_rad_s,
                           axle_angular_velocity_rad_s.value_or(speed_m_s / r0)};
  RequireWheelsetYaw(yaw_rad, "yaw_rad");
  RequireRollingVelocity(v, r0, "velocity");
  LutEvaluationOptions evaluation;
  evaluation.creep_force = ParseLutCreepForce(creep_force);
  // the table's geometry (contact_lut.hpp): another wheel or rail is refused, not answered from the table
  if (!lut.header.geometry_digest.empty()) {
    if (track.lut_digest.empty()) track.lut_digest = ContactLutGeometryDigest(*track.geometry);
    CheckContactLutGeometryDigest(lut, track.lut_digest);
  }
  WheelContactReport r;
  {
    py::gil_scoped_release release;
    r = EvaluateContactLut(lut, *track.geometry, s, WheelsetPose{lateral_m, 0.0, 0.0, yaw_rad}, v, o, nullptr,
                           evaluation);
  }
  return WheelDict(*track.geometry, r, false);
}

py::list Manchester(const std::string& model, bool creepages_from_file, const std::string& data_dir,
                    int fastsim_elements) {
  ManchesterOptions o;
  o.model = ParseContactModel(model);
  o.creepages_from_file = creepages_from_file;
  o.fastsim_elements = fastsim_elements;
  std::vector<ManchesterComparison> rows;
  {
    py::gil_scoped_release release;
    rows = RunManchesterA22(data_dir, o);
  }
  py::list out;
  for (const ManchesterComparison& r : rows) {
    const ManchesterReferenceCase& c = r.reference;
    py::dict ref;
    ref["case"] = c.id, ref["y_ws_mm"] = c.y_ws_mm, ref["yaw_mrad"] = c.yaw_mrad, ref["roll_rad"] = c.roll_rad;
    ref["y_cp_rail_mm"] = c.y_cp_rail_mm, ref["delta_cp_rad"] = c.delta_cp_rad, ref["fn_N"] = c.fn_N;
    ref["fx_N"] = c.fx_N, ref["fs_N"] = c.fs_N, ref["mn_Nmm"] = c.mn_Nmm, ref["xi"] = c.xi, ref["eta"] = c.eta;
    ref["phi_per_mm"] = c.phi_per_mm, ref["p_max_MPa"] = c.p_max_MPa, ref["area_mm2"] = c.area_mm2;
    py::dict d;
    d["reference"] = ref;
    d["patches"] = r.patches, d["fn_N"] = r.fn_N, d["fx_N"] = r.fx_N, d["fs_N"] = r.fs_N;
    d["pmax_MPa"] = r.pmax_MPa, d["area_mm2"] = r.area_mm2, d["y_cp_mm"] = r.y_cp_mm, d["delta_rad"] = r.delta_rad;
    d["err_fn"] = r.err_fn, d["err_pmax"] = r.err_pmax, d["err_area"] = r.err_area;
    d["err_fx_N"] = r.err_fx_N, d["err_fs_N"] = r.err_fs_N;
    d["status"] = to_string(r.report.status);
    out.append(d);
  }
  return out;
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "Conforma: conformal wheel-rail contact (C++ core). SI units everywhere (m, rad, N, Pa).";
  py::register_exception<InputError>(m, "InputError", PyExc_ValueError);
  m.attr("default_shared_data") = SharedDataDir();  // $CONFORMA_DATA_DIR or the built-in default, at import

  py::class_<Profile>(m, "Profile", R"doc(A wheel or rail cross-section profile (metres).

Conventions (include/conforma/profile.hpp): y towards the FIELD side; rail z up from the rail top; wheel z = radial
height above the taping line (flange at negative y, flange back at -0.070 m for S1002).)doc")
      .def_property_readonly("kind", [](const Profile& p) { return std::string(to_string(p.kind())); },
                             "'wheel' or 'rail'")
      .def_property_readonly("source", &Profile::source, "file or generator the profile came from")
      .def_property_readonly("length_m", &Profile::length, "total arc length [m]")
      .def_property_readonly("y_min_m", &Profile::y_min)
      .def_property_readonly("y_max_m", &Profile::y_max)
      .def(
          "points",
          [](const Profile& p, std::optional<double> spacing_m) {
            return conforma::python::PointsArray(spacing_m ? p.sample(*spacing_m) : p.samples());
          },
          py::arg("spacing_m") = py::none(),
          "(N, 2) array of (y, z) [m] along the curve, uniform in arc length (the stored samples by default)")
      .def(
          "height_at",
          [](const Profile& p, double y_m) {
            if (std::isnan(y_m)) throw InputError("height_at: y_m is NaN");
            return p.height_at(y_m);
          },
          py::arg("y_m"), "z [m] at lateral position y, or None outside")
      .def(
          "dimensions",
          [](const Profile& p, double flange_back_y_m, double taping_line_y_m) {
            return conforma::python::DimensionsDict(MeasureWheelDimensions(p, flange_back_y_m, taping_line_y_m));
          },
          py::arg("flange_back_y_m") = -0.070, py::arg("taping_line_y_m") = 0.0,
          "Flange dimensions Sd, Sh, qR (EN 15313) of a wheel profile: dict with sd_m, sh_m, qr_m (and _mm)")
      .def(
          "save_simpack", [](const Profile& p, const std::string& path) { SaveProfileSimpack(p, path); },
          py::arg("path"), "write a Simpack .prw (wheel) / .prr (rail) file in mm")
      .def(
          "save_csv", [](const Profile& p, const std::string& path) { SaveProfileCsv(p, path); }, py::arg("path"),
          "write 'y_mm,z_mm' CSV")
      .def("__repr__", [](const Profile& p) {
        return "<conforma.Profile " + std::string(to_string(p.kind())) + " '" + p.source() + "' y " +
               std::to_string(p.y_min() * 1e3) + ".." + std::to_string(p.y_max() * 1e3) + " mm>";
      });

  m.def("s1002", []() { return MakeS1002(); }, "The S1002 wheel profile generated from its standard definition.");
  m.def(
      "rail",
      [](const std::string& section, double inclination_rad) {
        RailSection s;
        if (FindBuiltInRail(section, &s)) return MakeRail(s, inclination_rad);
        throw InputError("unknown rail section '" + section + "' (expected " + BuiltInRailNames() + ")");
      },
      py::arg("section") = "60E1", py::arg("inclination_rad") = 0.0,
      "EN 13674 rail head ('60E1', '54E1', '50E6', '50E4') canted by inclination_rad, origin at its highest point.");
  m.def(
      "load_profile",
      [](const std::string& path, std::optional<std::string> kind, double smoothing_rms_m, bool mirror_y,
         bool mirror_z, double length_unit_m) {
        ProfileReadOptions o;
        if (kind) o.kind = conforma::python::KindFrom(*kind);
        o.fit.smoothing_rms_m = smoothing_rms_m;
        o.mirror_y = mirror_y, o.mirror_z = mirror_z, o.length_unit_m = length_unit_m;
        return LoadProfile(path, o);
      },
      py::arg("path"), py::arg("kind") = py::none(), py::arg("smoothing_rms_m") = 0.0, py::arg("mirror_y") = false,
      py::arg("mirror_z") = false, py::arg("length_unit_m") = 1e-3,
      "Read a profile file: Simpack .prw/.prr, MiniProf .whl/.ban, or two columns .txt/.csv/.dat (kind "
      "'wheel'/'rail' required for those). Raises InputError 'file:line: reason' on malformed files.");
  m.def(
      "profile_from_points",
      [](py::array_t<double, py::array::c_style | py::array::forcecast> points, const std::string& kind,
         double smoothing_rms_m) {
        if (points.ndim() != 2 || points.shape(1) != 2) throw InputError("points must be an (N, 2) array of (y, z) [m]");
        std::vector<Eigen::Vector2d> pts(static_cast<size_t>(points.shape(0)));
        auto v = points.unchecked<2>();
        for (py::ssize_t i = 0; i < points.shape(0); ++i) pts[static_cast<size_t>(i)] = {v(i, 0), v(i, 1)};
        ProfileFitOptions fit;
        fit.smoothing_rms_m = smoothing_rms_m;
        return ProfileFromCheckedPoints(std::move(pts), conforma::python::KindFrom(kind), fit, "python points");
      },
      py::arg("points"), py::arg("kind"), py::arg("smoothing_rms_m") = 0.0,
      "Profile from an (N, 2) array of (y, z) in metres (conventions of Profile).");
  m.def(
      "wheel_dimensions",
      [](const Profile& p, double flange_back_y_m, double taping_line_y_m) {
        return conforma::python::DimensionsDict(MeasureWheelDimensions(p, flange_back_y_m, taping_line_y_m));
      },
      py::arg("wheel"), py::arg("flange_back_y_m") = -0.070, py::arg("taping_line_y_m") = 0.0,
      "Sd, Sh, qR of a wheel profile (dict with sd_m, sh_m, qr_m, sd_mm, sh_mm, qr_mm and the points used).");

  py::class_<Track>(m, "Track", R"doc(Wheelset on straight track: both wheels share one wheel profile, both rails one
rail profile (the same construction as `conforma contact --wheel ... --rail ...`).

wheel: 'S1002', a file path or a Profile; rail: '60E1', '54E1', '50E6', '50E4', a file path or a Profile.
inclination_rad: rail cant applied by the track; default 1:40 for built-in rail names, 0 for files and Profiles.)doc")
      .def(py::init(&MakeTrack), py::arg("wheel") = "S1002", py::arg("rail") = "60E1",
           py::arg("inclination_rad") = py::none(), py::arg("gauge_m") = 1.435, py::arg("gauge_height_m") = 0.014,
           py::arg("flange_back_distance_m") = 1.360, py::arg("flange_back_position_m") = -0.070,
           py::arg("nominal_radius_m") = 0.46)
      .def_property_readonly("nominal_radius_m", [](const Track& t) { return t.geometry->setup().nominal_radius_m[0]; })
      .def(
          "mounted_rail", [](const Track& t, const std::string& side) {
            if (side != "left" && side != "right") throw InputError("side must be 'left' or 'right', not '" + side + "'");
            return t.geometry->mounted_rail(side == "right" ? Side::Right : Side::Left);
          },
          py::arg("side") = "left", "the rail profile as mounted (inclined, origin at its highest point)")
      .def(
          "rigid_equilibrium",
          [](const Track& t, double lateral_m, double yaw_rad) {
            RequireWheelsetYaw(yaw_rad, "yaw_rad");
            const EquilibriumResult e = t.geometry->SolveRigidEquilibrium(lateral_m, yaw_rad);
            py::dict d;
            d["status"] = to_string(e.status);
            d["y_m"] = e.pose.lateral_m, d["z_m"] = e.pose.vertical_m, d["roll_rad"] = e.pose.roll_rad;
            d["yaw_rad"] = e.pose.yaw_rad, d["rolling_radius_difference_m"] = e.rolling_radius_difference_m;
            return d;
          },
          py::arg("lateral_m"), py::arg("yaw_rad") = 0.0,
          "Vertical position and roll at which both wheels touch their rails (rigid).");

  m.def("contact", &Contact, py::arg("track"), py::arg("lateral_m") = 0.0, py::arg("yaw_rad") = 0.0,
        py::arg("roll_rad") = py::none(), py::arg("model") = "hertz", py::arg("load_N") = 10e3,
        py::arg("speed_m_s") = 2.0, py::arg("mu") = 0.3, py::arg("shear_modulus_Pa") = 82e9,
        py::arg("poisson_ratio") = 0.28, py::arg("grid") = 30, py::arg("approach_m") = 0.05e-3,
        py::arg("side") = "both", py::arg("xi") = py::none(), py::arg("eta") = py::none(),
        py::arg("phi_per_m") = py::none(), py::arg("fields") = true,
        py::arg("exact_element_m") = WheelContactOptions{}.exact_element_size_m,
        R"doc(Contact of one wheelset pose, exactly as `conforma contact` (same forces to the last bit).

The wheelset is placed at lateral_m (+ towards the left rail) and yaw_rad in rigid contact with both rails (roll
from that equilibrium unless roll_rad is given), then each wheel is pushed down until it carries load_N (load
control), or with load_N < 0 lowered by approach_m (approach mode). Creepages from pure rolling at speed_m_s
unless xi / eta / phi_per_m are given. model: 'hertz', 'kp', 'kpec', 'conformal', 'auto', 'exact' (BEM + Kalker's
exact tangential theory; 'reference' is accepted for it; exact_element_m: its element size, default 0.2 mm).

Returns a list of wheel dicts (side, status, pose, vertical_force_N, lateral_force_N, patches). Each patch dict has
the keys of `conforma contact --json` (fn_N, fx_N, fy_N, mz_Nm, pmax_Pa, area_m2, contact_angle_rad, xi, eta,
phi_per_m, ...; forces on the wheel in the patch's contact frame) plus force_track_N / contact_point_track_m in
the track frame and, with fields=True, 'fields': NumPy arrays per element -- grid coordinates x_m (along the
track), s_m (along the rail profile from the patch reference point), rail_s_m, wheel_y_m, area_m2, length_x_m, and
pressure_Pa, traction_x_Pa, traction_s_Pa, slip_x, slip_s, adhesion (bool), wear_index_Pa = |p_t . slip|.)doc");
  m.def("contact_at_pose", &ContactAtPose, py::arg("track"), py::arg("side"), py::arg("lateral_m"),
        py::arg("vertical_m"), py::arg("roll_rad") = 0.0, py::arg("yaw_rad") = 0.0, py::arg("speed_m_s") = 2.0,
        py::arg("lateral_velocity_m_s") = 0.0, py::arg("yaw_rate_rad_s") = 0.0,
        py::arg("axle_angular_velocity_rad_s") = py::none(), py::arg("model") = "hertz", py::arg("load_N") = -1.0,
        py::arg("mu") = 0.3, py::arg("shear_modulus_Pa") = 82e9, py::arg("poisson_ratio") = 0.28,
        py::arg("grid") = 30, py::arg("fields") = true,
        py::arg("exact_element_m") = WheelContactOptions{}.exact_element_size_m,
        "One wheel at a given wheelset pose and velocities (the multibody entry point); load_N < 0 (default): "
        "pose as given, otherwise load control starting from vertical_m. Returns a wheel dict as contact().");
  py::class_<ContactLut, std::shared_ptr<ContactLut>>(m, "ContactLut", R"doc(A contact look-up table file of
`conforma lut build` (HDF5; include/conforma/contact_lut.hpp), loaded once and evaluated at any pose inside it.)doc")
      .def(py::init([](const std::string& path) { return std::make_shared<ContactLut>(LoadContactLut(path)); }),
           py::arg("path"))
      .def_property_readonly("model", [](const ContactLut& l) { return std::string(to_string(l.header.model)); })
      .def_property_readonly("wheel_profile", [](const ContactLut& l) { return l.header.wheel_profile; })
      .def_property_readonly("rail_profile", [](const ContactLut& l) { return l.header.rail_profile; })
      .def_property_readonly("lateral_m", [](const ContactLut& l) { return l.grid.lateral_m; })
      .def_property_readonly("yaw_rad", [](const ContactLut& l) { return l.grid.yaw_rad; })
      .def_property_readonly("load_N", [](const ContactLut& l) { return l.grid.load_N; })
      .def("evaluate", &LutEvaluate, py::arg("track"), py::arg("side"), py::arg("lateral_m"), py::arg("yaw_rad") = 0.0,
           py::arg("load_N") = 50e3, py::arg("speed_m_s") = 2.0, py::arg("lateral_velocity_m_s") = 0.0,
           py::arg("yaw_rate_rad_s") = 0.0, py::arg("axle_angular_velocity_rad_s") = py::none(), py::arg("mu") = 0.3,
           py::arg("grid") = 30, py::arg("load_balance") = "total", py::arg("creep_force") = "fastsim",
           "One wheel from the table at (lateral_m, yaw_rad) carrying load_N (vertical position and roll of the "
           "rigid equilibrium, as the table); track must be the one the table was made for. creep_force: 'fastsim' "
           "(as the direct solver) or 'polach' (closed form on each patch's ellipse, for speed). Returns a wheel "
           "dict as contact() without fields (conforma.ContactLut, the package's subclass, adds 'complete' / 'problems'); "
           "outside the table InputError naming the axis.");
  m.def("manchester", &Manchester, py::arg("model") = "conformal", py::arg("creepages_from_file") = true,
        py::arg("data_dir") = SharedDataDir(), py::arg("fastsim_elements") = 30,
        "Manchester benchmark A-2.2 (left wheel, 21 cases) against CONTACT's results: one dict per case with the "
        "reference values and the relative/absolute errors (as `conforma mbench`).");
  conforma::python::BindWear(m);
}
