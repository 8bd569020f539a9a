// Strips over the lobes of a KP contact range (kp_ranges.hpp).
#include "kp_ranges.hpp"

namespace conforma {
namespace kp_detail {

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

}  // namespace kp_detail
}  // namespace conforma
