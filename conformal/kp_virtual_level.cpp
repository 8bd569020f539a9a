// KPEC's virtual penetration level (kp_virtual_level.hpp; docs/physics-reference.md §3.3).
#include "kp_virtual_level.hpp"

#include <cmath>

#include "conforma/hertz.hpp"
#include "kp_ranges.hpp"

namespace conforma {
namespace kp_detail {

namespace {

// KPEC (§3.3): total gap between the lobes of the eps = 0.5 region, as a multiple of their summed widths, from which
// the lobes get separate equivalent ellipses (blended in up to the upper value)
constexpr double kKpecSeparateLobesLow = 0.1;
constexpr double kKpecSeparateLobesHigh = 0.3;
// KPEC wells (§3.3): a well whose prominence (crest towards a deeper well above its bottom) is below the lower value
// times its approach delta_k is no separate contact (a ripple on a flank), fully one from the upper value
// (log-linear between)
constexpr double kWellProminenceLow = 0.002;
constexpr double kWellProminenceHigh = 0.01;

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

}  // namespace

KpecBuild BuildKpecVirtualLevel(const PatchInterpolant& patch, double delta, double s_contact, const Material& material,
                                KpecVirtualLevel* virtual_level) {
  EquivalentEllipse& combined = virtual_level->combined;
  std::vector<EquivalentEllipse>& wells = virtual_level->wells;
  double& separation_weight = virtual_level->separation_weight;
  // KPEC step 2: equivalent Hertz problem from the eps = 0.5 region (CONTACT m_snorm.f90,
  // docs/physics-reference.md §3.3).
  auto half_region = [&](double s) { return 0.5 * delta - patch.gap(s); };
  auto half_region_node = [&](size_t k) { return 0.5 * delta - patch.node_gaps()[k]; };  // = half_region(nodes[k])
  const double f0 = half_region(s_contact);
  if (!(f0 > 0.0)) return KpecBuild::NoRegion;
  auto ellipse_for = [&](double A, double half_width, double s_mid, double approach, EquivalentEllipse* out) {
    const double B = 0.5 * approach / (half_width * half_width);
    const HertzResult hertz = SolveHertzForApproach(A, B, approach, material);
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
    return KpecBuild::NoEllipse;
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
  return KpecBuild::Ok;
}

}  // namespace kp_detail
}  // namespace conforma
