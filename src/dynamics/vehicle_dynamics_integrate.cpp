// Time integration of the lateral vehicle model with Boost.Odeint (vehicle_dynamics.hpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include <boost/numeric/odeint.hpp>

#include "conforma/error.hpp"
#include "conforma/vehicle_dynamics.hpp"

namespace conforma {

const char* to_string(DynamicsStepper stepper) {
  switch (stepper) {
    case DynamicsStepper::Rosenbrock4: return "rosenbrock4";
    case DynamicsStepper::Dopri5: return "dopri5";
  }
  return "?";
}

const char* to_string(DynamicsStatus status) {
  switch (status) {
    case DynamicsStatus::Completed: return "completed";
    case DynamicsStatus::ContactFailed: return "contact_failed";
    case DynamicsStatus::StepTooSmall: return "step_too_small";
    case DynamicsStatus::StepLimit: return "step_limit";
    case DynamicsStatus::NonFinite: return "non_finite";
  }
  return "?";
}

void DynamicsOptions::validate() const {
  model.validate();
  require_positive(duration_s, "duration_s");
  require_positive(output_interval_s, "output_interval_s");
  // the history is kept in memory: 1e7 rows (~1 GB with a two-bogie vehicle) at the most
  if (duration_s / output_interval_s > kMaxHistoryRows) {
    char text[240];
    std::snprintf(text, sizeof text,
                  "duration_s / output_interval_s = %.6g history rows, more than %.0f: give a longer output interval",
                  duration_s / output_interval_s, kMaxHistoryRows);
    throw InputError(text);
  }
  require_positive(absolute_tolerance, "absolute_tolerance");
  require_positive(relative_tolerance, "relative_tolerance");
  require_positive(initial_step_s, "initial_step_s");
  require_positive(max_step_s, "max_step_s");
  require_positive(min_step_s, "min_step_s");
  require_positive(jacobian_step, "jacobian_step");
  if (jacobian_reuse_steps < 1) throw InputError("option 'jacobian_reuse_steps' must be >= 1");
  if (max_steps < 1) throw InputError("option 'max_steps' must be >= 1");
  require_non_negative(max_steps_per_s, "max_steps_per_s");
  require_non_negative(step_budget_grace_s, "step_budget_grace_s");
}

namespace {

namespace odeint = boost::numeric::odeint;
using Vector = boost::numeric::ublas::vector<double>;
using Matrix = boost::numeric::ublas::matrix<double>;

// Thrown out of the right-hand side to abandon a step attempt.
struct ContactFailure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The model seen by odeint, with the counters and a one-entry cache (rosenbrock4 evaluates f and the Jacobian at
// the same (x, t): the Jacobian reuses that evaluation's contact forces).
struct System {
  const VehicleDynamicsModel* model = nullptr;
  double jacobian_step = 1e-4;
  bool time_dependent = true;
  long derivatives = 0, jacobians = 0, contacts = 0;
  Eigen::VectorXd cache_x, cache_f;
  double cache_t = 0.0;
  std::vector<WheelsetDynamicsForces> cache_forces;
  Eigen::VectorXd jacobian_x;
  double jacobian_t = 0.0;
  Matrix jacobian;
  Vector jacobian_dfdt;
  int jacobian_reuse = 1, jacobian_age = 0;

  static Eigen::VectorXd ToEigen(const Vector& v) {
    Eigen::VectorXd e(v.size());
    for (size_t i = 0; i < v.size(); ++i) e[i] = v[i];
    return e;
  }
  void Evaluate(const Eigen::VectorXd& x, double t) {
    if (cache_x.size() == x.size() && cache_t == t && cache_x == x) return;
    std::string failure;
    int n = 0;
    Eigen::VectorXd f;
    std::vector<WheelsetDynamicsForces> forces;
    const bool ok = model->Derivative(x, t, &f, &forces, &failure, &n);
    ++derivatives;
    contacts += n;
    if (!ok) throw ContactFailure(failure);
    if (!f.allFinite()) throw ContactFailure("non-finite derivative at t = " + std::to_string(t) + " s");
    cache_x = x, cache_t = t, cache_f = f, cache_forces = std::move(forces);
  }
  void Derivative(const Vector& x, Vector& dxdt, double t) {
    Evaluate(ToEigen(x), t);
    dxdt.resize(x.size());
    for (size_t i = 0; i < x.size(); ++i) dxdt[i] = cache_f[i];
  }
  // Forward differences; a wheelset's contact is re-solved only for its own states, the rest reuses the cache.
  void Jacobian(const Vector& xv, Matrix& J, double t, Vector& dfdt) {
    const Eigen::VectorXd x = ToEigen(xv);
    // a step rejected by the error control is retried from the same (x, t): the same Jacobian
    if (jacobian_x.size() == x.size() && jacobian_t == t && jacobian_x == x) {
      J = jacobian, dfdt = jacobian_dfdt;
      return;
    }
    // optionally an older Jacobian (a W-method use of the Rosenbrock scheme: the error control sees the cost)
    if (jacobian_x.size() == x.size() && ++jacobian_age < jacobian_reuse) {
      J = jacobian, dfdt = jacobian_dfdt;
      return;
    }
    jacobian_age = 0;
    Evaluate(x, t);
    const Eigen::VectorXd f0 = cache_f;
    const std::vector<WheelsetDynamicsForces> F0 = cache_forces;
    const int n = static_cast<int>(x.size());
    J.resize(n, n);
    dfdt.resize(n);
    ++jacobians;
    Eigen::VectorXd fk;
    for (int k = 0; k < n; ++k) {
      Eigen::VectorXd xk = x;
      std::vector<WheelsetDynamicsForces> Fk = F0;
      const int j = model->wheelset_of_state(k);
      double h = jacobian_step;
      bool ok = true;
      xk[k] = x[k] + h;
      if (j >= 0) {
        Fk[j] = model->WheelsetForces(xk, t, j);
        contacts += Fk[j].contact_evaluations;
        if (!Fk[j].ok) {  // a step across the edge of the contact: the other side
          h = -h;
          xk[k] = x[k] + h;
          Fk[j] = model->WheelsetForces(xk, t, j);
          contacts += Fk[j].contact_evaluations;
          ok = Fk[j].ok;
        }
      }
      if (!ok) throw ContactFailure("Jacobian: " + Fk[j].failure);
      model->Assemble(xk, t, Fk, &fk);
      for (int i = 0; i < n; ++i) J(i, k) = (fk[i] - f0[i]) / h;
    }
    for (int i = 0; i < n; ++i) dfdt[i] = 0.0;
    if (time_dependent) {
      // a wheelset's contact depends on t only through the track at its station: re-solved only where the track
      // input differs between t and t + ht (transitions, irregularities), else the cached forces are exact
      const double ht = 1e-5;  // s
      std::vector<WheelsetDynamicsForces> Ft = F0;
      const TrackInput& tr = model->track();
      for (int j = 0; j < model->wheelset_count(); ++j) {
        const double s0 = model->reference_station_m(t) + model->body_position_m(model->wheelset_index(j));
        const double s1 = model->reference_station_m(t + ht) + model->body_position_m(model->wheelset_index(j));
        if (tr.curvature(s0) == tr.curvature(s1) && tr.cant(s0) == tr.cant(s1) && tr.alignment(s0) == tr.alignment(s1) &&
            tr.alignment_derivative(s0) == tr.alignment_derivative(s1) && tr.cross_level(s0) == tr.cross_level(s1))
          continue;
        Ft[j] = model->WheelsetForces(x, t + ht, j);
        contacts += Ft[j].contact_evaluations;
        if (!Ft[j].ok) throw ContactFailure("Jacobian d/dt: " + Ft[j].failure);
      }
      model->Assemble(x, t + ht, Ft, &fk);
      for (int i = 0; i < n; ++i) dfdt[i] = (fk[i] - f0[i]) / ht;
    }
    jacobian_x = x, jacobian_t = t, jacobian = J, jacobian_dfdt = dfdt;
  }
};

}  // namespace

DynamicsResult SimulateVehicleDynamics(const VehicleDynamicsModel& model, const DynamicsOptions& options) {
  options.validate();
  const int n = model.state_size(), nq = model.position_count(), W = model.wheelset_count();
  auto check_size = [](const std::vector<double>& v, int size, const char* name) {
    if (!v.empty() && static_cast<int>(v.size()) != size)
      throw InputError(std::string("option '") + name + "' must be empty or have " + std::to_string(size) + " values");
  };
  check_size(options.initial_positions, nq, "initial_positions");
  check_size(options.initial_velocities, nq, "initial_velocities");
  if (model.has_axle_speed()) check_size(options.initial_axle_speed_deviation, W, "initial_axle_speed_deviation");
  Vector x(n);
  for (int i = 0; i < n; ++i) x[i] = 0.0;
  for (size_t i = 0; i < options.initial_positions.size(); ++i) x[i] = 1e3 * options.initial_positions[i];
  for (size_t i = 0; i < options.initial_velocities.size(); ++i) x[nq + i] = 1e3 * options.initial_velocities[i];
  if (model.has_axle_speed())
    for (size_t i = 0; i < options.initial_axle_speed_deviation.size(); ++i)
      x[2 * nq + i] = 1e3 * options.initial_axle_speed_deviation[i];

  System sys;
  sys.model = &model;
  sys.jacobian_step = options.jacobian_step;
  sys.jacobian_reuse = options.jacobian_reuse_steps;
  const TrackInput& tr = model.track();
  sys.time_dependent = static_cast<bool>(tr.curvature_per_m) || static_cast<bool>(tr.cant_m) ||
                       static_cast<bool>(tr.alignment_m) || static_cast<bool>(tr.cross_level_m);
  auto deriv = [&sys](const Vector& xx, Vector& dxdt, double t) { sys.Derivative(xx, dxdt, t); };
  auto jacobi = [&sys](const Vector& xx, Matrix& J, const double& t, Vector& dfdt) { sys.Jacobian(xx, J, t, dfdt); };

  DynamicsResult result;
  auto record = [&](double t) {
    DynamicsSample s;
    s.time_s = t;
    s.station_m = model.reference_station_m(t);
    s.state.assign(x.begin(), x.end());
    if (options.record_wheels) {
      Eigen::VectorXd f;
      std::vector<WheelsetDynamicsForces> forces;
      std::string failure;
      int m = 0;
      const bool ok = model.Derivative(System::ToEigen(x), t, &f, &forces, &failure, &m);
      sys.contacts += m;
      if (ok) {
        for (const WheelsetDynamicsForces& w : forces) {
          std::array<WheelDynamicsSample, 2> ws;
          for (int i = 0; i < 2; ++i) {
            ws[i].lateral_force_N = w.wheel_lateral_N[i];
            ws[i].vertical_load_N = w.load_N[i];
            ws[i].y_over_q = w.y_over_q[i];
            ws[i].wear_number_N = w.wear_number_N[i];
            result.max_y_over_q = std::max(result.max_y_over_q, w.y_over_q[i]);
          }
          s.wheels.push_back(ws);
        }
      }
    }
    result.history.push_back(std::move(s));
  };

  using Rosenbrock = odeint::rosenbrock4_controller<odeint::rosenbrock4<double>>;
  using Dopri = odeint::controlled_runge_kutta<odeint::runge_kutta_dopri5<Vector>>;
  auto make_rosenbrock = [&] { return Rosenbrock(options.absolute_tolerance, options.relative_tolerance); };
  auto make_dopri = [&] {
    return Dopri(Dopri::error_checker_type(options.absolute_tolerance, options.relative_tolerance));
  };
  std::unique_ptr<Rosenbrock> rosenbrock;
  std::unique_ptr<Dopri> dopri;
  auto reset = [&] {
    if (options.stepper == DynamicsStepper::Rosenbrock4) rosenbrock = std::make_unique<Rosenbrock>(make_rosenbrock());
    else dopri = std::make_unique<Dopri>(make_dopri());
  };
  reset();

  double t = 0.0, dt = options.initial_step_s;
  long next_output = 1;
  try {
    sys.Evaluate(System::ToEigen(x), 0.0);  // the initial state must have contact
  } catch (const ContactFailure& e) {
    result.status = DynamicsStatus::ContactFailed;
    result.message = std::string("initial state: ") + e.what();
    result.derivative_evaluations = sys.derivatives;
    result.contact_evaluations = sys.contacts;
    return result;
  }
  record(0.0);
  const double t_end = options.duration_s;
  while (t < t_end) {
    const double t_out = std::min(t_end, next_output * options.output_interval_s);
    const double dt_natural = std::min(dt, options.max_step_s);
    const bool clipped = t + dt_natural >= t_out;
    double dt_try = clipped ? t_out - t : dt_natural;
    const double t_before = t;
    odeint::controlled_step_result r = odeint::fail;
    try {
      if (rosenbrock) r = rosenbrock->try_step(std::make_pair(deriv, jacobi), x, t, dt_try);
      else r = dopri->try_step(deriv, x, t, dt_try);
    } catch (const ContactFailure& e) {
      ++result.contact_failure_retries;
      dt = 0.5 * dt_natural;
      reset();
      if (dt < options.min_step_s) {
        result.status = DynamicsStatus::ContactFailed;
        result.message = e.what();
        break;
      }
      continue;
    }
    if (r == odeint::success) {
      ++result.steps;
      bool finite = true;
      for (double v : x) finite &= std::isfinite(v);
      if (!finite) {
        result.status = DynamicsStatus::NonFinite;
        result.message = "non-finite state at t = " + std::to_string(t) + " s";
        break;
      }
      // dt_try is the controller's proposal for the next step; a step clipped to an output time keeps the
      // unclipped size when that is larger
      dt = clipped ? std::max(dt_try, dt_natural) : dt_try;
      if (clipped && t >= t_out - 1e-12 * std::max(1.0, t_out)) {
        t = t_out;
        record(t);
        ++next_output;
        if (options.on_progress) options.on_progress(t, t_end, std::string());
      }
    } else {
      ++result.rejected_steps;
      t = t_before;
      dt = dt_try;
      if (dt < options.min_step_s) {
        result.status = DynamicsStatus::StepTooSmall;
        result.message = "step below min_step_s at t = " + std::to_string(t) + " s";
        break;
      }
    }
    if (result.steps + result.rejected_steps >= options.max_steps) {
      result.status = DynamicsStatus::StepLimit;
      result.message = "max_steps reached at t = " + std::to_string(t) + " s";
      break;
    }
    if (options.max_steps_per_s > 0.0 &&
        result.steps + result.rejected_steps > options.max_steps_per_s * (t + options.step_budget_grace_s)) {
      result.status = DynamicsStatus::StepLimit;
      char text[200];
      std::snprintf(text, sizeof text, "step budget exceeded at t = %.6f s: %ld step attempts, over %g per simulated "
                    "second x (t + %g s)", t, result.steps + result.rejected_steps, options.max_steps_per_s,
                    options.step_budget_grace_s);
      result.message = text;
      break;
    }
  }
  if (result.status != DynamicsStatus::Completed && result.history.back().time_s < t) record(t);
  result.simulated_time_s = t;
  result.derivative_evaluations = sys.derivatives;
  result.jacobian_evaluations = sys.jacobians;
  result.contact_evaluations = sys.contacts;
  return result;
}

}  // namespace conforma
