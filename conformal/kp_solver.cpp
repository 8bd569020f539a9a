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
// Strip collocation (§5.3): a coarse strip whose virtual half-length is below this fraction of its lobe's largest has
// its contact condition blended with KP's constant ratio P / c (CollocationEdgeTie), the weight of the contact
// condition rising smoothly from 0 at c = 0 to 1 here. A Hertzian lobe's outermost coarse strip has
// c / c_max >= sqrt(1 - (1 - 1/n)^2), 0.42 for n = 11, so Hertzian lobes keep the pure collocation.
constexpr double kCollocationEdgeBlend = 0.1;
// KPEC (§3.3): total gap between the lobes of the eps = 0.5 region, as a multiple of their summed widths, from which
// the lobes get separate equivalent ellipses (blended in up to the upper value)
constexpr double kKpecSeparateLobesLow = 0.1;
constexpr double kKpecSeparateLobesHigh = 0.3;
// KPEC wells (§3.3): a well whose prominence (crest towards a deeper well above its bottom) is below the lower value
// times its approach delta_k is no separate contact (a ripple on a flank), fully one from the upper value
// (log-linear between)
constexpr double kWellProminenceLow = 0.002;
constexpr double kWellProminenceHigh = 0.01;



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
  // the lobes beyond the main range walking the nodes outwards (step -1: towards lower s), in walking order
  auto walk = [&](int step) {
    const bool up = step > 0;
    const double start = up ? main.high : main.low, domain_end = up ? patch.domain_high() : patch.domain_low();
    std::vector<ContactRange> found;
    double inner = 0.0;  // the current lobe's edge towards the main range
    auto close = [&](double outer, bool cut) {
      ContactRange lobe;
      lobe.low = up ? inner : outer;
      lobe.high = up ? outer : inner;
      lobe.cut = cut;
      found.push_back(lobe);
    };
    bool in = false;
    double s_prev = start, f_prev = 0.0;
    for (size_t i = 0; i < nodes.size(); ++i) {
      const size_t k = up ? i : nodes.size() - 1 - i;
      if (up ? nodes[k] <= start : nodes[k] >= start) continue;
      const double value = f_at_node(k);
      if (!in && value > 0.0) inner = EdgeRoot(f, nodes[k], value, s_prev, f_prev), in = true;
      if (in && value <= 0.0) close(EdgeRoot(f, s_prev, f_prev, nodes[k], value), false), in = false;
      s_prev = nodes[k], f_prev = value;
    }
    if (in) {
      const double end = f(domain_end);
      if (end <= 0.0) close(EdgeRoot(f, s_prev, f_prev, domain_end, end), false);
      else close(domain_end, true);
    }
    return found;
  };
  std::vector<ContactRange> lobes = walk(-1);
  std::reverse(lobes.begin(), lobes.end());
  lobes.push_back(main);
  for (const ContactRange& lobe : walk(+1)) lobes.push_back(lobe);
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
  edges.reserve(static_cast<size_t>(per_lobe) * std::max<size_t>(lobes.size(), 1));
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

// A well of the gap other than the deepest (§3.3 "wells"): its bottom node, the crests towards deeper nodes on
// either side, its prominence (the lower crest above its bottom) and its weight as a separate contact.
struct Valley {
  size_t bottom = 0;
  double crest[2] = {-std::numeric_limits<double>::infinity(),  // s of the crest towards a deeper node (low, high
                     std::numeric_limits<double>::infinity()};  // side); none: -inf / +inf
  double prominence = std::numeric_limits<double>::infinity();
  double weight = 0.0;
};

// Every interior local minimum of the gap at the nodes below the approach delta that has a deeper node on some side,
// with a positive weight: log-linear from 0 to 1 as its prominence grows from kWellProminenceLow to
// kWellProminenceHigh times its own approach delta - g_k (a ripple is no separate contact).
std::vector<Valley> SeparateWells(const std::vector<double>& nodes, const std::vector<double>& node_gaps, double delta) {
  const size_t node_count = nodes.size();
  std::vector<Valley> valleys;
  for (size_t k = 1; k + 1 < node_count; ++k) {
    if (!(node_gaps[k] < node_gaps[k - 1] && node_gaps[k] <= node_gaps[k + 1]) || !(node_gaps[k] < delta)) continue;
    Valley v;
    v.bottom = k;
    for (int side = 0; side < 2; ++side) {
      const long step = side == 0 ? -1 : 1;
      size_t crest = k;
      for (long i = static_cast<long>(k) + step; i >= 0 && i < static_cast<long>(node_count); i += step) {
        if (node_gaps[i] < node_gaps[k]) {
          v.crest[side] = nodes[crest];
          v.prominence = std::min(v.prominence, node_gaps[crest] - node_gaps[k]);
          break;
        }
        if (node_gaps[i] > node_gaps[crest]) crest = static_cast<size_t>(i);
      }
    }
    if (!std::isfinite(v.prominence)) continue;  // the deepest node: the main well
    const double delta_k = delta - node_gaps[k];
    v.weight = v.prominence > kWellProminenceLow * delta_k
                   ? std::min(1.0, std::log(v.prominence / (kWellProminenceLow * delta_k)) /
                                       std::log(kWellProminenceHigh / kWellProminenceLow))
                   : 0.0;
    if (v.weight > 0.0) valleys.push_back(v);
  }
  return valleys;
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

bool CollocateStripPeaks(const PatchInterpolant& patch, const std::vector<KpStrip>& strips,
                         const std::vector<CollocationEdgeTie>& ties, double delta, const ElasticConstants& elastic,
                         bool blanco, double coupling_K, std::vector<double>& peaks,
                         std::vector<double>& unconstrained) {
  // docs/physics-reference.md §5.3: u_n(s_i, m_i) = sum_j peak_j / (pi G c_j) I_j(s_i) = delta cos(alpha_i) - gap_i
  // at every strip's centre line point (the BEM's gap closure, §10.4), I_j of §3.5 seen from strip i.
  const int n = static_cast<int>(strips.size());
  Eigen::MatrixXd influence(n, n);
  Eigen::VectorXd required(n);
  std::vector<StripLoad> loads;  // one collocation row: the strips with length, seen from strip i
  std::vector<int> load_index;
  std::vector<double> integrals(n);
  loads.reserve(n);
  load_index.reserve(n);
  // each strip's ends and normal angles there, the same for every observation point (row)
  std::vector<double> s_low(n), s_high(n), alpha_low(n), alpha_high(n);
  for (int j = 0; j < n; ++j) {
    s_low[j] = strips[j].s_m - 0.5 * strips[j].ds_m;
    s_high[j] = strips[j].s_m + 0.5 * strips[j].ds_m;
    if (blanco) {
      alpha_low[j] = patch.alpha(s_low[j]);
      alpha_high[j] = patch.alpha(s_high[j]);
    }
  }
  for (int i = 0; i < n; ++i) {
    const KpStrip& obs = strips[i];
    required(i) = delta * std::cos(obs.alpha_rad) - patch.gap(obs.s_m);
    loads.clear();
    load_index.clear();
    for (int j = 0; j < n; ++j) {
      const KpStrip& load_strip = strips[j];
      if (!(load_strip.half_length_m > 0.0)) {
        influence(i, j) = 0.0;
        continue;
      }
      StripLoad load;
      load.s_low = s_low[j];
      load.s_high = s_high[j];
      load.half_length = load_strip.half_length_m;
      load.centre_offset = load_strip.x_centre_m - obs.x_centre_m;
      if (blanco) {
        load.alpha_low = alpha_low[j] - obs.alpha_rad;
        load.alpha_high = alpha_high[j] - obs.alpha_rad;
      }
      loads.push_back(load);
      load_index.push_back(j);
    }
    // the whole row in one batch (bit-identical to StripNormalDisplacementIntegral strip by strip)
    StripNormalDisplacementIntegrals(loads.data(), static_cast<int>(loads.size()), obs.s_m, elastic.poisson_ratio,
                                     blanco, coupling_K, integrals.data());
    for (size_t k = 0; k < loads.size(); ++k) {
      const int j = load_index[k];
      influence(i, j) = integrals[k] / (M_PI * elastic.shear_modulus_Pa * strips[j].half_length_m);
    }
  }
  // Active set: strips whose amplitude comes out non-positive (or without length or required displacement) carry
  // nothing and are dropped, the rest re-solved, until every remaining amplitude is positive (at most n passes).
  std::vector<char> active(n);
  for (int j = 0; j < n; ++j) active[j] = strips[j].half_length_m > 0.0 && required(j) > 0.0;
  peaks.assign(n, 0.0);
  std::vector<int> index;
  index.reserve(n);
  for (int pass = 0; pass < n; ++pass) {
    index.clear();
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
    // §5.3, steep lobe edge: weight w (contact condition) + (1 - w) A_anchor (P_i - c_i / c_nb P_nb) = 0; a dropped
    // neighbour carries nothing, so its term vanishes
    for (int r = 0; r < q && !ties.empty(); ++r) {
      const int i = index[r];
      const CollocationEdgeTie& tie = ties[i];
      if (!(tie.weight < 1.0)) continue;
      const double scale = (1.0 - tie.weight) * influence(tie.anchor, tie.anchor);
      b(r) *= tie.weight;
      for (int c = 0; c < q; ++c) a(r, c) *= tie.weight;
      a(r, r) += scale;
      if (tie.neighbour >= 0 && active[tie.neighbour]) {
        const int c = static_cast<int>(std::lower_bound(index.begin(), index.end(), tie.neighbour) - index.begin());
        a(r, c) -= scale * strips[i].half_length_m / strips[tie.neighbour].half_length_m;
      }
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
  // Each well of the gap is such an ellipse of its own (bottom gap g_k, approach delta_k = delta - g_k): its virtual
  // level is g_k + weight eps_k(s) delta_k inside its valley where eps_k > 0, none (0) elsewhere. The main well (the
  // contact point, g = 0) has approach delta.
  struct EquivalentEllipse {
    double s_mid = 0.0, a_squared_A = 0.0, spread = 0.0, b = 1.0;
    double bottom_gap = 0.0, weight = 1.0;
    double valley_low = -std::numeric_limits<double>::infinity(), valley_high = std::numeric_limits<double>::infinity();
    // The main well beyond the crest of a well of weight w < 1 (outwards on either side): its level times the
    // product of (1 - w) of the crests passed, (crest s, that product) in order outwards (§3.3 "wells")
    std::vector<std::pair<double, double>> fade_low, fade_high;
    double eps(double s, double approach) const {
      const double t = (s - s_mid) / b;
      return std::clamp((a_squared_A - spread * t * t) / approach, 0.0, 1.0);
    }
    double level(double s, double delta) const {
      if (s < valley_low || s > valley_high) return 0.0;
      const double e = eps(s, delta - bottom_gap);
      if (!(e > 0.0)) return 0.0;
      double factor = weight;
      for (const auto& f : fade_low)
        if (s < f.first) factor = weight * f.second;
      for (const auto& f : fade_high)
        if (s > f.first) factor = weight * f.second;
      return bottom_gap + factor * e * (delta - bottom_gap);
    }
  };
  EquivalentEllipse combined;            // one ellipse over every lobe of the eps = 0.5 region
  std::vector<EquivalentEllipse> wells;  // one per well, the main one first, when the wells are separate contacts
  double separation_weight = 0.0;        // 0: the combined ellipse, 1: the separate wells, blended between
  if (kpec) {
    // KPEC step 2: equivalent Hertz problem from the eps = 0.5 region (CONTACT m_snorm.f90,
    // docs/physics-reference.md §3.3).
    auto half_region = [&](double s) { return 0.5 * delta - patch.gap(s); };
    auto half_region_node = [&](size_t k) { return 0.5 * delta - patch.node_gaps()[k]; };  // = half_region(nodes[k])
    const double f0 = half_region(s_contact);
    if (!(f0 > 0.0)) return result;
    auto ellipse_for = [&](double A, double half_width, double s_mid, double approach, EquivalentEllipse* out) {
      const double B = 0.5 * approach / (half_width * half_width);
      const HertzResult hertz = SolveHertzForApproach(A, B, approach, options.material);
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
    if (!ellipse_for(patch.curvature(s_contact), 0.5 * width, s_mid, delta, &combined)) {
      result.status = KpStatus::NoEquivalentEllipse;
      return result;
    }
    // Lobes far apart: the combined ellipse centred in the gap between them lowered eps at the main lobe as a
    // distant lobe grew, so the force fell while the wheel was pushed down (stress case 432, S1002/60E1 tread, lobes
    // 8 mm apart). Weight of the separate wells: 0 up to a total gap of kKpecSeparateLobesLow times the summed
    // widths (continuous when lobes join), 1 from kKpecSeparateLobesHigh; at least the largest well weight below.
    const double gaps = lobes.back().high - lobes.front().low - width;
    separation_weight = width > 0.0 ? std::clamp((gaps / width - kKpecSeparateLobesLow) /
                                                     (kKpecSeparateLobesHigh - kKpecSeparateLobesLow), 0.0, 1.0)
                                    : 0.0;
    // Wells (§3.3 "wells", issue 15): every interior local minimum k of the gap at the nodes below the approach
    // (g_k < delta) is a Hertzian contact of approach delta_k = delta - g_k with its own eps = 0.5 region
    // g - g_k < delta_k / 2 around its bottom, up to the crests towards deeper wells (its valley). Measured from
    // the main well's bottom instead, a distant well entered only at eps delta = g_k, with a rigid approach of
    // about g_k already asked for there, far narrower than that approach gives (the strip collocation then came
    // out ~1/c: p_max of 4-40 GPa on two-well gaps). A well enters with zero width at delta = g_k. Its weight
    // rises log-linearly from 0 to 1 as its prominence p_k (crest above its bottom) grows from kWellProminenceLow to
    // kWellProminenceHigh times delta_k: a ripple is no separate contact. Wells stay separate after their lobes
    // join (fading them into the combined ellipse then cost force growth: the combined ellipse cannot reach a well
    // whose bottom lies above delta / 2).
    const auto& nodes = patch.nodes();
    const auto& node_gaps = patch.node_gaps();
    const size_t node_count = nodes.size();
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    const std::vector<Valley> valleys = SeparateWells(nodes, node_gaps, delta);
    for (const Valley& v : valleys) separation_weight = std::max(separation_weight, v.weight);
    if (separation_weight > 0.0) {
      // the main well: the connected eps = 0.5 region around the contact point, up to the crests towards the valleys
      // of the other wells (it neither floods them nor jumps when it reaches them)
      auto bottom_weight = [&](size_t i) {  // the weight of the well whose bottom node is i, 0: none
        for (const Valley& v : valleys)
          if (v.bottom == i) return v.weight;
        return 0.0;
      };
      // The main well ends at the crest towards a well of weight 1 and, towards a well of weight w < 1, reaches
      // past that crest with the share 1 - w: its edge is sum_k (prod_{l<k} (1 - w_l)) w_k crest_k + (prod (1 - w))
      // (the edge without those wells), and its level beyond such a crest is multiplied by prod (1 - w) (the
      // ellipse's fades). A ripple well whose weight fades to 0 thus leaves the main well continuously (its crest
      // cut the main well until the weight reached 0, and the force then jumped by 17 % on a worn tread:
      // tests/data/kp_worn_tread/worn_cruise_patch.txt).
      double edge[2] = {s_contact, s_contact};
      double valley_edge[2] = {-kInfinity, kInfinity};
      std::vector<std::pair<double, double>> fades[2];
      const size_t first_right =
          static_cast<size_t>(std::upper_bound(nodes.begin(), nodes.end(), s_contact) - nodes.begin());
      for (int side = 0; side < 2; ++side) {
        const long step = side == 0 ? -1 : 1;
        double inside = s_contact, f_in = f0;
        long crest = -1;
        double share = 1.0, edge_sum = 0.0;  // prod (1 - w) of the crests passed; sum of their weighted crests
        bool in_region = true;               // still inside the eps = 0.5 region (edge[side] not yet set)
        for (long i = side == 0 ? static_cast<long>(first_right) - 1 : static_cast<long>(first_right);
             i >= 0 && i < static_cast<long>(node_count); i += step) {
          const double w = bottom_weight(static_cast<size_t>(i));
          if (w > 0.0) {
            const double crest_s = crest >= 0 ? nodes[crest] : nodes[i];  // (a bottom next to the contact point)
            if (in_region) edge_sum += share * w * crest_s;
            share *= 1.0 - w;
            if (!(share > 0.0)) {
              if (in_region) edge[side] = edge_sum, in_region = false;
              valley_edge[side] = crest_s;
              break;
            }
            fades[side].push_back({crest_s, share});
            crest = -1;
            if (!in_region) continue;
          }
          if (crest < 0 || node_gaps[i] > node_gaps[crest]) crest = i;
          if (!in_region) continue;
          const double value = 0.5 * delta - node_gaps[i];
          if (value <= 0.0) {
            // past the region the scan goes on for the valley's end: the crest of the next well (of weight 1)
            edge[side] = edge_sum + share * EdgeRoot(half_region, inside, f_in, nodes[i], value);
            in_region = false;
            continue;
          }
          inside = nodes[i], f_in = value;
        }
        if (in_region) edge[side] = edge_sum + share * (side == 0 ? patch.domain_low() : patch.domain_high());
      }
      EquivalentEllipse main_well;
      if (edge[1] > edge[0] &&
          ellipse_for(patch.curvature(s_contact), 0.5 * (edge[1] - edge[0]), 0.5 * (edge[0] + edge[1]), delta,
                      &main_well)) {
        main_well.valley_low = valley_edge[0];
        main_well.valley_high = valley_edge[1];
        main_well.fade_low = fades[0];
        main_well.fade_high = fades[1];
        wells.push_back(main_well);
      } else {
        separation_weight = 0.0;
      }
      // the other wells: own-level region around the bottom, up to the crests of its valley
      for (const Valley& v : valleys) {
        if (wells.empty()) break;
        const double g_k = node_gaps[v.bottom], delta_k = delta - g_k, level = g_k + 0.5 * delta_k;
        auto f = [&](double s) { return level - patch.gap(s); };
        double well_edge[2];
        for (int side = 0; side < 2; ++side) {
          const long step = side == 0 ? -1 : 1;
          double inside = nodes[v.bottom], f_in = 0.5 * delta_k;
          well_edge[side] = side == 0 ? std::max(patch.domain_low(), v.crest[0]) : std::min(patch.domain_high(), v.crest[1]);
          for (long i = static_cast<long>(v.bottom) + step; i >= 0 && i < static_cast<long>(node_count); i += step) {
            if (side == 0 ? nodes[i] <= well_edge[0] : nodes[i] >= well_edge[1]) break;  // the crest: clipped
            const double value = level - node_gaps[i];
            if (value <= 0.0) {
              well_edge[side] = EdgeRoot(f, inside, f_in, nodes[i], value);
              break;
            }
            inside = nodes[i], f_in = value;
          }
        }
        EquivalentEllipse e;
        // a region too narrow for an ellipse (a well just entered) carries nothing yet
        if (!(well_edge[1] > well_edge[0]) ||
            !ellipse_for(patch.curvature(nodes[v.bottom]), 0.5 * (well_edge[1] - well_edge[0]),
                         0.5 * (well_edge[0] + well_edge[1]), delta_k, &e))
          continue;
        e.bottom_gap = g_k;
        e.weight = v.weight;
        e.valley_low = v.crest[0];
        e.valley_high = v.crest[1];
        wells.push_back(e);
      }
    }
  }
  const double eps = options.virtual_penetration_factor;
  auto interpenetration_with_gap = [&](double s, double gap) {
    if (!kpec) return eps * delta - gap;
    double level = combined.eps(s, delta) * delta;
    if (separation_weight > 0.0) {
      double level_separate = 0.0;
      for (const EquivalentEllipse& e : wells) level_separate = std::max(level_separate, e.level(s, delta));
      level = (1.0 - separation_weight) * level + separation_weight * level_separate;
    }
    return level - gap;
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
    // §5.3: the amplitudes collocated on `nodes` coarse strips in each lobe of the contact range (the strips
    // themselves when nodes >= n); their ratio peak / c, constant on a Hertzian patch, interpolated linearly onto the
    // strips within each lobe (constant beyond its outer coarse centres). Coarse strips per lobe: laid over the span
    // of all lobes, a coarse centre falling into an entering lobe brought a finite half-length at once (issue 15).
    const int nodes = std::min(options.collocation_strips, per_lobe);
    // the lobes of the contact range clipped to [range.low, range.high]; a lobe outside keeps zero width
    std::vector<ContactRange> coarse_lobes;
    if (lobes.size() <= 1) {
      coarse_lobes.push_back(range);
    } else {
      for (const ContactRange& lobe : lobes) {
        ContactRange clipped = lobe;
        clipped.low = std::clamp(lobe.low, range.low, range.high);
        clipped.high = std::clamp(lobe.high, range.low, range.high);
        coarse_lobes.push_back(clipped);
      }
    }
    struct CoarseSolution {
      std::vector<ContactRange> lobes;  // `nodes` equal coarse strips in each (zero width: none)
      std::vector<int> first;           // index of each lobe's first coarse strip (-1: none)
      std::vector<KpStrip> strips;
      std::vector<double> peaks, free_peaks;  // active-set and unconstrained amplitudes, Pa
      std::vector<kp_detail::CollocationEdgeTie> ties;  // §5.3, steep lobe edge
    };
    auto solve_on = [&](const std::vector<ContactRange>& on, CoarseSolution& out) {
      out.lobes = on;
      out.first.assign(on.size(), -1);
      std::vector<std::pair<double, double>> edges_on;
      edges_on.reserve(static_cast<size_t>(nodes) * on.size());
      // a lobe far narrower than the range (entering, or cut down to its last positive amplitude) carries no coarse
      // strips: they would be degenerate, and its strips take the ratio of the nearest lobe
      const double narrow = 1e-6 * (on.back().high - on.front().low);
      for (size_t l = 0; l < on.size(); ++l) {
        if (!(on[l].high - on[l].low > narrow)) continue;
        out.first[l] = static_cast<int>(edges_on.size());
        for (const auto& e : StripEdges({}, on[l].low, on[l].high, nodes)) edges_on.push_back(e);
      }
      if (edges_on.empty()) return false;
      out.strips = strips_on(edges_on);
      // A coarse strip whose virtual half-length is a small fraction of its lobe's largest (centre just inside a steep
      // edge of the virtual interpenetration): its influence column vanishes with c while its required displacement
      // does not, so its collocated amplitude P ~ 1/c and the ratio P/c the strips take from it ~ 1/c^2 (a worn tread:
      // c = 3e-9 m gave P = 1e11 Pa and F_n 7e9 N; docs/physics-reference.md §5.3). Its contact condition is blended
      // with KP's constant ratio (the inward neighbour's), the condition's weight a smoothstep of c / c_max that
      // vanishes with c: the amplitude stays bounded and goes to 0 with c, continuously.
      std::vector<kp_detail::CollocationEdgeTie>& ties = out.ties;
      ties.assign(out.strips.size(), {});
      for (size_t l = 0; l < on.size(); ++l) {
        if (out.first[l] < 0) continue;
        const int base = out.first[l];
        int longest = 0;
        for (int k = 1; k < nodes; ++k)
          if (out.strips[base + k].half_length_m > out.strips[base + longest].half_length_m) longest = k;
        const double lobe_c_max = out.strips[base + longest].half_length_m;
        for (int k = 0; k < nodes; ++k) {
          const double u = lobe_c_max > 0.0 ? std::clamp(out.strips[base + k].half_length_m /
                                                             (kCollocationEdgeBlend * lobe_c_max), 0.0, 1.0)
                                            : 1.0;
          kp_detail::CollocationEdgeTie& tie = ties[base + k];
          tie.weight = u * u * (3.0 - 2.0 * u);
          if (tie.weight < 1.0) {
            tie.anchor = base + longest;
            tie.neighbour = base + k + (longest > k ? 1 : -1);
          }
        }
      }
      return kp_detail::CollocateStripPeaks(patch, out.strips, ties, delta, elastic, blanco, coupling_K, out.peaks,
                                            out.free_peaks);
    };
    // Contact edge in s where the amplitude vanishes (p ~ sqrt(distance) at a smooth edge: q = sign(P) P^2 linear in
    // s), per lobe, from the unconstrained amplitudes (continuous in delta, so is the edge): the zero of q between the
    // lobe's outermost positive coarse strip and its outer neighbour, or extrapolated outwards from its two outermost
    // coarse strips when both are positive; the lobe is cut there when that lies inside it. Of several lobes, one
    // without a positive amplitude shrinks to zero width (at its strip of largest amplitude, where it would enter).
    auto cut_lobes = [&](const CoarseSolution& c) {
      std::vector<ContactRange> out = c.lobes;
      for (size_t l = 0; l < out.size(); ++l) {
        if (c.first[l] < 0) continue;
        const int base = c.first[l];
        auto amplitude = [&](int k) { return c.free_peaks[base + k]; };
        auto centre = [&](int k) { return c.strips[base + k].s_m; };
        auto signed_square = [&](int k) { return amplitude(k) * std::fabs(amplitude(k)); };
        auto edge = [&](int step) {  // step +1: low edge (scan upwards), -1: high edge
          const int start = step > 0 ? 0 : nodes - 1;
          int k = start;
          while (k >= 0 && k < nodes && !(amplitude(k) > 0.0)) k += step;
          if (k < 0 || k >= nodes) return std::nan("");
          const int outer = k == start ? k : k - step, inner = k == start ? k + step : k;
          if (inner < 0 || inner >= nodes) return std::nan("");
          const double q_outer = signed_square(outer), q_inner = signed_square(inner);
          if (!(q_inner > q_outer)) return std::nan("");
          return centre(outer) + (centre(inner) - centre(outer)) * (-q_outer) / (q_inner - q_outer);
        };
        bool any_positive = false;
        int largest = 0;
        for (int k = 0; k < nodes; ++k) {
          any_positive |= amplitude(k) > 0.0;
          if (amplitude(k) > amplitude(largest)) largest = k;
        }
        if (!any_positive) {
          if (out.size() > 1) out[l].low = out[l].high = centre(largest);
          continue;
        }
        const double low = edge(+1), high = edge(-1);
        if (low > out[l].low && low < high) out[l].low = low;
        if (high < out[l].high && high > out[l].low) out[l].high = high;
      }
      return out;
    };
    auto total_width = [](const std::vector<ContactRange>& on) {
      double w = 0.0;
      for (const ContactRange& r : on) w += std::max(r.high - r.low, 0.0);
      return w;
    };
    // ratio P / c of a coarse solution at s: within the lobe that holds s (else the nearest), linear between its
    // coarse centres, constant beyond the outer ones
    auto ratio_at = [&](const CoarseSolution& c, double s_m) {
      int best = -1;
      double best_distance = 0.0;
      for (size_t l = 0; l < c.lobes.size(); ++l) {
        if (c.first[l] < 0) continue;
        const double distance = std::max({c.lobes[l].low - s_m, s_m - c.lobes[l].high, 0.0});
        if (best < 0 || distance < best_distance) best = static_cast<int>(l), best_distance = distance;
      }
      if (best < 0) return 0.0;
      const int base = c.first[best];
      const double t = std::clamp((s_m - c.strips[base].s_m) / (c.strips[base + 1].s_m - c.strips[base].s_m), 0.0,
                                  double(nodes - 1));
      const int k = std::min(static_cast<int>(t), nodes - 2);
      const double w = t - k;
      // a coarse strip without length takes its tied neighbour's ratio, the limit of its blended row as c -> 0
      auto ratio = [&](int i) {
        int j = base + i;
        while (!(c.strips[j].half_length_m > 0.0) && c.ties[j].neighbour >= 0) j = c.ties[j].neighbour;
        const KpStrip& strip = c.strips[j];
        return strip.half_length_m > 0.0 ? c.peaks[j] / strip.half_length_m : 0.0;
      };
      return (1.0 - w) * ratio(k) + w * ratio(k + 1);
    };
    // Solve A over the virtual range and cut it (range 1). A cut of more than kCollocationRecutLow of the width asks
    // for solve B over range 1, cut again (range 2); the result is the blend (1 - w) A + w B of the ranges and of
    // the ratios P / c, w rising linearly from 0 to 1 between kCollocationRecutLow and kCollocationRecutHigh: every
    // step continuous in delta, and one solve where the virtual range was nearly right.
    CoarseSolution first, second;
    if (!solve_on(coarse_lobes, first)) {
      result.status = KpStatus::InfluenceNotPositive;
      result.strips.clear();
      return result;
    }
    const std::vector<ContactRange> range1 = cut_lobes(first);
    const double width0 = total_width(coarse_lobes);
    const double cut_fraction = width0 > 0.0 ? 1.0 - total_width(range1) / width0 : 0.0;
    const double blend = std::clamp((cut_fraction - kCollocationRecutLow) / (kCollocationRecutHigh - kCollocationRecutLow),
                                    0.0, 1.0);
    std::vector<ContactRange> final_lobes = range1;
    if (blend > 0.0) {
      if (!solve_on(range1, second)) {
        result.status = KpStatus::InfluenceNotPositive;
        result.strips.clear();
        return result;
      }
      const std::vector<ContactRange> range2 = cut_lobes(second);
      for (size_t l = 0; l < final_lobes.size(); ++l) {
        final_lobes[l].low = (1.0 - blend) * range1[l].low + blend * range2[l].low;
        final_lobes[l].high = (1.0 - blend) * range1[l].high + blend * range2[l].high;
      }
    }
    bool changed = false;
    for (size_t l = 0; l < final_lobes.size(); ++l)
      changed |= final_lobes[l].low != coarse_lobes[l].low || final_lobes[l].high != coarse_lobes[l].high;
    if (changed) {
      std::vector<std::pair<double, double>> final_edges;
      final_edges.reserve(static_cast<size_t>(per_lobe) * final_lobes.size());
      for (const ContactRange& lobe : final_lobes)
        if (lobe.high > lobe.low)
          for (const auto& e : StripEdges({}, lobe.low, lobe.high, per_lobe)) final_edges.push_back(e);
      if (!final_edges.empty()) {
        range.low = final_edges.front().first;
        range.high = final_edges.back().second;
        result.strips = strips_on(final_edges);
        n = static_cast<int>(result.strips.size());
        peaks.assign(n, 0.0);
      }
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
