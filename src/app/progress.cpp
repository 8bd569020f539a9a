// Progress display of the long commands (progress.hpp).
#include "progress.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <utility>

namespace conforma::cli {

namespace {

constexpr int kBarWidth = 30;            // characters between the brackets
constexpr double kMinRedrawS = 0.1;      // bar: at most 10 redraws per second
constexpr double kManyUnits = 100.0;     // lines: above this many units, one line per 5 %
constexpr double kManyUnitsFraction = 0.05;

std::string Count(double v, int decimals) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f", decimals, v);
  return b;
}

// "3/7 step" (total unknown: "3 step")
std::string Counts(double done, double total, const std::string& unit, int decimals) {
  std::string s = Count(done, decimals);
  if (total > 0.0) s += "/" + Count(total, decimals);
  if (!unit.empty()) s += " " + unit;
  return s;
}

// whole seconds for the bar, one decimal for the log lines
std::string Seconds(double s, int decimals) {
  char b[64];
  std::snprintf(b, sizeof b, "%.*f s", decimals, std::max(0.0, s));
  return b;
}

}  // namespace

ProgressMode StderrProgressMode(bool quiet) {
  if (quiet) return ProgressMode::Quiet;
  return isatty(fileno(stderr)) ? ProgressMode::Bar : ProgressMode::Lines;
}

ProgressMode ProgressModeOf(const CLI::App* command) {
  const CLI::App* root = command;
  while (root->get_parent() != nullptr) root = root->get_parent();
  bool quiet = false;
  try {
    quiet = root->get_option("--quiet")->count() > 0;
  } catch (const CLI::OptionNotFound&) {  // an app without the flag (none in conforma): progress shown
  }
  return StderrProgressMode(quiet);
}

int StderrColumns() {
  winsize w{};
  if (ioctl(fileno(stderr), TIOCGWINSZ, &w) != 0) return 0;
  return w.ws_col;
}

double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

ProgressReporter::ProgressReporter(std::string label, double total, std::string unit, ProgressMode mode,
                                   std::ostream& out, std::function<double()> now_s)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      mode_(mode),
      out_(out),
      now_s_(std::move(now_s)),
      start_s_(now_s_()),
      line_step_(total > kManyUnits ? kManyUnitsFraction * total : 0.0) {
  if (mode_ == ProgressMode::Bar && &out_ == &std::cerr) max_width_ = std::max(0, StderrColumns() - 1);
}

ProgressReporter::~ProgressReporter() { Finish(); }

void ProgressReporter::SetDecimals(int decimals) {
  std::lock_guard<std::mutex> lock(mutex_);
  decimals_ = std::clamp(decimals, 0, 9);
}

void ProgressReporter::SetMaxWidth(int columns) {
  std::lock_guard<std::mutex> lock(mutex_);
  max_width_ = std::max(0, columns);
}

void ProgressReporter::SetLineStep(double step) {
  std::lock_guard<std::mutex> lock(mutex_);
  line_step_ = std::max(0.0, step);
  line_step_set_ = true;
}

double ProgressReporter::EtaSeconds(double done, double total, double elapsed_s) {
  if (!(done > 0.0) || !(total > 0.0)) return -1.0;
  return elapsed_s / done * std::max(0.0, total - done);
}

std::string ProgressReporter::BarText(const std::string& label, double done, double total, const std::string& unit,
                                      int decimals, const std::string& detail, double elapsed_s) {
  std::string s = "[" + label + "] ";
  if (total > 0.0) {
    const int filled = std::clamp(static_cast<int>(std::floor(kBarWidth * done / total)), 0, kBarWidth);
    s += "[" + std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "] ";
  }
  s += Counts(done, total, unit, decimals);
  if (!detail.empty()) s += ", " + detail;
  s += ", elapsed " + Seconds(elapsed_s, 0);
  const double eta = EtaSeconds(done, total, elapsed_s);
  if (eta >= 0.0) s += ", ETA " + Seconds(eta, 0);
  return s;
}

std::string ProgressReporter::LineText(const std::string& label, double done, double total, const std::string& unit,
                                       int decimals, const std::string& detail, double elapsed_s) {
  std::string s = label + ": " + Counts(done, total, unit, decimals);
  if (!detail.empty()) s += " " + detail;
  s += " elapsed " + Seconds(elapsed_s, 1);
  const double eta = EtaSeconds(done, total, elapsed_s);
  if (eta >= 0.0) s += " ETA " + Seconds(eta, 0);
  return s;
}

void ProgressReporter::Update(double done, const std::string& detail) {
  if (mode_ == ProgressMode::Quiet) return;
  std::lock_guard<std::mutex> lock(mutex_);
  UpdateLocked(done, detail);
}

void ProgressReporter::Update(double done, double total, const std::string& detail) {
  if (mode_ == ProgressMode::Quiet) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (total != total_) {
    total_ = total;
    if (!line_step_set_) line_step_ = total > kManyUnits ? kManyUnitsFraction * total : 0.0;
  }
  UpdateLocked(done, detail);
}

ProgressFunction ProgressReporter::Function() {
  return [this](double done, double total, const std::string& what) { Update(done, total, what); };
}

void ProgressReporter::UpdateLocked(double done, const std::string& detail) {
  if (done < shown_done_) return;  // an older update overtaken by a newer one
  shown_done_ = done;
  const double now = now_s_();
  const double elapsed = now - start_s_;
  const bool last = total_ > 0.0 && done >= total_;
  if (mode_ == ProgressMode::Bar) {
    if (!last && now - last_draw_s_ < kMinRedrawS) return;
    last_draw_s_ = now;
    // "\033[K": erase the rest of the line (a shorter bar than the previous one leaves nothing behind)
    std::string text = BarText(label_, done, total_, unit_, decimals_, detail, elapsed);
    if (max_width_ > 0 && static_cast<int>(text.size()) > max_width_) text.resize(max_width_);
    out_ << "\r" + text + "\033[K" << std::flush;
    bar_open_ = true;
    return;
  }
  if (!last && line_step_ > 0.0 && done - last_line_done_ < line_step_ * (1.0 - 1e-9)) return;
  last_line_done_ = done;
  out_ << LineText(label_, done, total_, unit_, decimals_, detail, elapsed) + "\n" << std::flush;
}

void ProgressReporter::Suspend() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (mode_ != ProgressMode::Bar || !bar_open_) return;
  out_ << "\r\033[K" << std::flush;
  bar_open_ = false;
  last_draw_s_ = -1e300;  // the next update draws at once
}

void ProgressReporter::Finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (mode_ != ProgressMode::Bar || !bar_open_) return;
  out_ << "\n" << std::flush;
  bar_open_ = false;
}

}  // namespace conforma::cli
