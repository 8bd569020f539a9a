// conforma track irregularity: synthesise track irregularities from a published PSD (track_irregularity.hpp), write
// them as CSV and report their standard deviations against the PSD's band integral.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.hpp"
#include "conforma/track_irregularity.hpp"

namespace conforma::cli {

namespace {

struct IrregularityArgs {
  std::string spectrum = "ore_b176_low", out = "track_irregularity.csv";
  TrackIrregularityOptions options;
};

double RootMeanSquare(const std::vector<double>& x) {  // one period: the last sample repeats the first
  double sum = 0.0;
  for (size_t i = 0; i + 1 < x.size(); ++i) sum += x[i] * x[i];
  return x.size() > 1 ? std::sqrt(sum / (x.size() - 1)) : 0.0;
}

void RunIrregularity(IrregularityArgs a) {
  a.options.spectrum = ParseIrregularitySpectrum(a.spectrum);
  const TrackIrregularity t = SynthesizeTrackIrregularity(a.options);
  WriteTrackIrregularityCsv(t, a.out);
  const double pi2 = 6.283185307179586;
  const double w0 = pi2 / a.options.wavelength_max_m, w1 = pi2 / a.options.wavelength_min_m;
  std::printf("%s: %zu samples every %.4g m over %.6g m -> %s\n", t.source().c_str(), t.s().size(),
              t.s()[1] - t.s()[0], t.s_end(), a.out.c_str());
  struct Row { const char* name; IrregularityComponent c; const std::vector<double>* x; double unit; const char* u; };
  const Row rows[] = {{"alignment", IrregularityComponent::Alignment, &t.alignment(), 1e3, "mm"},
                      {"vertical level", IrregularityComponent::VerticalLevel, &t.vertical_level(), 1e3, "mm"},
                      {"cross-level", IrregularityComponent::CrossLevel, &t.cross_level(), 1e3, "mrad"}};
  for (const Row& r : rows) {
    const bool has_psd = r.c != IrregularityComponent::CrossLevel || HasCrossLevelSpectrum(a.options.spectrum);
    if (!has_psd || (r.c == IrregularityComponent::CrossLevel && !a.options.cross_level)) {
      std::printf("  %-15s not synthesised\n", r.name);
      continue;
    }
    std::printf("  %-15s standard deviation %.4f %s (PSD band integral %.4f %s)\n", r.name,
                RootMeanSquare(*r.x) * r.unit, r.u,
                std::sqrt(IrregularityBandVariance(a.options.spectrum, r.c, w0, w1)) * r.unit, r.u);
  }
}

}  // namespace

void RegisterTrackCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("track", "track geometry tools");
  sub->require_subcommand(1);
  auto a = std::make_shared<IrregularityArgs>();
  CLI::App* irr = sub->add_subcommand(
      "irregularity", "synthesise track irregularities from a published PSD (seeded, reproducible) into a CSV file");
  irr->add_option("--spectrum", a->spectrum, "ore_b176_low, ore_b176_high, fra_class_1 ... fra_class_6")
      ->capture_default_str();
  irr->add_option("--length-m", a->options.length_m, "synthesised length (the signal repeats after it)")
      ->capture_default_str();
  irr->add_option("--spacing-m", a->options.spacing_m, "sample spacing")->capture_default_str();
  irr->add_option("--wavelength-min-m", a->options.wavelength_min_m, "shortest wavelength")->capture_default_str();
  irr->add_option("--wavelength-max-m", a->options.wavelength_max_m, "longest wavelength")->capture_default_str();
  irr->add_option("--seed", a->options.seed, "random phases")->capture_default_str();
  irr->add_flag("!--no-cross-level", a->options.cross_level, "leave the cross-level at 0");
  irr->add_option("--out", a->out, "CSV file (s_m, alignment_m, alignment_slope, vertical_level_m, cross_level_rad)")
      ->capture_default_str();
  irr->callback([a]() { RunIrregularity(*a); });
}

}  // namespace conforma::cli
