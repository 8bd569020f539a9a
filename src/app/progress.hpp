#pragma once
// Progress display of the long commands on stderr (issue 17): a bar redrawn in place when stderr is a terminal, one
// plain line per step otherwise, nothing with the global --quiet. Progress never goes to stdout, so the results a
// command prints there are the same with or without it.
//
//   bar:   "[label] [############..................] 3/7 step, <detail>, elapsed 12 s, ETA 16 s"
//   lines: "label: 3/7 step <detail> elapsed 12.3 s ETA 16 s"
//
// ETA = mean time per unit so far x units left (elapsed / done x (total - done)); left out before the first unit
// and when the total is unknown (<= 0). Bar redraws are limited to 10 per second (the last unit is always drawn).
// Lines: one per update, except that a run of more than 100 units (bench or stress cases, LUT nodes) prints one
// line per 5 % of the total (and the last unit); SetLineStep changes that granularity (the dynamics: simulated s).
#include <functional>
#include <mutex>
#include <ostream>
#include <string>

#include "conforma/progress.hpp"

namespace CLI {
class App;
}  // namespace CLI

namespace conforma::cli {

enum class ProgressMode {
  Bar,    // one line redrawn in place ("\r"), for a terminal
  Lines,  // one newline-terminated line per shown update, for a log file or a pipe
  Quiet,  // nothing (--quiet)
};

// Quiet when `quiet`, else Bar when stderr is a terminal, else Lines.
ProgressMode StderrProgressMode(bool quiet);
// The mode of a subcommand's progress: the root app's --quiet flag, and whether stderr is a terminal.
ProgressMode ProgressModeOf(const CLI::App* command);

// Seconds on a monotonic clock (std::chrono::steady_clock); the reporter's default clock.
double SteadySeconds();
// Columns of the terminal on stderr; 0 when stderr is not a terminal or its width is not known.
int StderrColumns();

class ProgressReporter {
 public:
  // label: "[label]" of the bar, "label:" of the lines; total: units of the whole run (<= 0: unknown); unit: the noun
  // after the count ("step", "case"; "s" for simulated seconds); now_s: the clock (seconds; tests give a fake one).
  ProgressReporter(std::string label, double total, std::string unit, ProgressMode mode, std::ostream& out,
                   std::function<double()> now_s = &SteadySeconds);
  ~ProgressReporter();  // Finish()
  ProgressReporter(const ProgressReporter&) = delete;
  ProgressReporter& operator=(const ProgressReporter&) = delete;

  // Counts shown with this many decimals (default 0: "3/7"; the dynamics: 2, "1.20/5.00 s").
  void SetDecimals(int decimals);
  // Bar mode: cut the bar text to this many characters (0: no limit), so that it stays on one terminal line
  // ("\r" returns to the start of the last line only). Default: the width of stderr's terminal less 1 when `out` is
  // std::cerr, else no limit.
  void SetMaxWidth(int columns);
  // Lines mode: print when `done` has advanced by at least `step` units since the last printed line (and the last
  // unit); 0: every update.
  void SetLineStep(double step);
  // `done` units of the total finished; detail: what the last one was ("km 120, Sd 32.10 mm"). Thread-safe; a done
  // below one already shown is ignored (updates from parallel loops).
  void Update(double done, const std::string& detail = std::string());
  // The same with the total given (a library runner knows it: conforma/progress.hpp).
  void Update(double done, double total, const std::string& detail);
  // A ProgressFunction (conforma/progress.hpp) for a library runner's Options that updates this reporter, total
  // included; the reporter must outlive the run.
  ProgressFunction Function();
  // Bar: erases the bar line so that text printed next (stdout on the same terminal) starts on a clean line; the
  // next Update draws it again. Lines, Quiet: nothing.
  void Suspend();
  // Bar: ends the bar's line (once). Lines, Quiet: nothing.
  void Finish();

  // The text of one bar / one line (no "\r", no newline), for the given state: what Update draws.
  static std::string BarText(const std::string& label, double done, double total, const std::string& unit,
                             int decimals, const std::string& detail, double elapsed_s);
  static std::string LineText(const std::string& label, double done, double total, const std::string& unit,
                              int decimals, const std::string& detail, double elapsed_s);
  // Seconds left at the mean time per unit so far; negative when not known (done <= 0, total <= 0).
  static double EtaSeconds(double done, double total, double elapsed_s);

 private:
  void UpdateLocked(double done, const std::string& detail);

  std::string label_, unit_;
  double total_;
  ProgressMode mode_;
  std::ostream& out_;
  std::function<double()> now_s_;
  double start_s_;
  int decimals_ = 0;
  int max_width_ = 0;
  double line_step_;
  bool line_step_set_ = false;   // SetLineStep called: the total does not choose the step
  double shown_done_ = -1.0;     // the largest done shown (or accepted) so far
  double last_line_done_ = 0.0;  // Lines: done of the last printed line
  double last_draw_s_ = -1e300;  // Bar: time of the last redraw
  bool bar_open_ = false;        // Bar: a bar line is on the terminal without its newline
  std::mutex mutex_;
};

}  // namespace conforma::cli
