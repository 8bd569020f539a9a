// Strip-collocation pressure rule of the KP solvers (kp_strip_collocation.hpp; docs/physics-reference.md §5.3).
#include "kp_strip_collocation.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "kp_strip_integrals.hpp"

namespace conforma {
namespace kp_detail {

namespace {

// Strip collocation (docs/physics-reference.md §5.3): cut of the virtual range (fraction of its width) from which a
// second collocation solve is blended in, fully at the upper value
constexpr double kCollocationRecutLow = 0.02;
constexpr double kCollocationRecutHigh = 0.06;
// Strip collocation (§5.3): a coarse strip whose virtual half-length is below this fraction of its lobe's largest has
// its contact condition blended with KP's constant ratio P / c (CollocationEdgeTie), the weight of the contact
// condition rising smoothly from 0 at c = 0 to 1 here. A Hertzian lobe's outermost coarse strip has
// c / c_max >= sqrt(1 - (1 - 1/n)^2), 0.42 for n = 11, so Hertzian lobes keep the pure collocation.
constexpr double kCollocationEdgeBlend = 0.1;

}  // namespace

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

bool CollocateStripPressure(const PatchInterpolant& patch, const std::vector<ContactRange>& lobes, int per_lobe,
                            int collocation_strips, const StripLayer& strips_on, double delta,
                            const ElasticConstants& elastic, bool blanco, double coupling_K, ContactRange* contact_range,
                            std::vector<KpStrip>* laid_strips, std::vector<double>* strip_peaks) {
  ContactRange& range = *contact_range;
  std::vector<KpStrip>& strips = *laid_strips;
  std::vector<double>& peaks = *strip_peaks;
  int n = static_cast<int>(strips.size());
  // §5.3: the amplitudes collocated on `nodes` coarse strips in each lobe of the contact range (the strips
  // themselves when nodes >= n); their ratio peak / c, constant on a Hertzian patch, interpolated linearly onto the
  // strips within each lobe (constant beyond its outer coarse centres). Coarse strips per lobe: laid over the span
  // of all lobes, a coarse centre falling into an entering lobe brought a finite half-length at once (issue 15).
  const int nodes = std::min(collocation_strips, per_lobe);
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
    return false;
  }
  const std::vector<ContactRange> range1 = cut_lobes(first);
  const double width0 = total_width(coarse_lobes);
  const double cut_fraction = width0 > 0.0 ? 1.0 - total_width(range1) / width0 : 0.0;
  const double blend = std::clamp((cut_fraction - kCollocationRecutLow) / (kCollocationRecutHigh - kCollocationRecutLow),
                                  0.0, 1.0);
  std::vector<ContactRange> final_lobes = range1;
  if (blend > 0.0) {
    if (!solve_on(range1, second)) {
      return false;
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
      strips = strips_on(final_edges);
      n = static_cast<int>(strips.size());
      peaks.assign(n, 0.0);
    }
  }
  for (int j = 0; j < n; ++j) {
    const double s_j = strips[j].s_m;
    const double ratio = blend > 0.0 ? (1.0 - blend) * ratio_at(first, s_j) + blend * ratio_at(second, s_j)
                                     : ratio_at(first, s_j);
    peaks[j] = strips[j].half_length_m * ratio;
  }
  return true;
}

}  // namespace kp_detail
}  // namespace conforma
