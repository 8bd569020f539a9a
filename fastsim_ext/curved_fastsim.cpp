// Curved-patch FASTSIM (paper 003 §4.2 eqs. 9-12; the derivation of L(s^r) is in curved_fastsim.hpp).
#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "conforma/curved_fastsim.hpp"
#include "conforma/error.hpp"

namespace conforma {

namespace {

// Antiderivative of the semi-ellipse shape sqrt(1 - t^2), t in [-1, 1].
double SemiEllipseIntegral(double t) {
  t = std::max(-1.0, std::min(1.0, t));
  return 0.5 * (t * std::sqrt(std::max(0.0, 1.0 - t * t)) + std::asin(t));
}

void ValidateStrip(const KpStrip& k, size_t j) {
  if (!std::isfinite(k.s_m) || !std::isfinite(k.ds_m) || k.ds_m < 0.0 || !std::isfinite(k.x_centre_m) ||
      !std::isfinite(k.half_length_m) || k.half_length_m < 0.0 || !std::isfinite(k.alpha_rad) ||
      !std::isfinite(k.peak_pressure_Pa) || k.peak_pressure_Pa < 0.0 || !k.position_m.allFinite())
    throw InputError("SolveCurvedFastsim: KP strip " + std::to_string(j) + " has NaN or negative entries");
}

// Builds the FASTSIM strip patch (element i of strip j: x from x_lead - (i+1) dx to x_lead - i dx) with the exact
// element mean of the KP semi-ellipse as bound (eq. 10). Returns the discrete load.
double BuildPatch(const KpResult& normal, const CurvedFastsimOptions& options, CurvedFastsimWorkspace* w,
                  std::vector<int>* first_element) {
  const int nx = options.elements_per_strip;
  const size_t ns = normal.strips.size();
  w->strips.resize(ns);
  first_element->resize(ns);
  w->patch.bound_pressure_Pa.resize(ns * static_cast<size_t>(nx));
  w->patch.friction_coefficient.clear();
  // Element means of the normalised semi-ellipse (eq. 10): the same for every strip (equal elements in t = x/c_j).
  w->shape_means.resize(nx);
  double upper = SemiEllipseIntegral(1.0);
  for (int i = 0; i < nx; ++i) {
    const double lower = SemiEllipseIntegral(1.0 - 2.0 * (i + 1) / nx);
    w->shape_means[i] = (upper - lower) * (0.5 * nx);
    upper = lower;
  }
  double load = 0.0;
  int next = 0;
  for (size_t j = 0; j < ns; ++j) {
    const KpStrip& k = normal.strips[j];
    ValidateStrip(k, j);
    FastsimStrip& s = w->strips[j];
    const bool in_contact = k.half_length_m > 0.0 && k.ds_m > 0.0;
    s.y_m = k.s_m - options.spin_origin_s_m;
    s.width_m = k.ds_m;
    s.x_lead_m = k.x_centre_m + k.half_length_m - options.spin_origin_x_m;
    s.x_trail_m = k.x_centre_m - k.half_length_m - options.spin_origin_x_m;
    s.first_element = next;
    s.n_elements = in_contact ? nx : 0;
    (*first_element)[j] = next;
    double* bound = w->patch.bound_pressure_Pa.data() + next;
    if (in_contact) {
      double strip_sum = 0.0;
      for (int i = 0; i < nx; ++i) {
        bound[i] = k.peak_pressure_Pa * w->shape_means[i];  // element mean of eq. 10
        strip_sum += bound[i];
      }
      load += strip_sum * (2.0 * k.half_length_m / nx) * k.ds_m;
      next += nx;
    }
  }
  w->patch.bound_pressure_Pa.resize(next);
  return load;
}

// Totals of a patch solved strip by strip, summed in strip order (the same arithmetic for both per-strip paths)
struct StripSums {
  double fx = 0.0, fy = 0.0, mz = 0.0, adhesion = 0.0, slip = 0.0, power = 0.0;
  template <class Totals>
  void Add(const Totals& t) {
    fx += t.fx_N;
    fy += t.fy_N;
    mz += t.mz_Nm;
    adhesion += t.adhesion_area_m2;
    slip += t.slip_area_m2;
    power += t.frictional_power_W;
  }
  void WriteTo(FastsimResult* field) const {
    field->fx_N = fx;
    field->fy_N = fy;
    field->mz_Nm = mz;
    field->adhesion_area_m2 = adhesion;
    field->slip_area_m2 = slip;
    field->frictional_power_W = power;
    field->status = adhesion > 0.0 ? FastsimStatus::Ok : FastsimStatus::FullSlip;
  }
};

}  // namespace

void SolveCurvedFastsim(const KpResult& normal, const CurvedFastsimInput& input, const CurvedFastsimOptions& options,
                        CurvedFastsimWorkspace* workspace, CurvedFastsimResult* result) {
  if (workspace == nullptr || result == nullptr) throw InputError("SolveCurvedFastsim: workspace/result must not be null");
  if (options.elements_per_strip < 1) throw InputError("SolveCurvedFastsim: elements_per_strip must be >= 1");
  require_positive(options.slope_reduction, "slope_reduction");
  require_non_negative(options.load_N, "load_N");
  require_finite(options.spin_origin_x_m, "spin_origin_x_m");
  require_finite(options.spin_origin_s_m, "spin_origin_s_m");
  input.friction.validate();
  input.material.validate();
  const size_t ns = normal.strips.size();
  const size_t nc = input.strip_creepages.size(), nf = input.strip_flexibilities.size();
  if (nc != 1 && nc != ns)
    throw InputError("SolveCurvedFastsim: strip_creepages has " + std::to_string(nc) + " entries, expected 1 or " +
                     std::to_string(ns));
  if (nf > 1 && nf != ns)
    throw InputError("SolveCurvedFastsim: strip_flexibilities has " + std::to_string(nf) + " entries, expected 0, 1 or " +
                     std::to_string(ns));
  // Spin about the patch centre (curved_fastsim.hpp, docs/physics-reference.md §5.4): the origin moved to the
  // c^2-weighted centroid (x_c, s_c) of the strips, the creepages moved with it (w_x = xi - phi y, w_s = eta + phi x
  // unchanged: xi' = xi - phi (s_c - s_o), eta' = eta + phi (x_c - x_o)).
  CurvedFastsimOptions centred = options;
  const std::vector<FastsimCreepages>* creepages = &input.strip_creepages;
  if (options.spin_about_patch_centre) {
    double w = 0.0, ws = 0.0, wx = 0.0;
    for (const KpStrip& k : normal.strips) {
      if (!(k.half_length_m > 0.0) || !(k.ds_m > 0.0)) continue;
      const double weight = k.half_length_m * k.half_length_m * k.ds_m;
      w += weight, ws += weight * k.s_m, wx += weight * k.x_centre_m;
    }
    if (w > 0.0) {
      centred.spin_origin_s_m = ws / w;
      centred.spin_origin_x_m = wx / w;
      const double ds = centred.spin_origin_s_m - options.spin_origin_s_m;
      const double dx = centred.spin_origin_x_m - options.spin_origin_x_m;
      workspace->centred_creepages = input.strip_creepages;
      for (FastsimCreepages& c : workspace->centred_creepages) c.xi -= c.phi_per_m * ds, c.eta += c.phi_per_m * dx;
      creepages = &workspace->centred_creepages;
    }
  }
  CurvedFastsimResult& r = *result;
  r.fx_N = r.fs_N = r.mz_Nm = 0.0;
  r.force_reference_N.setZero();
  r.moment_reference_Nm.setZero();
  r.adhesion_area_m2 = r.slip_area_m2 = r.frictional_power_W = r.bound_load_N = 0.0;
  r.status = FastsimStatus::NoContact;
  r.sdec = ReduceToSdec(normal, input.material);

  double load = BuildPatch(normal, centred, workspace, &r.strip_first_element);
  if (options.load_N > 0.0 && load > 0.0) {
    const double scale = options.load_N / load;
    for (double& p : workspace->patch.bound_pressure_Pa) p *= scale;
    load = options.load_N;
  }
  r.bound_load_N = load;
  if (load <= 0.0 || workspace->patch.bound_pressure_Pa.empty() || r.sdec.status != SdecStatus::Ok) {
    r.field = FastsimResult{};
    r.field.status = FastsimStatus::NoContact;
    return;
  }

  // Flexibilities (curved_fastsim.hpp): SDEC or given, divided by k, optionally blended.
  auto flexibility_of = [&](size_t j) {
    const FastsimFlexibilities& base = nf == 0 ? r.sdec.flexibilities : input.strip_flexibilities[nf == 1 ? 0 : j];
    return ReducedFlexibilities(base, options.slope_reduction);
  };
  FastsimFlexibilities uniform = flexibility_of(0);
  if (options.blend_flexibilities && nf <= 1) {
    size_t ref = 0;  // creepages of the strip at the longest-strip line
    for (size_t j = 0; j < ns; ++j)
      if (std::abs(normal.strips[j].s_m - r.sdec.longest_strip_s_m) < std::abs(normal.strips[ref].s_m - r.sdec.longest_strip_s_m)) ref = j;
    uniform = BlendedFlexibilities(uniform, r.sdec.a_m, r.sdec.b_m, r.sdec.coefficients, input.material.shear_modulus_Pa,
                                   input.friction.static_value(), load, (*creepages)[nc == 1 ? 0 : ref]);
  }
  r.flexibilities = uniform;
  // Strip-wise flexibilities from the local half-length (curved_fastsim.hpp, docs/physics-reference.md §5.4): the
  // uniform (SDEC, reduced, blended) values scaled by kappa_i c_j / a, kappa_1 = kappa_2 = 3 pi/8 (L1_j = pi c_j/(C11 G)),
  // kappa_3 = 32/(9 pi) (L3_j = 8 c_j sqrt(a/b)/(9 C23 G)).
  std::vector<FastsimFlexibilities>& local = workspace->strip_flexibilities;
  const bool use_local = options.local_flexibilities && nf == 0;
  if (use_local) {
    const double kappa12 = 3.0 * M_PI / 8.0, kappa3 = 32.0 / (9.0 * M_PI);
    local.assign(ns, uniform);
    for (size_t j = 0; j < ns; ++j) {
      const double c = normal.strips[j].half_length_m;
      if (!(c > 0.0)) continue;  // not in contact: no elements
      const double ratio = c / r.sdec.a_m;
      local[j].L1 = uniform.L1 * kappa12 * ratio;
      local[j].L2 = uniform.L2 * kappa12 * ratio;
      local[j].L3 = uniform.L3 * kappa3 * ratio;
    }
  }

  FastsimOptions core_options;
  core_options.marching = options.marching;
  FastsimPatch& patch = workspace->patch;
  if (nc == 1 && nf <= 1 && !use_local) {  // uniform: one call of the strip core for the whole patch
    patch.strips.assign(workspace->strips.begin(), workspace->strips.end());
    SolveFastsimStripsWithLaw(patch, uniform, (*creepages)[0], input.friction, input.rolling_speed_m_per_s,
                              core_options, &r.field);
  } else if (nc == ns && nf <= 1 && !use_local && input.friction.is_constant()) {
    // per-strip creepages, one flexibility, constant friction: the core marches every strip with its own creepages
    // (as one call per strip below, the same arithmetic), strip totals summed in strip order
    input.friction.validate();
    patch.strips.assign(workspace->strips.begin(), workspace->strips.end());
    SolveFastsimStripsEach(patch, uniform, *creepages, input.friction.parameters[0],
                           input.rolling_speed_m_per_s, core_options, &r.field, &workspace->strip_totals);
    StripSums sums;
    for (const FastsimStripTotals& t : workspace->strip_totals) sums.Add(t);
    sums.WriteTo(&r.field);
  } else {  // per strip: the core on a one-strip view of the same element arrays
    patch.strips.resize(1);
    StripSums sums;
    for (size_t j = 0; j < ns; ++j) {
      patch.strips[0] = workspace->strips[j];
      const FastsimFlexibilities L = use_local ? local[j] : nf > 1 ? flexibility_of(j) : uniform;
      SolveFastsimStripsWithLaw(patch, L, (*creepages)[nc == 1 ? 0 : j], input.friction,
                                input.rolling_speed_m_per_s, core_options, &r.field);
      sums.Add(r.field);
    }
    sums.WriteTo(&r.field);
  }
  if (centred.spin_origin_s_m != options.spin_origin_s_m || centred.spin_origin_x_m != options.spin_origin_x_m) {
    // the field and the curvilinear moment back to the given origin (CurvedFastsimResult's frame)
    const double ds = centred.spin_origin_s_m - options.spin_origin_s_m;
    const double dx = centred.spin_origin_x_m - options.spin_origin_x_m;
    for (double& x : r.field.x_m) x += dx;
    for (double& y : r.field.y_m) y += ds;
    r.field.mz_Nm += dx * r.field.fy_N - ds * r.field.fx_N;
  }
  r.status = r.field.status;
  r.fx_N = r.field.fx_N;
  r.fs_N = r.field.fy_N;
  r.mz_Nm = r.field.mz_Nm;
  r.adhesion_area_m2 = r.field.adhesion_area_m2;
  r.slip_area_m2 = r.field.slip_area_m2;
  r.frictional_power_W = r.field.frictional_power_W;

  // Rotation into the patch reference frame (x, t0, n0): p = p_x e1 + p_s t_j, t_j = (cos a) t0 - (sin a) n0.
  for (size_t j = 0; j < ns; ++j) {
    const FastsimStrip& s = workspace->strips[j];
    if (s.n_elements == 0) continue;
    double sx = 0.0, ss = 0.0, sxs = 0.0, sxx = 0.0;  // sums p_x dA, p_s dA, x p_s dA, x p_x dA
    for (int i = 0; i < s.n_elements; ++i) {
      const int e = s.first_element + i;
      const double dA = r.field.area_m2[e], x = r.field.x_m[e] + options.spin_origin_x_m;
      sx += r.field.px_Pa[e] * dA;
      ss += r.field.py_Pa[e] * dA;
      sxs += x * r.field.py_Pa[e] * dA;
      sxx += x * r.field.px_Pa[e] * dA;
    }
    const double ca = std::cos(normal.strips[j].alpha_rad), sa = std::sin(normal.strips[j].alpha_rad);
    const Eigen::Vector3d force(sx, ss * ca, -ss * sa);
    const Eigen::Vector3d first_moment(sxx, sxs * ca, -sxs * sa);  // sum x f dA
    const Eigen::Vector3d arm(0.0, normal.strips[j].position_m.x(), normal.strips[j].position_m.y());
    r.force_reference_N += force;
    // sum (x e1 + arm) x f dA = e1 x (sum x f dA) + arm x F_j
    r.moment_reference_Nm += Eigen::Vector3d::UnitX().cross(first_moment) + arm.cross(force);
  }
}

CurvedFastsimResult SolveCurvedFastsim(const KpResult& normal, const CurvedFastsimInput& input,
                                       const CurvedFastsimOptions& options) {
  CurvedFastsimWorkspace workspace;
  CurvedFastsimResult result;
  SolveCurvedFastsim(normal, input, options, &workspace, &result);
  return result;
}

CurvedFastsimResult SolveFastsimOnKpPatch(const KpResult& normal, const FastsimCreepages& creepages,
                                          const FrictionLaw& friction, const Material& material,
                                          const CurvedFastsimOptions& options) {
  CurvedFastsimInput input;
  input.strip_creepages = {creepages};
  input.friction = friction;
  input.material = material;
  return SolveCurvedFastsim(normal, input, options);
}

Eigen::Vector3d ReferenceToRailProfile(const Eigen::Vector3d& v, const PatchGeometry& geometry) {
  const Eigen::Vector2d n0 = geometry.reference_normal.normalized();
  const Eigen::Vector2d t0(n0.y(), -n0.x());
  const Eigen::Vector2d yz = v.y() * t0 + v.z() * n0;
  return Eigen::Vector3d(v.x(), yz.x(), yz.y());
}

}  // namespace conforma
