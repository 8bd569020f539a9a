// Track irregularities (track_irregularity.hpp, track_irregularity_psd.hpp): the PSDs against a published table, the
// band integrals against quadrature, the synthesised signal's variance and periodogram against the PSD,
// reproducibility, interpolation, files and errors.
// test-links: track  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/track_irregularity.hpp"

namespace conforma {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
using C = IrregularityComponent;
using S = IrregularitySpectrum;

// ORE B176 "high level" as tabulated in GENSYS' TRC_IPSD manual (www.gensys.se, trc_ipsd), in m^2/(1/m) over the
// spatial frequency f = 1/lambda: S_f(f) = 2 pi S(Omega = 2 pi f).
TEST(TrackIrregularityPsd, OreB176HighMatchesThePublishedGensysTable) {
  struct Row { double f, lateral, vertical; };
  const Row rows[] = {{0.02, 2.3194e-4, 4.0897e-4}, {0.1, 6.1608e-6, 1.0863e-5}, {0.2, 7.3333e-7, 1.2931e-6}};
  for (const Row& r : rows) {
    const double omega = kTwoPi * r.f;
    EXPECT_NEAR(kTwoPi * IrregularityPsd(S::OreB176High, C::Alignment, omega) / r.lateral, 1.0, 5e-4) << r.f;
    EXPECT_NEAR(kTwoPi * IrregularityPsd(S::OreB176High, C::VerticalLevel, omega) / r.vertical, 1.0, 5e-4) << r.f;
  }
}

// The closed-form band integrals (partial fractions) against composite Simpson on a log-spaced grid.
TEST(TrackIrregularityPsd, BandVarianceEqualsTheQuadratureOfThePsd) {
  const double w0 = kTwoPi / 150.0, w1 = kTwoPi / 3.0;
  for (S s : {S::OreB176Low, S::OreB176High, S::FraClass1, S::FraClass4, S::FraClass6}) {
    for (C c : {C::Alignment, C::VerticalLevel, C::CrossLevel}) {
      const bool ore = s == S::OreB176Low || s == S::OreB176High;
      if (!ore && c == C::CrossLevel) {
        EXPECT_THROW(IrregularityPsd(s, c, 1.0), InputError);
        continue;
      }
      const int n = 20000;  // Simpson in t = ln Omega: integrand S(Omega) Omega
      const double h = (std::log(w1) - std::log(w0)) / n;
      double sum = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double w = std::exp(std::log(w0) + i * h);
        const double f = IrregularityPsd(s, c, w) * w;
        sum += (i == 0 || i == n) ? f : (i % 2 ? 4 * f : 2 * f);
      }
      const double quadrature = sum * h / 3.0;
      EXPECT_NEAR(IrregularityBandVariance(s, c, w0, w1) / quadrature, 1.0, 1e-9) << to_string(s) << " " << int(c);
    }
  }
  // the high level is the rougher track: larger standard deviation in every component
  EXPECT_GT(IrregularityBandVariance(S::OreB176High, C::Alignment, w0, w1),
            IrregularityBandVariance(S::OreB176Low, C::Alignment, w0, w1));
  EXPECT_GT(IrregularityBandVariance(S::FraClass4, C::Alignment, w0, w1),
            IrregularityBandVariance(S::FraClass6, C::Alignment, w0, w1));
}

TrackIrregularityOptions Options(S spectrum, std::uint64_t seed) {
  TrackIrregularityOptions o;
  o.spectrum = spectrum;
  o.length_m = 1000.0;
  o.spacing_m = 0.25;
  o.wavelength_min_m = 3.0;
  o.wavelength_max_m = 150.0;
  o.seed = seed;
  return o;
}

double MeanSquare(const std::vector<double>& x) {  // over one period (the last sample repeats the first)
  double sum = 0.0;
  for (size_t i = 0; i + 1 < x.size(); ++i) sum += x[i] * x[i];
  return sum / (x.size() - 1);
}

// Variance over one period = sum_k a_k^2 / 2 = sum_k S(Omega_k) dOmega exactly (discrete orthogonality), and that
// midpoint rule converges to the band integral over [(k_min - 1/2), (k_max + 1/2)] dOmega; standard deviations of a
// few mm (ORE high alignment ~3.6 mm over 3-150 m; FRA class 5 ~6.6 mm, its 1/Omega^2 long-wave end).
TEST(TrackIrregularity, VarianceOfTheSynthesisedTrackEqualsTheBandIntegral) {
  for (S s : {S::OreB176Low, S::OreB176High, S::FraClass5}) {
    const TrackIrregularityOptions o = Options(s, 7);
    const TrackIrregularity t = SynthesizeTrackIrregularity(o);
    const double d_omega = kTwoPi / o.length_m;
    const int k_min = 7, k_max = 333;  // wavelengths 142.9 ... 3.003 m
    for (C c : {C::Alignment, C::VerticalLevel, C::CrossLevel}) {
      const std::vector<double>& x =
          c == C::Alignment ? t.alignment() : (c == C::VerticalLevel ? t.vertical_level() : t.cross_level());
      if (s == S::FraClass5 && c == C::CrossLevel) {
        EXPECT_EQ(MeanSquare(x), 0.0);
        continue;
      }
      double rectangle = 0.0;
      for (int k = k_min; k <= k_max; ++k) rectangle += IrregularityPsd(s, c, k * d_omega) * d_omega;
      EXPECT_NEAR(MeanSquare(x) / rectangle, 1.0, 1e-9) << to_string(s) << " " << int(c);
      const double band = IrregularityBandVariance(s, c, (k_min - 0.5) * d_omega, (k_max + 0.5) * d_omega);
      EXPECT_NEAR(MeanSquare(x) / band, 1.0, 0.01) << to_string(s) << " " << int(c);
    }
    const double sd = std::sqrt(MeanSquare(t.alignment()));
    EXPECT_GT(sd, 0.2e-3);
    EXPECT_LT(sd, 10e-3);
  }
}

// Periodogram: the discrete Fourier coefficient of bin k has amplitude a_k = sqrt(2 S(Omega_k) dOmega) inside the band
// and vanishes outside it.
TEST(TrackIrregularity, PeriodogramReproducesThePsdBinByBin) {
  const TrackIrregularityOptions o = Options(S::OreB176High, 3);
  const TrackIrregularity t = SynthesizeTrackIrregularity(o);
  const std::vector<double>& x = t.alignment();
  const int n = static_cast<int>(x.size()) - 1;
  const double d_omega = kTwoPi / o.length_m;
  for (int k : {2, 5, 7, 50, 200, 333, 334, 600}) {
    std::complex<double> X = 0.0;
    for (int j = 0; j < n; ++j) X += x[j] * std::polar(1.0, -kTwoPi * k * j / n);
    const double amplitude = 2.0 * std::abs(X) / n;
    const double wavelength = o.length_m / k;
    if (wavelength >= 3.0 && wavelength <= 150.0) {
      const double expected = std::sqrt(2.0 * IrregularityPsd(S::OreB176High, C::Alignment, k * d_omega) * d_omega);
      EXPECT_NEAR(amplitude / expected, 1.0, 1e-8) << k;
    } else {
      EXPECT_LT(amplitude, 1e-12) << k;
    }
  }
}

TEST(TrackIrregularity, SameSeedSameTrackOtherSeedOtherTrack) {
  const TrackIrregularity a = SynthesizeTrackIrregularity(Options(S::OreB176Low, 11));
  const TrackIrregularity b = SynthesizeTrackIrregularity(Options(S::OreB176Low, 11));
  const TrackIrregularity c = SynthesizeTrackIrregularity(Options(S::OreB176Low, 12));
  EXPECT_EQ(a.alignment(), b.alignment());
  EXPECT_EQ(a.cross_level(), b.cross_level());
  EXPECT_NE(a.alignment(), c.alignment());
  // components are independent streams: alignment and level are uncorrelated (|r| small over 4000 samples)
  double sxy = 0.0;
  for (size_t i = 0; i + 1 < a.s().size(); ++i) sxy += a.alignment()[i] * a.vertical_level()[i];
  const double r = sxy / (a.s().size() - 1) / std::sqrt(MeanSquare(a.alignment()) * MeanSquare(a.vertical_level()));
  EXPECT_LT(std::abs(r), 0.2);
}

// At(): the samples at the nodes, the analytic slope of the harmonic sum, and a slope consistent with the values.
TEST(TrackIrregularity, InterpolationHitsTheNodesAndItsSlopeIsTheDerivative) {
  const TrackIrregularity t = SynthesizeTrackIrregularity(Options(S::OreB176High, 5));
  for (size_t i : {size_t(0), size_t(17), size_t(2000), t.s().size() - 1}) {
    const TrackIrregularitySample p = t.At(t.s()[i]);
    EXPECT_DOUBLE_EQ(p.alignment_m, t.alignment()[i]);
    EXPECT_DOUBLE_EQ(p.alignment_slope, t.alignment_slope()[i]);
    EXPECT_DOUBLE_EQ(p.vertical_level_m, t.vertical_level()[i]);
  }
  // slope against the central difference of the interpolated values (h = 1 mm)
  double worst = 0.0, scale = 0.0;
  for (double s = 10.0; s < 990.0; s += 7.31) {
    const double numeric = (t.At(s + 1e-3).alignment_m - t.At(s - 1e-3).alignment_m) / 2e-3;
    worst = std::max(worst, std::abs(numeric - t.At(s).alignment_slope));
    scale = std::max(scale, std::abs(numeric));
  }
  EXPECT_LT(worst, 1e-3 * scale);
  // the stored slopes are the derivative of the harmonic sum: compare with a central difference of the nodes
  const std::vector<double>& x = t.alignment();
  const double h = t.s()[1] - t.s()[0];
  double err = 0.0, peak = 0.0;
  for (size_t i = 1; i + 1 < x.size(); ++i) {
    err = std::max(err, std::abs((x[i + 1] - x[i - 1]) / (2 * h) - t.alignment_slope()[i]));
    peak = std::max(peak, std::abs(t.alignment_slope()[i]));
  }
  EXPECT_LT(err, 0.05 * peak);  // O((Omega h)^2) with lambda_min = 3 m, h = 0.25 m: ~4 %
}

TEST(TrackIrregularity, CsvRoundTripIsBitExactAndErrorsNameTheLine) {
  const TrackIrregularity t = SynthesizeTrackIrregularity(Options(S::OreB176Low, 2));
  const std::string path = testing::TempDir() + "track_irregularity_roundtrip.csv";
  WriteTrackIrregularityCsv(t, path);
  const TrackIrregularity r = ReadTrackIrregularityCsv(path);
  EXPECT_EQ(r.s(), t.s());
  EXPECT_EQ(r.alignment(), t.alignment());
  EXPECT_EQ(r.alignment_slope(), t.alignment_slope());
  EXPECT_EQ(r.vertical_level(), t.vertical_level());
  EXPECT_EQ(r.cross_level(), t.cross_level());

  const std::string bad = testing::TempDir() + "track_irregularity_bad.csv";
  {
    std::ofstream f(bad);
    f << "# measured\ns_m, alignment_m\n0, 0.001\n1, 0.002\n1, 0.003\n";
  }
  try {
    ReadTrackIrregularityCsv(bad);
    FAIL() << "non-increasing s accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(":5:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("s_m"), std::string::npos) << e.what();
  }
  {
    std::ofstream f(bad);
    f << "s_m,level\n0,1\n1,2\n";
  }
  EXPECT_THROW(ReadTrackIrregularityCsv(bad), InputError);  // no alignment_m column
  // a measured file without slopes: central differences, level/cross-level default 0
  {
    std::ofstream f(bad);
    f << "alignment_m,s_m\n0,0\n0.002,1\n0.006,2\n";
  }
  const TrackIrregularity m = ReadTrackIrregularityCsv(bad);
  EXPECT_DOUBLE_EQ(m.At(1.0).alignment_slope, 0.003);
  EXPECT_DOUBLE_EQ(m.At(1.5).vertical_level_m, 0.0);
  std::remove(path.c_str());
  std::remove(bad.c_str());
}

TEST(TrackIrregularity, BadInputIsANamedError) {
  const TrackIrregularity t = PerfectTrack(100.0);
  EXPECT_EQ(t.At(50.0).alignment_m, 0.0);
  EXPECT_THROW(t.At(100.5), InputError);
  EXPECT_THROW(t.At(std::nan("")), InputError);
  EXPECT_THROW(PerfectTrack(-1.0), InputError);
  TrackIrregularityOptions o = Options(S::OreB176Low, 1);
  o.spacing_m = 1.0;  // coarser than lambda_min / 4
  EXPECT_THROW(SynthesizeTrackIrregularity(o), InputError);
  o = Options(S::OreB176Low, 1);
  o.wavelength_max_m = 2000.0;  // longer than the track
  EXPECT_THROW(SynthesizeTrackIrregularity(o), InputError);
  o = Options(S::OreB176Low, 1);
  o.length_m = std::nan("");
  EXPECT_THROW(SynthesizeTrackIrregularity(o), InputError);
  EXPECT_THROW(ParseIrregularitySpectrum("ore_b176_medium"), InputError);
  EXPECT_EQ(ParseIrregularitySpectrum("fra_class_4"), S::FraClass4);
  EXPECT_THROW(IrregularityPsd(S::OreB176Low, C::Alignment, 0.0), InputError);
  EXPECT_THROW(IrregularityBandVariance(S::OreB176Low, C::Alignment, 2.0, 1.0), InputError);
}

}  // namespace
}  // namespace conforma
