// Track irregularities: synthesis from a PSD, measured files, evaluation along the track (track_irregularity.hpp;
// docs/physics-reference.md §15.2).
#include "conforma/track_irregularity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <utility>

#include "conforma/csv_columns.hpp"
#include "conforma/error.hpp"

namespace conforma {

namespace {

constexpr double kMaxSynthesisEvaluations = 5e9;  // TrackIrregularityOptions::validate

constexpr double kTwoPi = 6.283185307179586476925286766559;

// Uniform phase in [0, 2 pi) from the top 53 bits of the generator (the conversion is fully specified, unlike
// std::uniform_real_distribution's).
double Phase(std::mt19937_64& generator) { return kTwoPi * static_cast<double>(generator() >> 11) * 0x1.0p-53; }

// Independent stream per component: the seed mixed with the component number (splitmix64 finaliser).
std::mt19937_64 ComponentGenerator(std::uint64_t seed, std::uint64_t component) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ull * (component + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return std::mt19937_64(z ^ (z >> 31));
}

// x_j = sum_k a_k cos(Omega_k s_j + phi_k) and its slope at s_j = j ds, j = 0..n (eq. 15.4). Each harmonic is
// advanced by a rotation (one complex multiplication per sample), re-started from std::cos/sin every 256 samples
// so that the rounding of the recurrence stays at a few ulp.
void SumHarmonics(IrregularitySpectrum spectrum, IrregularityComponent component, const TrackIrregularityOptions& o,
                  int n, std::uint64_t stream, std::vector<double>* value, std::vector<double>* slope) {
  value->assign(n + 1, 0.0);
  if (slope) slope->assign(n + 1, 0.0);
  std::mt19937_64 generator = ComponentGenerator(o.seed, stream);
  const double L = n * o.spacing_m;
  const double d_omega = kTwoPi / L;
  const int k_min = std::max(1, static_cast<int>(std::ceil(L / o.wavelength_max_m - 1e-9)));
  const int k_max = static_cast<int>(std::floor(L / o.wavelength_min_m + 1e-9));
  for (int k = 1; k <= k_max; ++k) {
    const double phi = Phase(generator);  // drawn for every k, so the band does not shift the phases of the others
    if (k < k_min) continue;
    const double omega = k * d_omega;
    const double a = std::sqrt(2.0 * IrregularityPsd(spectrum, component, omega) * d_omega);
    const double step_c = std::cos(omega * o.spacing_m), step_s = std::sin(omega * o.spacing_m);
    double c = 0.0, s = 0.0;
    for (int j = 0; j <= n; ++j) {
      if (j % 256 == 0) {
        const double arg = omega * (j * o.spacing_m) + phi;
        c = std::cos(arg);
        s = std::sin(arg);
      }
      (*value)[j] += a * c;
      if (slope) (*slope)[j] -= a * omega * s;
      const double c_next = c * step_c - s * step_s;
      s = s * step_c + c * step_s;
      c = c_next;
    }
  }
}

std::vector<double> CentralSlopes(const std::vector<double>& s, const std::vector<double>& x) {
  const size_t n = s.size();
  std::vector<double> d(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    const size_t a = i == 0 ? 0 : i - 1, b = i + 1 == n ? n - 1 : i + 1;
    d[i] = (x[b] - x[a]) / (s[b] - s[a]);
  }
  return d;
}

}  // namespace

void TrackIrregularityOptions::validate() const {
  auto positive = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw InputError(std::string("track irregularity: ") + name + " must be finite and > 0, got " + MessageNumber(v));
  };
  positive(length_m, "length_m");
  positive(spacing_m, "spacing_m");
  positive(wavelength_min_m, "wavelength_min_m");
  positive(wavelength_max_m, "wavelength_max_m");
  if (wavelength_max_m < wavelength_min_m)
    throw InputError("track irregularity: wavelength_max_m " + MessageNumber(wavelength_max_m) +
                     " < wavelength_min_m " + MessageNumber(wavelength_min_m));
  if (wavelength_max_m > length_m)
    throw InputError("track irregularity: wavelength_max_m " + MessageNumber(wavelength_max_m) +
                     " exceeds length_m " + MessageNumber(length_m) + " (the longest wave must fit the track)");
  if (spacing_m > wavelength_min_m / 4.0)
    throw InputError("track irregularity: spacing_m " + MessageNumber(spacing_m) +
                     " is coarser than wavelength_min_m / 4 = " + MessageNumber(wavelength_min_m / 4.0));
  if (length_m / spacing_m > 1e8) throw InputError("track irregularity: more than 1e8 samples (length_m / spacing_m)");
  // the synthesis sums every harmonic at every sample: (length / wavelength_min) (length / spacing) evaluations,
  // quadratic in the length (4e4 m took 14 s, 2.5e5 m did not finish in a minute: fuzzing, session 25)
  const double evaluations = (length_m / wavelength_min_m) * (length_m / spacing_m);
  if (evaluations > kMaxSynthesisEvaluations) {
    char text[300];
    std::snprintf(text, sizeof text, "track irregularity: length_m = %g m needs %.3g harmonic evaluations, more than "
                  "%.0g (~30 s): a shorter length (the signal repeats after it) or a coarser spacing_m / longer "
                  "wavelength_min_m", length_m, evaluations, kMaxSynthesisEvaluations);
    throw InputError(text);
  }
}

TrackIrregularity::TrackIrregularity(std::string source, std::vector<double> s_m, std::vector<double> alignment_m,
                                     std::vector<double> alignment_slope, std::vector<double> vertical_level_m,
                                     std::vector<double> cross_level_rad)
    : source_(std::move(source)), s_(std::move(s_m)), alignment_(std::move(alignment_m)),
      slope_(std::move(alignment_slope)), level_(std::move(vertical_level_m)), cross_(std::move(cross_level_rad)) {
  const size_t n = s_.size();
  if (n < 2) throw InputError("track irregularity " + source_ + ": needs at least 2 samples");
  if (level_.empty()) level_.assign(n, 0.0);
  if (cross_.empty()) cross_.assign(n, 0.0);
  if (slope_.empty() && alignment_.size() == n) slope_ = CentralSlopes(s_, alignment_);
  if (alignment_.size() != n || slope_.size() != n || level_.size() != n || cross_.size() != n)
    throw InputError("track irregularity " + source_ + ": columns of different lengths");
  for (size_t i = 0; i < n; ++i) {
    if (!std::isfinite(s_[i]) || !std::isfinite(alignment_[i]) || !std::isfinite(slope_[i]) ||
        !std::isfinite(level_[i]) || !std::isfinite(cross_[i]))
      throw InputError("track irregularity " + source_ + ": non-finite value at sample " + std::to_string(i));
    if (i > 0 && !(s_[i] > s_[i - 1]))
      throw InputError("track irregularity " + source_ + ": s is not strictly increasing at sample " +
                       std::to_string(i) + " (s = " + MessageNumber(s_[i]) + " m)");
  }
}

TrackIrregularitySample TrackIrregularity::At(double s) const {
  if (s_.empty()) throw InputError("track irregularity: empty (no samples)");
  if (!(s >= s_.front() && s <= s_.back()))
    throw InputError("track irregularity " + source_ + ": s = " + MessageNumber(s, 9) + " m outside [" +
                     MessageNumber(s_.front(), 9) + ", " + MessageNumber(s_.back(), 9) + "] m");
  size_t i = static_cast<size_t>(std::upper_bound(s_.begin(), s_.end(), s) - s_.begin());
  i = std::min(std::max<size_t>(i, 1), s_.size() - 1) - 1;  // interval [s_i, s_{i+1}]
  const double h = s_[i + 1] - s_[i];
  const double t = (s - s_[i]) / h;
  // cubic Hermite basis in the alignment (value and slope at both ends)
  const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
  const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
  const double d00 = 6 * t * t - 6 * t, d10 = 3 * t * t - 4 * t + 1, d01 = -d00, d11 = 3 * t * t - 2 * t;
  TrackIrregularitySample out;
  out.alignment_m = h00 * alignment_[i] + h10 * h * slope_[i] + h01 * alignment_[i + 1] + h11 * h * slope_[i + 1];
  out.alignment_slope =
      (d00 * alignment_[i] + d01 * alignment_[i + 1]) / h + d10 * slope_[i] + d11 * slope_[i + 1];
  out.vertical_level_m = (1 - t) * level_[i] + t * level_[i + 1];
  out.cross_level_rad = (1 - t) * cross_[i] + t * cross_[i + 1];
  return out;
}

TrackIrregularity PerfectTrack(double length_m) {
  if (!(length_m > 0.0) || !std::isfinite(length_m))
    throw InputError("perfect track: length_m must be finite and > 0, got " + MessageNumber(length_m));
  return TrackIrregularity("perfect track", {0.0, length_m}, {0.0, 0.0}, {0.0, 0.0}, {}, {});
}

TrackIrregularity SynthesizeTrackIrregularity(const TrackIrregularityOptions& o) {
  o.validate();
  const int n = static_cast<int>(std::lround(o.length_m / o.spacing_m));
  TrackIrregularityOptions grid = o;
  grid.spacing_m = o.length_m / n;  // L an exact multiple of the spacing: the signal is L-periodic
  std::vector<double> s(n + 1), alignment, slope, level, cross;
  for (int j = 0; j <= n; ++j) s[j] = j * grid.spacing_m;
  SumHarmonics(o.spectrum, IrregularityComponent::Alignment, grid, n, 0, &alignment, &slope);
  SumHarmonics(o.spectrum, IrregularityComponent::VerticalLevel, grid, n, 1, &level, nullptr);
  if (o.cross_level && HasCrossLevelSpectrum(o.spectrum)) SumHarmonics(o.spectrum, IrregularityComponent::CrossLevel, grid, n, 2, &cross, nullptr);
  char source[160];
  std::snprintf(source, sizeof source, "%s seed %llu, %.6g m, wavelengths %.6g-%.6g m", to_string(o.spectrum),
                static_cast<unsigned long long>(o.seed), o.length_m, o.wavelength_min_m, o.wavelength_max_m);
  return TrackIrregularity(source, std::move(s), std::move(alignment), std::move(slope), std::move(level),
                           std::move(cross));
}

TrackIrregularity ReadTrackIrregularityCsv(const std::string& path) {
  const std::vector<std::string> names = {"s_m", "alignment_m", "vertical_level_m", "cross_level_rad",
                                          "alignment_slope"};
  CsvColumns t = ReadCsvColumns(path, names, 2);
  if (t.rows() < 2) throw InputError(path, 0, "needs at least 2 samples");
  for (size_t i = 1; i < t.rows(); ++i)
    if (!(t.values[0][i] > t.values[0][i - 1]))
      throw InputError(path, t.line[i], "column 's_m' must be strictly increasing");
  return TrackIrregularity(path, std::move(t.values[0]), std::move(t.values[1]), std::move(t.values[4]),
                           std::move(t.values[2]), std::move(t.values[3]));
}

void WriteTrackIrregularityCsv(const TrackIrregularity& track, const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw InputError(path, 0, "cannot write track irregularity file");
  std::fprintf(f, "# %s\ns_m,alignment_m,alignment_slope,vertical_level_m,cross_level_rad\n", track.source().c_str());
  for (size_t i = 0; i < track.s().size(); ++i)
    std::fprintf(f, "%.17g,%.17g,%.17g,%.17g,%.17g\n", track.s()[i], track.alignment()[i], track.alignment_slope()[i],
                 track.vertical_level()[i], track.cross_level()[i]);
  if (std::fclose(f) != 0) throw InputError(path, 0, "error writing track irregularity file");
}

}  // namespace conforma
