// Kik-Piotrowski normal contact for one patch, approach given: planar KP, KPEC, conformal KP.
// docs/physics-reference.md §3.1-3.3, §4, §9; paper 003 eqs. 2-8 and 13.
#include <algorithm>
#include <cmath>
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
#include "kp_solver_internal.hpp"
#include "kp_strip_integrals.hpp"

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

// Strip collocation (docs/physics-reference.md §5.3): cut of the virtual range (fraction of its width) from which a
// second collocation solve is blended in, fully at the upper value
constexpr double kCollocationRecutLow = 0.02;
constexpr double kCollocationRecutHigh = 0.06;
// KPEC (§3.3): total gap between the lobes of the eps = 0.5 region, as a multiple of their summed widths, from which
// the lobes get separate equivalent ellipses (blended in up to the upper value)
constexpr double kKpecSeparateLobesLow = 0.1;
constexpr double kKpecSeparateLobesHigh = 0.3;



// Root of f on [inside, outside] where f(inside) > 0 >= f(outside): Illinois false position.
template <class F>
double EdgeRoot(const F& f, double inside, double f_inside, double outside, double f_outside) {
  IllinoisBracket bracket(inside, f_inside, outside, f_outside);  // "low" = the inside end (root_finding.hpp)
  const double f_scale = 1e-15 * (std::abs(f_inside) + std::abs(f_outside));
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double c = bracket.FalsePosition();
    const double a = bracket.low(), b = bracket.high();
    if (std::abs(b - a) <= 1e-14 * (std::abs(a) + std::abs(b)) + 1e-18) return c;
    const double fc = f(c);
    bracket.Replace(c, fc, fc > 0.0);
    if (std::abs(fc) <= f_scale) return c;
  }
  return 0.5 * (bracket.low() + bracket.high());
}

struct ContactRange {
  double low = 0.0;
  double high = 0.0;
  bool cut = false;  // reached the end of the given strips
};

// The connected range around s_start where f > 0 (f(s_start) > 0). Walks the input nodes outward (f_at_node(k) =
// f(nodes[k]), from the node values without interpolation), then finds each edge on the interpolant.
template <class F, class FNode>
ContactRange FindRange(const PatchInterpolant& patch, const F& f, const FNode& f_at_node, double s_start,
                       double f_start) {
  ContactRange range;
  const auto& nodes = patch.nodes();
  const size_t first_right = static_cast<size_t>(std::upper_bound(nodes.begin(), nodes.end(), s_start) - nodes.begin());
  // right
  {
    double inside = s_start, f_in = f_start;
    bool found = false;
    for (size_t k = first_right; k <= nodes.size() && !found; ++k) {
      const double s = k < nodes.size() ? nodes[k] : patch.domain_high();
      const double value = k < nodes.size() ? f_at_node(k) : f(s);
      if (value <= 0.0) {
        range.high = EdgeRoot(f, inside, f_in, s, value);
        found = true;
      } else {
        inside = s;
        f_in = value;
      }
    }
    if (!found) {
      range.high = patch.domain_high();
      range.cut = true;
    }
  }
  // left
  {
    double inside = s_start, f_in = f_start;
    bool found = false;
    for (size_t k = first_right; k-- > 0 && !found;) {
      const double s = nodes[k];
      if (s >= s_start) continue;
      const double value = f_at_node(k);
      if (value <= 0.0) {
        range.low = EdgeRoot(f, inside, f_in, s, value);
        found = true;
      } else {
        inside = s;
        f_in = value;
      }
    }
    if (!found) {
      const double value = f(patch.domain_low());
      if (value <= 0.0) {
        range.low = EdgeRoot(f, inside, f_in, patch.domain_low(), value);
      } else {
        range.low = patch.domain_low();
        range.cut = true;
      }
    }
  }
  return range;
}

// Every range where f > 0 on the patch: the connected one around s_start (FindRange) and the other lobes beyond it
// on either side, found by walking the input nodes (as FindRange: a lobe is seen once it reaches a node), each
// edge on the interpolant; ordered along s.
template <class F, class FNode>
std::vector<ContactRange> FindAllRanges(const PatchInterpolant& patch, const F& f, const FNode& f_at_node,
                                        double s_start, double f_start) {
  const ContactRange main = FindRange(patch, f, f_at_node, s_start, f_start);
  const auto& nodes = patch.nodes();
  std::vector<ContactRange> lobes;
  // left of the main range, walking outwards (towards lower s)
  {
    bool in = false;
    double s_prev = main.low, f_prev = 0.0;
    ContactRange lobe;
    for (size_t k = nodes.size(); k-- > 0;) {
      if (nodes[k] >= main.low) continue;
      const double value = f_at_node(k);
      if (!in && value > 0.0) lobe.high = EdgeRoot(f, nodes[k], value, s_prev, f_prev), in = true;
      if (in && value <= 0.0) lobe.low = EdgeRoot(f, s_prev, f_prev, nodes[k], value), lobes.push_back(lobe), in = false;
      s_prev = nodes[k], f_prev = value;
    }
    if (in) {
      const double end = f(patch.domain_low());
      if (end <= 0.0) lobe.low = EdgeRoot(f, s_prev, f_prev, patch.domain_low(), end);
      else lobe.low = patch.domain_low(), lobe.cut = true;
      lobes.push_back(lobe);
    }
  }
  std::reverse(lobes.begin(), lobes.end());
  lobes.push_back(main);
  // right of the main range, walking outwards (towards higher s)
  {
    bool in = false;
    double s_prev = main.high, f_prev = 0.0;
    ContactRange lobe;
    for (size_t k = 0; k < nodes.size(); ++k) {
      if (nodes[k] <= main.high) continue;
      const double value = f_at_node(k);
      if (!in && value > 0.0) lobe.low = EdgeRoot(f, nodes[k], value, s_prev, f_prev), in = true;
      if (in && value <= 0.0) lobe.high = EdgeRoot(f, s_prev, f_prev, nodes[k], value), lobes.push_back(lobe), in = false;
      s_prev = nodes[k], f_prev = value;
    }
    if (in) {
      const double end = f(patch.domain_high());
      if (end <= 0.0) lobe.high = EdgeRoot(f, s_prev, f_prev, patch.domain_high(), end);
      else lobe.high = patch.domain_high(), lobe.cut = true;
      lobes.push_back(lobe);
    }
  }
  return lobes;
}

// Strip edges over the lobes of the contact range clipped to [low, high], `per_lobe` equal strips in each lobe.
// A lobe enters with zero width (FindAllRanges) and so with strips of zero width: the solution stays continuous
// when a lobe appears (strips laid over the span of all lobes left the main lobe with a third of its strips as soon
// as a distant lobe reached a node: the patch's p_max and SDEC jumped by 20-50 %, issue 15). One lobe: `per_lobe`
// strips over [low, high] exactly as before.
std::vector<std::pair<double, double>> StripEdges(const std::vector<ContactRange>& lobes, double low, double high,
                                                  int per_lobe) {
  std::vector<std::pair<double, double>> edges;
  auto lay = [&](double from, double to) {
    const double ds = (to - from) / per_lobe;
    for (int j = 0; j < per_lobe; ++j) {
      const double strip_low = from + j * ds;
      edges.emplace_back(strip_low, j + 1 == per_lobe ? to : strip_low + ds);
    }
  };
  if (lobes.size() <= 1) {
    lay(low, high);
    return edges;
  }
  for (const ContactRange& lobe : lobes) {
    const double from = std::max(lobe.low, low), to = std::min(lobe.high, high);
    if (to > from) lay(from, to);
  }
  if (edges.empty()) lay(low, high);
  return edges;
}

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
                     std::to_string(options.virtual_penetration_factor));
  if (options.strips_across_contact < 3 || options.strips_across_contact > 100000)
    throw InputError("KpOptions.strips_across_contact must lie in [3, 100000], got " +
                     std::to_string(options.strips_across_contact));
  require_finite(options.conformity_threshold_deg, "KpOptions.conformity_threshold_deg");
  if (options.collocation_strips < 2)
    throw InputError("KpOptions.collocation_strips must be >= 2, got " + std::to_string(options.collocation_strips));
}

bool CollocateStripPeaks(const PatchInterpolant& patch, const std::vector<KpStrip>& strips, double delta,
                         const ElasticConstants& elastic, bool blanco, double coupling_K, std::vector<double>& peaks,
                         std::vector<double>& unconstrained) {
  // docs/physics-reference.md §5.3: u_n(s_i, m_i) = sum_j peak_j / (pi G c_j) I_j(s_i) = delta cos(alpha_i) - gap_i
  // at every strip's centre line point (the BEM's gap closure, §10.4), I_j of §3.5 seen from strip i.
  const int n = static_cast<int>(strips.size());
  Eigen::MatrixXd influence(n, n);
  Eigen::VectorXd required(n);
  for (int i = 0; i < n; ++i) {
    const KpStrip& obs = strips[i];
    required(i) = delta * std::cos(obs.alpha_rad) - patch.gap(obs.s_m);
    for (int j = 0; j < n; ++j) {
      const KpStrip& load_strip = strips[j];
      if (!(load_strip.half_length_m > 0.0)) {
        influence(i, j) = 0.0;
        continue;
      }
      StripLoad load;
      load.s_low = load_strip.s_m - 0.5 * load_strip.ds_m;
      load.s_high = load_strip.s_m + 0.5 * load_strip.ds_m;
      load.half_length = load_strip.half_length_m;
      load.centre_offset = load_strip.x_centre_m - obs.x_centre_m;
      if (blanco) {
        load.alpha_low = patch.alpha(load.s_low) - obs.alpha_rad;
        load.alpha_high = patch.alpha(load.s_high) - obs.alpha_rad;
      }
      influence(i, j) = StripNormalDisplacementIntegral(load, obs.s_m, elastic.poisson_ratio, blanco, coupling_K) /
                        (M_PI * elastic.shear_modulus_Pa * load_strip.half_length_m);
    }
  }
  // Active set: strips whose amplitude comes out non-positive (or without length or required displacement) carry
  // nothing and are dropped, the rest re-solved, until every remaining amplitude is positive (at most n passes).
  std::vector<char> active(n);
  for (int j = 0; j < n; ++j) active[j] = strips[j].half_length_m > 0.0 && required(j) > 0.0;
  peaks.assign(n, 0.0);
  for (int pass = 0; pass < n; ++pass) {
    std::vector<int> index;
    for (int j = 0; j < n; ++j)
      if (active[j]) index.push_back(j);
    const int q = static_cast<int>(index.size());
    if (q == 0) return false;
    Eigen::MatrixXd a(q, q);
    Eigen::VectorXd b(q);
    for (int r = 0; r < q; ++r) {
      b(r) = required(index[r]);
      for (int c = 0; c < q; ++c) a(r, c) = influence(index[r], index[c]);
    }
    const Eigen::VectorXd x = a.partialPivLu().solve(b);
    if (!x.allFinite()) return false;
    if (pass == 0) {
      unconstrained.assign(n, 0.0);
      for (int r = 0; r < q; ++r) unconstrained[index[r]] = x(r);
    }
    bool changed = false;
    std::fill(peaks.begin(), peaks.end(), 0.0);
    for (int r = 0; r < q; ++r) {
      if (x(r) <= 0.0) {
        active[index[r]] = 0;
        changed = true;
      } else {
        peaks[index[r]] = x(r);
      }
    }
    if (!changed) return true;
  }
  return false;
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
  // KPEC's equivalent ellipses: eps(s) = clamp((a^2 A - spread t^2) / delta, 0, 1), t = (s - s_mid) / b (§3.3 step 3)
  struct EquivalentEllipse {
    double s_mid = 0.0, a_squared_A = 0.0, spread = 0.0, b = 1.0;
    double eps(double s, double delta) const {
      const double t = (s - s_mid) / b;
      return std::clamp((a_squared_A - spread * t * t) / delta, 0.0, 1.0);
    }
  };
  EquivalentEllipse combined;            // one ellipse over every lobe of the eps = 0.5 region
  std::vector<EquivalentEllipse> separate;  // one per lobe, when the lobes lie apart
  double separation_weight = 0.0;        // 0: the combined ellipse, 1: the separate ones, blended between
  if (kpec) {
    // KPEC step 2: equivalent Hertz problem from the eps = 0.5 region (CONTACT m_snorm.f90,
    // docs/physics-reference.md §3.3).
    auto half_region = [&](double s) { return 0.5 * delta - patch.gap(s); };
    auto half_region_node = [&](size_t k) { return 0.5 * delta - patch.node_gaps()[k]; };  // = half_region(nodes[k])
    const double f0 = half_region(s_contact);
    if (!(f0 > 0.0)) return result;
    auto ellipse = [&](double A, double half_width, double s_mid, EquivalentEllipse* out) {
      const double B = 0.5 * delta / (half_width * half_width);
      const HertzResult hertz = SolveHertzForApproach(A, B, delta, options.material);
      if (hertz.status != HertzStatus::Ok) return false;
      out->s_mid = s_mid;
      out->a_squared_A = A * hertz.a_m * hertz.a_m;
      out->spread = out->a_squared_A - B * hertz.b_m * hertz.b_m;
      out->b = hertz.b_m;
      return true;
    };
    // Every lobe of the eps = 0.5 region counts, by its width (CONTACT's region is one ellipse; for a gap with
    // several minima along s, as on worn treads, the connected lobe alone made B, eps(s) and so the force jump by
    // up to 40 % in 10 nm of approach when a second lobe joined it, issue 15): half-width = half the summed
    // widths, centre = their width-weighted mean. One lobe: the connected range as before.
    const std::vector<ContactRange> lobes = FindAllRanges(patch, half_region, half_region_node, s_contact, f0);
    double width = 0.0, weighted_centre = 0.0;
    for (const ContactRange& lobe : lobes) {
      width += lobe.high - lobe.low;
      weighted_centre += (lobe.high - lobe.low) * 0.5 * (lobe.low + lobe.high);
    }
    const double s_mid = width > 0.0 ? weighted_centre / width : s_contact;
    if (!ellipse(patch.curvature(s_contact), 0.5 * width, s_mid, &combined)) {
      result.status = KpStatus::NoEquivalentEllipse;
      return result;
    }
    // Lobes far apart are separate contacts: the combined ellipse centred in the gap between them lowered eps at
    // the main lobe as a distant lobe grew, so the force fell while the wheel was pushed down (several load-
    // controlled equilibria: stress case 432, S1002/60E1 tread, lobes 8 mm apart). There every lobe gets its own
    // ellipse (eps = the largest of them; a lobe entering with zero width adds nothing), blended in with the gaps
    // between the lobes: weight 0 up to a total gap of kKpecSeparateLobesLow times the summed widths (continuous
    // when lobes join), 1 from kKpecSeparateLobesHigh.
    const double gaps = lobes.back().high - lobes.front().low - width;
    separation_weight = width > 0.0 ? std::clamp((gaps / width - kKpecSeparateLobesLow) /
                                                     (kKpecSeparateLobesHigh - kKpecSeparateLobesLow), 0.0, 1.0)
                                    : 0.0;
    if (separation_weight > 0.0) {
      for (const ContactRange& lobe : lobes) {
        const double middle = 0.5 * (lobe.low + lobe.high);
        const bool main = s_contact >= lobe.low && s_contact <= lobe.high;
        EquivalentEllipse e;
        // a lobe too narrow for an ellipse (just entered) carries nothing yet
        if (ellipse(patch.curvature(main ? s_contact : middle), 0.5 * (lobe.high - lobe.low), middle, &e))
          separate.push_back(e);
      }
    }
  }
  const double eps = options.virtual_penetration_factor;
  auto interpenetration_with_gap = [&](double s, double gap) {
    if (!kpec) return eps * delta - gap;
    double eps_s = combined.eps(s, delta);
    if (separation_weight > 0.0) {
      double eps_separate = 0.0;
      for (const EquivalentEllipse& e : separate) eps_separate = std::max(eps_separate, e.eps(s, delta));
      eps_s = (1.0 - separation_weight) * eps_s + separation_weight * eps_separate;
    }
    return eps_s * delta - gap;
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
  const std::vector<ContactRange> lobes =
      FindAllRanges(patch, interpenetration, interpenetration_node, s_contact, g_contact);
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
  result.strips.resize(n);
  double c_max = c_contact;
  double influence_sum = 0.0;
  for (int j = 0; j < n; ++j) {
    KpStrip& strip = result.strips[j];
    const double low = edges[j].first, high = edges[j].second;
    strip.s_m = 0.5 * (low + high);
    strip.ds_m = high - low;
    strip.x_centre_m = patch.x_offset(strip.s_m);
    strip.alpha_rad = patch.alpha(strip.s_m);
    strip.half_length_m = std::sqrt(std::max(interpenetration(strip.s_m), 0.0) / patch.curvature(strip.s_m));
    c_max = std::max(c_max, strip.half_length_m);
    kp_detail::StripLoad load;
    load.s_low = low;
    load.s_high = high;
    load.half_length = strip.half_length_m;
    load.centre_offset = strip.x_centre_m - x_contact;
    if (blanco) {
      load.alpha_low = patch.alpha(low) - alpha_contact;  // alpha = alpha_J - alpha_I (§4.1)
      load.alpha_high = patch.alpha(high) - alpha_contact;
    }
    influence_sum +=
        kp_detail::StripNormalDisplacementIntegral(load, s_contact, elastic.poisson_ratio, blanco, coupling_K);
  }
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
    // §5.3: the amplitudes collocated on `nodes` coarse strips over the contact range (the strips themselves when
    // nodes >= n); their ratio peak / c, constant on a Hertzian patch, interpolated linearly onto the strips (constant
    // beyond the outer coarse centres).
    // strips on the given edges; lay_strips: `count` equal ones over [low_end, high_end]
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
    const int nodes = std::min(options.collocation_strips, per_lobe);
    auto lay_strips = [&](double low_end, double high_end, int count) {
      return strips_on(StripEdges({}, low_end, high_end, count));
    };
    struct CoarseSolution {
      std::vector<KpStrip> strips;
      std::vector<double> peaks, free_peaks;  // active-set and unconstrained amplitudes, Pa
    };
    auto solve_on = [&](const ContactRange& on, CoarseSolution& out) {
      out.strips = lay_strips(on.low, on.high, nodes);
      return kp_detail::CollocateStripPeaks(patch, out.strips, delta, elastic, blanco, coupling_K, out.peaks,
                                            out.free_peaks);
    };
    // Contact edge in s where the amplitude vanishes (p ~ sqrt(distance) at a smooth edge: q = sign(P) P^2 linear in
    // s), from the unconstrained amplitudes (continuous in delta, so is the edge): the zero of q between the outermost
    // positive coarse strip and its outer neighbour, or extrapolated outwards from the two outermost coarse strips
    // when both are positive; the range is cut there when that lies inside it.
    auto cut_range = [&](const CoarseSolution& c, ContactRange on) {
      auto signed_square = [&](int k) { return c.free_peaks[k] * std::fabs(c.free_peaks[k]); };
      auto edge = [&](int step) {  // step +1: low edge (scan upwards), -1: high edge
        const int start = step > 0 ? 0 : nodes - 1;
        int k = start;
        while (k >= 0 && k < nodes && !(c.free_peaks[k] > 0.0)) k += step;
        if (k < 0 || k >= nodes) return std::nan("");
        const int outer = k == start ? k : k - step, inner = k == start ? k + step : k;
        if (inner < 0 || inner >= nodes) return std::nan("");
        const double q_outer = signed_square(outer), q_inner = signed_square(inner);
        if (!(q_inner > q_outer)) return std::nan("");
        return c.strips[outer].s_m + (c.strips[inner].s_m - c.strips[outer].s_m) * (-q_outer) / (q_inner - q_outer);
      };
      const double low = edge(+1), high = edge(-1);
      if (low > on.low && low < high) on.low = low;
      if (high < on.high && high > on.low) on.high = high;
      return on;
    };
    // ratio P / c of a coarse solution at s (linear between the coarse centres, constant beyond the outer ones)
    auto ratio_at = [&](const CoarseSolution& c, double s_m) {
      const double t = std::clamp((s_m - c.strips[0].s_m) / (c.strips[1].s_m - c.strips[0].s_m), 0.0,
                                  double(nodes - 1));
      const int k = std::min(static_cast<int>(t), nodes - 2);
      const double w = t - k;
      auto ratio = [&](int i) { return c.strips[i].half_length_m > 0.0 ? c.peaks[i] / c.strips[i].half_length_m : 0.0; };
      return (1.0 - w) * ratio(k) + w * ratio(k + 1);
    };
    // Solve A over the virtual range and cut it (range 1). A cut of more than kCollocationRecutLow of the width asks
    // for solve B over range 1, cut again (range 2); the result is the blend (1 - w) A + w B of the ranges and of
    // the ratios P / c, w rising linearly from 0 to 1 between kCollocationRecutLow and kCollocationRecutHigh: every
    // step continuous in delta, and one solve where the virtual range was nearly right.
    CoarseSolution first, second;
    if (!solve_on(range, first)) {
      result.status = KpStatus::InfluenceNotPositive;
      result.strips.clear();
      return result;
    }
    const ContactRange range1 = cut_range(first, range);
    const double cut_fraction = ((range1.low - range.low) + (range.high - range1.high)) / (range.high - range.low);
    const double blend = std::clamp((cut_fraction - kCollocationRecutLow) / (kCollocationRecutHigh - kCollocationRecutLow),
                                    0.0, 1.0);
    ContactRange final_range = range1;
    if (blend > 0.0) {
      if (!solve_on(range1, second)) {
        result.status = KpStatus::InfluenceNotPositive;
        result.strips.clear();
        return result;
      }
      const ContactRange range2 = cut_range(second, range1);
      final_range.low = (1.0 - blend) * range1.low + blend * range2.low;
      final_range.high = (1.0 - blend) * range1.high + blend * range2.high;
    }
    if (final_range.low != range.low || final_range.high != range.high) {
      range.low = final_range.low;
      range.high = final_range.high;
      result.strips = strips_on(StripEdges(lobes, range.low, range.high, per_lobe));
      n = static_cast<int>(result.strips.size());
      peaks.assign(n, 0.0);
    }
    for (int j = 0; j < n; ++j) {
      const double s_j = result.strips[j].s_m;
      const double ratio = blend > 0.0 ? (1.0 - blend) * ratio_at(first, s_j) + blend * ratio_at(second, s_j)
                                       : ratio_at(first, s_j);
      peaks[j] = result.strips[j].half_length_m * ratio;
    }
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
