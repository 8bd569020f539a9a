// Kik-Piotrowski normal contact for one patch, approach given: planar KP, KPEC, conformal KP.
// docs/physics-reference.md §3.1-3.3, §4, §9; paper 003 eqs. 2-8 and 13.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "conforma/conformity.hpp"
#include "conforma/error.hpp"
#include "conforma/hertz.hpp"
#include "conforma/influence.hpp"
#include "conforma/kik_piotrowski.hpp"
#include "conforma/root_finding.hpp"
#include "kp_patch_interpolant.hpp"
#include "kp_ranges.hpp"
#include "kp_solver_internal.hpp"
#include "kp_strip_collocation.hpp"
#include "kp_strip_integrals.hpp"
#include "kp_virtual_level.hpp"

namespace conforma {

const char* to_string(KpStatus status) {
  switch (status) {
    case KpStatus::Ok: return "ok";
    case KpStatus::NoContact: return "no_contact";
    case KpStatus::ContactAtPatchBoundary: return "contact_at_patch_boundary";
    case KpStatus::NoEquivalentEllipse: return "no_equivalent_ellipse";
    case KpStatus::InfluenceNotPositive: return "influence_not_positive";
    case KpStatus::LoadNotReached: return "load_not_reached";
  }
  return "unknown";
}

KpOptions PlanarKpOptions(const Material& material) {
  KpOptions options;
  options.material = material;
  return options;
}

KpOptions KpecOptions(const Material& material) {
  KpOptions options = PlanarKpOptions(material);
  options.penetration = KpPenetrationRule::VariableEpsilon;
  return options;
}

KpOptions ConformalKpOptions(const Material& material) {
  KpOptions options = PlanarKpOptions(material);
  options.influence = KpInfluence::BlancoLorenzo;
  return options;
}

KpOptions ConformalKpecOptions(const Material& material) {
  KpOptions options = ConformalKpOptions(material);
  options.penetration = KpPenetrationRule::VariableEpsilon;
  options.pressure = KpPressureRule::StripCollocation;
  return options;
}

namespace {

using kp_detail::PatchInterpolant;

// Position on the rail surface relative to the reference point (s = 0), (t0, n0) components:
// integral of the tangent (cos alpha, -sin alpha) from 0 to s (the tangent turns with the normal).
Eigen::Vector2d SurfaceStep(const PatchInterpolant& patch, double from, double to) {
  const double mid = 0.5 * (from + to), half = 0.5 * (to - from);
  const double node = 0.5773502691896257 * half;
  const double a1 = patch.alpha(mid - node), a2 = patch.alpha(mid + node);
  return half * Eigen::Vector2d(std::cos(a1) + std::cos(a2), -std::sin(a1) - std::sin(a2));
}

}  // namespace

namespace kp_detail {

void ValidateKpOptions(const KpOptions& options) {
  require_positive(options.virtual_penetration_factor, "KpOptions.virtual_penetration_factor");
  if (options.virtual_penetration_factor > 1.0)
    throw InputError("KpOptions.virtual_penetration_factor must be <= 1, got " +
                     MessageNumber(options.virtual_penetration_factor));
  if (options.strips_across_contact < 3 || options.strips_across_contact > 100000)
    throw InputError("KpOptions.strips_across_contact must lie in [3, 100000], got " +
                     std::to_string(options.strips_across_contact));
  require_finite(options.conformity_threshold_deg, "KpOptions.conformity_threshold_deg");
  if (options.collocation_strips < 2)
    throw InputError("KpOptions.collocation_strips must be >= 2, got " + std::to_string(options.collocation_strips));
}

}  // namespace kp_detail

KpResult SolveKikPiotrowskiForApproach(const PatchGeometry& geometry, double approach_m, const KpOptions& options) {
  require_non_negative(approach_m, "approach_m");
  kp_detail::ValidateKpOptions(options);
  (void)CombinedElasticConstants(options.material);  // material errors before patch errors, as before
  const PatchInterpolant patch(geometry);
  return kp_detail::SolveKikPiotrowskiOnInterpolant(patch, approach_m, options);
}

KpResult kp_detail::SolveKikPiotrowskiOnInterpolant(const PatchInterpolant& patch, double approach_m,
                                                    const KpOptions& options) {
  const ElasticConstants elastic = CombinedElasticConstants(options.material);

  KpResult result;
  result.approach_m = approach_m;
  const double delta = approach_m;
  const double s_contact = patch.MinimumGapLocation();
  const double gap_contact = patch.gap(s_contact);
  result.contact_point_s_m = s_contact;
  result.contact_point_x_m = patch.x_offset(s_contact);
  if (delta <= 0.0) return result;

  // Virtual interpenetration g(s) = eps(s) delta - gap(s) (docs/physics-reference.md §3.1 / §3.3).
  const bool kpec = options.penetration == KpPenetrationRule::VariableEpsilon;
  kp_detail::KpecVirtualLevel kpec_level;
  if (kpec) {
    switch (kp_detail::BuildKpecVirtualLevel(patch, delta, s_contact, options.material, &kpec_level)) {
      case kp_detail::KpecBuild::NoRegion: return result;
      case kp_detail::KpecBuild::NoEllipse: result.status = KpStatus::NoEquivalentEllipse; return result;
      case kp_detail::KpecBuild::Ok: break;
    }
  }
  const std::vector<kp_detail::EquivalentEllipse>& wells = kpec_level.wells;
  const double separation_weight = kpec_level.separation_weight;
  const double eps = options.virtual_penetration_factor;
  auto interpenetration_with_gap = [&](double s, double gap) {
    if (!kpec) return eps * delta - gap;
    return kpec_level.Level(s, delta) - gap;
  };
  auto interpenetration = [&](double s) { return interpenetration_with_gap(s, patch.gap(s)); };
  auto interpenetration_node = [&](size_t k) {  // = interpenetration(nodes[k]): the interpolant is exact at nodes
    return interpenetration_with_gap(patch.nodes()[k], patch.node_gaps()[k]);
  };
  const double g_contact = interpenetration(s_contact);
  if (!(g_contact > 0.0)) return result;
  result.virtual_penetration_m = g_contact + gap_contact;
  // Strips over every lobe of the virtual interpenetration (strips between lobes carry nothing: c_j = 0). The
  // connected lobe around the contact point alone dropped a second lobe until the two joined, and the force then
  // jumped (up to 40 % on worn treads, issue 15); a new lobe enters with zero width.
  std::vector<ContactRange> lobes = FindAllRanges(patch, interpenetration, interpenetration_node, s_contact, g_contact);
  // Separate wells whose virtual lobes have joined stay separate lobes (strips laid per lobe), split where the
  // interpenetration is least near the crest between them: the lobes join there, so the strips do not jump when
  // they do (31 strips over the joined lobe instead of 31 in each moved the force by 1-3 %).
  if (separation_weight > 0.0 && wells.size() > 1) {
    std::vector<double> crests;
    for (const EquivalentEllipse& e : wells)
      for (double c : {e.valley_low, e.valley_high})
        if (std::isfinite(c) && std::find(crests.begin(), crests.end(), c) == crests.end()) crests.push_back(c);
    std::sort(crests.begin(), crests.end());
    const auto& nodes = patch.nodes();
    for (double crest : crests) {
      for (size_t l = 0; l < lobes.size(); ++l) {
        if (!(crest > lobes[l].low && crest < lobes[l].high)) continue;
        // least interpenetration on [crest - 2h, crest + 2h] within the lobe (h: the node spacing there), golden
        // section on either side of the crest (the level has a kink at the crest)
        const size_t i = std::min(static_cast<size_t>(std::lower_bound(nodes.begin(), nodes.end(), crest) - nodes.begin()),
                                  nodes.size() - 1);
        const double h = i > 0 ? nodes[i] - nodes[i - 1] : 0.0;
        double best = crest, best_value = interpenetration(crest);
        for (int side = 0; side < 2; ++side) {
          double a = side == 0 ? std::max(lobes[l].low, crest - 2.0 * h) : crest;
          double b = side == 0 ? crest : std::min(lobes[l].high, crest + 2.0 * h);
          constexpr double kGolden = 0.6180339887498949;
          double x1 = b - kGolden * (b - a), x2 = a + kGolden * (b - a);
          double f1 = interpenetration(x1), f2 = interpenetration(x2);
          for (int it = 0; it < 60 && b - a > 1e-12; ++it) {
            if (f1 < f2) b = x2, x2 = x1, f2 = f1, x1 = b - kGolden * (b - a), f1 = interpenetration(x1);
            else a = x1, x1 = x2, f1 = f2, x2 = a + kGolden * (b - a), f2 = interpenetration(x2);
          }
          const double x = 0.5 * (a + b), f = interpenetration(x);
          if (f < best_value) best = x, best_value = f;
        }
        if (!(best > lobes[l].low && best < lobes[l].high)) break;
        ContactRange upper = lobes[l];
        upper.low = best;
        lobes[l].high = best;
        lobes.insert(lobes.begin() + static_cast<long>(l) + 1, upper);
        break;
      }
    }
  }
  ContactRange range = lobes.front();
  range.high = lobes.back().high;
  for (const ContactRange& lobe : lobes) range.cut |= lobe.cut;

  // Strips over exactly the contact range, strips_across_contact in each lobe.
  const int per_lobe = options.strips_across_contact;
  const std::vector<std::pair<double, double>> edges = StripEdges(lobes, range.low, range.high, per_lobe);
  int n = static_cast<int>(edges.size());  // changes with the cut of the strip collocation
  const double c_contact = std::sqrt(g_contact / patch.curvature(s_contact));
  const double x_contact = result.contact_point_x_m;
  const bool blanco = options.influence == KpInfluence::BlancoLorenzo;
  const double coupling_K = blanco ? CouplingParameter(options.coupling, elastic) : 0.0;
  const double alpha_contact = patch.alpha(s_contact);
  // strips on the given edges, each with the virtual half-length at its centre line
  auto strips_on = [&](const std::vector<std::pair<double, double>>& on) {
    std::vector<KpStrip> laid(on.size());
    for (size_t k = 0; k < on.size(); ++k) {
      KpStrip& strip = laid[k];
      strip.s_m = 0.5 * (on[k].first + on[k].second);
      strip.ds_m = on[k].second - on[k].first;
      strip.x_centre_m = patch.x_offset(strip.s_m);
      strip.alpha_rad = patch.alpha(strip.s_m);
      strip.half_length_m = std::sqrt(std::max(interpenetration(strip.s_m), 0.0) / patch.curvature(strip.s_m));
    }
    return laid;
  };
  result.strips = strips_on(edges);
  double c_max = c_contact;
  std::vector<kp_detail::StripLoad> loads(n);
  for (int j = 0; j < n; ++j) {
    const KpStrip& strip = result.strips[j];
    const double low = edges[j].first, high = edges[j].second;
    c_max = std::max(c_max, strip.half_length_m);
    kp_detail::StripLoad& load = loads[j];
    load.s_low = low;
    load.s_high = high;
    load.half_length = strip.half_length_m;
    load.centre_offset = strip.x_centre_m - x_contact;
    if (blanco) {
      load.alpha_low = patch.alpha(low) - alpha_contact;  // alpha = alpha_J - alpha_I (§4.1)
      load.alpha_high = patch.alpha(high) - alpha_contact;
    }
  }
  // every strip seen from the contact point in one batch (each integral bit-identical to
  // StripNormalDisplacementIntegral strip by strip), summed in strip order
  std::vector<double> integrals(n);
  kp_detail::StripNormalDisplacementIntegrals(loads.data(), n, s_contact, elastic.poisson_ratio, blanco, coupling_K,
                                              integrals.data());
  double influence_sum = 0.0;
  for (int j = 0; j < n; ++j) influence_sum += integrals[j];
  if (!(influence_sum > 0.0)) {
    result.status = KpStatus::InfluenceNotPositive;
    result.strips.clear();
    return result;
  }
  // Paper 003 eq. 8 / docs/physics-reference.md §3.2: u_n(contact point) = delta with p = p0 sqrt(c^2 - x^2) / c_norm.
  const double c_norm = kpec ? c_max : c_contact;
  result.p0_Pa = M_PI * elastic.shear_modulus_Pa * delta * c_norm / influence_sum;
  result.pmax_Pa = result.p0_Pa * c_max / c_norm;
  std::vector<double> peaks(n);
  for (int j = 0; j < n; ++j) peaks[j] = result.p0_Pa * result.strips[j].half_length_m / c_norm;
  if (options.pressure == KpPressureRule::StripCollocation) {
    if (!kp_detail::CollocateStripPressure(patch, lobes, per_lobe, options.collocation_strips, strips_on, delta, elastic,
                                           blanco, coupling_K, &range, &result.strips, &peaks)) {
      result.status = KpStatus::InfluenceNotPositive;
      result.strips.clear();
      return result;
    }
    n = static_cast<int>(result.strips.size());
    result.pmax_Pa = *std::max_element(peaks.begin(), peaks.end());
  }

  // Forces along each strip's own normal n_j = cos(alpha_j) n0 + sin(alpha_j) t0, moments, extents.
  std::vector<double> angles;
  angles.reserve(n + 2);
  angles.push_back(patch.alpha(range.low));
  angles.push_back(patch.alpha(range.high));
  Eigen::Vector2d position = SurfaceStep(patch, 0.0, result.strips[0].s_m);
  double x_low = x_contact - c_contact, x_high = x_contact + c_contact;
  double force_s = 0.0, force_x = 0.0;
  for (int j = 0; j < n; ++j) {
    KpStrip& strip = result.strips[j];
    if (j > 0) position += SurfaceStep(patch, result.strips[j - 1].s_m, strip.s_m);
    strip.position_m = position;
    strip.peak_pressure_Pa = peaks[j];
    strip.force_N = 0.5 * M_PI * strip.peak_pressure_Pa * strip.half_length_m * strip.ds_m;
    const Eigen::Vector2d force(std::sin(strip.alpha_rad) * strip.force_N, std::cos(strip.alpha_rad) * strip.force_N);
    result.force_on_wheel_N += force;
    result.moment_Nm += position.x() * force.y() - position.y() * force.x();
    result.fn_surface_N += strip.force_N;
    result.area_m2 += 2.0 * strip.half_length_m * strip.ds_m;
    force_s += strip.force_N * strip.s_m;
    force_x += strip.force_N * strip.x_centre_m;
    if (strip.half_length_m > 0.0) {
      x_low = std::min(x_low, strip.x_centre_m - strip.half_length_m);
      x_high = std::max(x_high, strip.x_centre_m + strip.half_length_m);
    }
    angles.push_back(strip.alpha_rad);
  }
  result.fs_N = result.force_on_wheel_N.x();
  result.fn_N = result.force_on_wheel_N.y();
  if (result.fn_surface_N > 0.0) {
    result.action_s_m = force_s / result.fn_surface_N;
    result.action_x_m = force_x / result.fn_surface_N;
  }
  result.s_min_m = range.low;
  result.s_max_m = range.high;
  result.width_m = range.high - range.low;
  result.length_m = x_high - x_low;
  const ConformityIndex conformity = ComputeConformityIndex(angles, options.conformity_threshold_deg);
  result.alpha_c_deg = conformity.alpha_c_deg;
  result.is_conformal = conformity.is_conformal;
  result.status = range.cut ? KpStatus::ContactAtPatchBoundary : KpStatus::Ok;
  return result;
}

double KpPressureAt(const KpResult& result, double x_m, double s_m) {
  if (result.strips.empty() || s_m < result.s_min_m || s_m > result.s_max_m) return 0.0;
  for (const KpStrip& strip : result.strips) {
    if (std::abs(s_m - strip.s_m) <= 0.5 * strip.ds_m) {
      if (strip.half_length_m <= 0.0) return 0.0;
      const double t = (x_m - strip.x_centre_m) / strip.half_length_m;
      return std::abs(t) < 1.0 ? strip.peak_pressure_Pa * std::sqrt(1.0 - t * t) : 0.0;
    }
  }
  return 0.0;
}

std::vector<KpPressureElement> SampleKpPressure(const KpResult& result, int elements_along_x) {
  if (elements_along_x < 1) throw InputError("SampleKpPressure: elements_along_x must be >= 1");
  std::vector<KpPressureElement> elements;
  elements.reserve(result.strips.size() * elements_along_x);
  for (const KpStrip& strip : result.strips) {
    if (strip.half_length_m <= 0.0) continue;
    const double dx = 2.0 * strip.half_length_m / elements_along_x;
    for (int i = 0; i < elements_along_x; ++i) {
      KpPressureElement element;
      element.x_m = strip.x_centre_m - strip.half_length_m + (i + 0.5) * dx;
      element.s_m = strip.s_m;
      element.dx_m = dx;
      element.ds_m = strip.ds_m;
      const double t = (element.x_m - strip.x_centre_m) / strip.half_length_m;
      element.pressure_Pa = strip.peak_pressure_Pa * std::sqrt(std::max(1.0 - t * t, 0.0));
      elements.push_back(element);
    }
  }
  return elements;
}

}  // namespace conforma
