#pragma once
// The one scalar root finder of the project: Illinois false position on a sign-changing bracket, with a bisection
// safeguard (docs/physics-reference.md §3.6). Every bracketed root in the code (load control, contact-range ends,
// rigid wheelset equilibrium, variable-friction element slip) narrows its bracket with IllinoisBracket, so the step
// and the Illinois halving exist once.
#include <functional>

namespace conforma {

// A bracket of a root between the ends `low` and `high` (names only: low may lie above high) with f(low) and
// f(high) of opposite signs (either order of signs), narrowed by
// false position; the end kept twice in a row has its function value halved (Illinois), which restores
// superlinear convergence where plain false position keeps one end fixed.
class IllinoisBracket {
 public:
  IllinoisBracket(double low, double f_low, double high, double f_high)
      : low_(low), high_(high), f_low_(f_low), f_high_(f_high) {}
  // The false-position point (low f_high - high f_low) / (f_high - f_low).
  double FalsePosition() const { return (low_ * f_high_ - high_ * f_low_) / (f_high_ - f_low_); }
  // Replaces the end whose value has the sign of f_x (f_x on the low end's side: `on_low_side`) by (x, f_x).
  void Replace(double x, double f_x, bool on_low_side) {
    if (on_low_side) {
      low_ = x, f_low_ = f_x;
      if (kept_ == -1) f_high_ *= 0.5;
      kept_ = -1;
    } else {
      high_ = x, f_high_ = f_x;
      if (kept_ == 1) f_low_ *= 0.5;
      kept_ = 1;
    }
  }
  double low() const { return low_; }
  double high() const { return high_; }
  double f_low() const { return f_low_; }
  double f_high() const { return f_high_; }

 private:
  double low_, high_, f_low_, f_high_;
  int kept_ = 0;  // -1: the low end was replaced last, +1: the high end
};

// Root of an increasing f on [low, high] with f(low) < 0 < f(high): false position, bisection where the step
// leaves the open bracket. Stops when |f| <= tolerance_abs, the bracket is narrower than 1e-15 or after 100 steps.
// f was last evaluated at the returned x; *f_at_root is that value and *iterations the number of evaluations.
double SolveIncreasingRoot(const std::function<double(double)>& f, double low, double high, double f_low,
                           double f_high, double tolerance_abs, int* iterations, double* f_at_root);

}  // namespace conforma
