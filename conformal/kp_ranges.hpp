#pragma once
// Private to the KP solvers: the ranges of s where a function of the patch is positive (the contact range and its
// lobes, docs/physics-reference.md §3.1 / §3.3 / §5.3) and the strips laid over them.
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "conforma/root_finding.hpp"
#include "kp_patch_interpolant.hpp"

namespace conforma {
namespace kp_detail {

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

// Strip edges over the lobes of the contact range clipped to [low, high], `per_lobe` equal strips in each lobe
// (kp_ranges.cpp).
std::vector<std::pair<double, double>> StripEdges(const std::vector<ContactRange>& lobes, double low, double high,
                                                  int per_lobe);

}  // namespace kp_detail
}  // namespace conforma
