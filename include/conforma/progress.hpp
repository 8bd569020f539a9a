#pragma once
// Progress of a long library run, for a caller that shows it (the command line's progress display, issue 17): an
// optional callback in the Options of the long runners (bench, Manchester benchmark, threshold sweep, stress suite,
// contact LUT build and check, time-domain dynamics). It reports work done, never results: setting it or not
// changes no result, and an empty one costs nothing.
#include <functional>
#include <mutex>
#include <string>
#include <utility>

namespace conforma {

// Called after each finished unit of work with the units done so far, the total in the same unit (a count of cases,
// nodes, samples; simulated seconds for the dynamics) and a short name of what just finished ("case 7"). The
// runners call it serialized (never from two threads at once) with `done` non-decreasing, from whichever thread
// finished the unit; it must not throw (an exception from it is dropped: it must not leave a parallel loop).
using ProgressFunction = std::function<void(double done, double total, const std::string& what)>;

// Counts the finished units of a (parallel) loop and calls the ProgressFunction once per unit, serialized and in
// order (done = 1, 2, ..., total). Thread-safe; does nothing when the function is empty.
class ProgressCounter {
 public:
  ProgressCounter(ProgressFunction report, double total) : report_(std::move(report)), total_(total) {}
  // One more unit finished; `what` names it.
  void Finished(const std::string& what = std::string()) {
    if (!report_) return;
    std::lock_guard<std::mutex> lock(mutex_);
    done_ += 1.0;
    try {
      report_(done_, total_, what);
    } catch (...) {  // progress is a display: it must never abort the run (nor leave an OpenMP loop)
    }
  }

  // Calls Finished(what) when it goes out of scope, so that a loop body left early (`continue`) still counts:
  // `ProgressCounter::Unit unit(counter, "case 3");` at the top of the body.
  class Unit {
   public:
    Unit(ProgressCounter& counter, std::string what) : counter_(counter), what_(std::move(what)) {}
    Unit(const Unit&) = delete;
    Unit& operator=(const Unit&) = delete;
    ~Unit() { counter_.Finished(what_); }

   private:
    ProgressCounter& counter_;
    std::string what_;
  };

 private:
  ProgressFunction report_;
  double total_ = 0.0;
  double done_ = 0.0;
  std::mutex mutex_;
};

}  // namespace conforma
