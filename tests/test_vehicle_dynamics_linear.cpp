// Time-domain vehicle model with linear contact (vehicle_dynamics*.hpp): the free wheelset's kinematic (Klingel)
// wavelength at low speed from the time history's zero crossings, and the critical speed of a linear bogie from
// the time domain (a small disturbance decays below it and grows above it) against the eigenvalue analysis.
// test-links: dynamics

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "conforma/error.hpp"
#include "conforma/vehicle_dynamics.hpp"
#include "conforma/vehicle_dynamics_eigen.hpp"

namespace conforma {
namespace {

LinearWheelsetContact Linear(double conicity) {
  LinearWheelsetContact k;
  k.f11_N = 1.0e7;
  k.f22_N = 8.7e6;
  k.conicity = conicity;
  k.contact_angle_parameter = conicity;  // coned wheels on knife-edge rails: gravitational stiffness W lambda / b0
  return k;
}

// One bogie whose secondary stage acts against a carbody following the track.
VehicleParameters Bogie() {
  VehicleParameters v;
  v.bogie_count = 1;
  v.bogie_centre_distance_m = 0.0;
  v.wheelbase_m = 2.5;
  v.nominal_wheel_radius_m = 0.46;
  v.contact_half_distance_m = 0.75;
  v.primary_longitudinal_stiffness_N_m = 5.0e6;
  v.primary_lateral_stiffness_N_m = 2.5e6;
  v.secondary_lateral_stiffness_N_m = 2.4e5;
  v.secondary_yaw_stiffness_Nm_rad = 5.0e5;
  return v;
}

// A run with linear contact of the given conicity at speed_m_s for duration_s, sampled every interval_s, no wheel
// records; StartDisplaced: every body at rest on the centre line but the leading wheelset 2 mm off it.
DynamicsOptions LinearRun(double conicity, double speed_m_s, double duration_s, double interval_s) {
  DynamicsOptions o;
  o.model.contact_kind = DynamicsContactKind::Linear;
  o.model.linear = Linear(conicity);
  o.model.speed_m_s = speed_m_s;
  o.duration_s = duration_s;
  o.output_interval_s = interval_s;
  o.record_wheels = false;
  return o;
}
void StartDisplaced(const VehicleDynamicsModel& model, DynamicsOptions* o) {
  o->initial_positions.assign(model.position_count(), 0.0);
  o->initial_positions[model.wheelset_index(0)] = 2e-3;
}

TEST(VehicleDynamicsLinear, FreeWheelsetKinematicWavelength) {
  VehicleParameters v = Bogie();
  v.primary_longitudinal_stiffness_N_m = 1e-6;  // no suspension (validate() asks for > 0): free wheelsets
  v.primary_lateral_stiffness_N_m = 1e-6;
  const double lambda = 0.2, r0 = v.nominal_wheel_radius_m, e = v.contact_half_distance_m;
  const double expected = 2.0 * M_PI * std::sqrt(r0 * e / lambda);  // Klingel
  const double V = 2.0;  // low speed: the wheelset's inertia is negligible
  DynamicsOptions o = LinearRun(lambda, V, 3.2 * expected / V, 2e-3);
  const VehicleDynamicsModel model(v, nullptr, TrackInput{}, o.model);
  StartDisplaced(model, &o);
  const DynamicsResult r = SimulateVehicleDynamics(model, o);
  ASSERT_EQ(r.status, DynamicsStatus::Completed) << r.message;
  // zero crossings of y (linear interpolation between samples)
  std::vector<double> crossings;
  for (size_t i = 1; i < r.history.size(); ++i) {
    const double y0 = r.history[i - 1].state[model.wheelset_index(0)], y1 = r.history[i].state[model.wheelset_index(0)];
    if ((y0 < 0.0) != (y1 < 0.0))
      crossings.push_back(r.history[i - 1].station_m + (r.history[i].station_m - r.history[i - 1].station_m) * y0 / (y0 - y1));
  }
  ASSERT_GE(crossings.size(), 5u);
  const double wavelength = 2.0 * (crossings.back() - crossings.front()) / (crossings.size() - 1);
  const double error = wavelength / expected - 1.0;
  std::printf("free wheelset: wavelength %.5f m, Klingel %.5f m, error %+.4f %%, %ld steps, %ld rejected, %ld f, %ld J\n",
              wavelength, expected, 100.0 * error, r.steps, r.rejected_steps, r.derivative_evaluations,
              r.jacobian_evaluations);
  EXPECT_LT(std::fabs(error), 0.02);
  // and it really oscillates about the centre: the amplitude stays of the order of the initial offset
  double amplitude = 0.0;
  for (const DynamicsSample& s : r.history) amplitude = std::max(amplitude, std::fabs(s.state[model.wheelset_index(0)]));
  EXPECT_GT(amplitude, 1.5);
  EXPECT_LT(amplitude, 4.0);
  // the state matrix of the same model has the kinematic mode at V / L_K (two free wheelsets: a pair of them)
  const LinearStabilityResult eig = AnalyseLinearStability(v, o.model);
  double closest = 0.0;
  for (const DynamicsMode& m : eig.modes)
    if (std::fabs(m.frequency_Hz - o.model.speed_m_s / expected) < std::fabs(closest - o.model.speed_m_s / expected))
      closest = m.frequency_Hz;
  std::printf("free wheelset: eigenvalue frequency %.6f Hz, V / L_K %.6f Hz\n", closest, o.model.speed_m_s / expected);
  EXPECT_NEAR(closest / (o.model.speed_m_s / expected), 1.0, 0.02);
}

// A free wheelset at low speed on a sinusoidal alignment irregularity y_irr = A sin(kappa s) follows the forced
// kinematic oscillation y'' + k^2 y = k^2 y_irr (k = 2 pi / L_K; from eta = 0: dy/ds = psi, and xi = 0:
// dpsi/ds = -lambda (y - y_irr) / (r0 b0)): started on the particular solution, y = A k^2 / (k^2 - kappa^2)
// sin(kappa s), 9/8 A for L_irr = 3 L_K. Checks the irregularity's way into the contact (pose and velocity
// relative to the actual rails).
TEST(VehicleDynamicsLinear, FreeWheelsetFollowsTheForcedKinematicResponseToAnAlignment) {
  VehicleParameters v = Bogie();
  v.primary_longitudinal_stiffness_N_m = 1e-6;
  v.primary_lateral_stiffness_N_m = 1e-6;
  const double lambda = 0.2, r0 = v.nominal_wheel_radius_m, b0 = v.contact_half_distance_m;
  const double k = 1.0 / std::sqrt(r0 * b0 / lambda), kappa = k / 3.0, A = 2e-3;
  DynamicsOptions o;
  o.model.contact_kind = DynamicsContactKind::Linear;
  o.model.linear = Linear(lambda);
  o.model.speed_m_s = 2.0;
  const double s0 = 0.5 * v.wheelbase_m;  // the leading wheelset's station at t = 0
  TrackInput track;
  track.alignment_m = [=](double s) { return A * std::sin(kappa * (s - s0)); };
  track.alignment_slope = [=](double s) { return A * kappa * std::cos(kappa * (s - s0)); };
  const double gain = k * k / (k * k - kappa * kappa);
  o.duration_s = 2.0 * 2.0 * M_PI / kappa / o.model.speed_m_s;  // two irregularity wavelengths
  o.output_interval_s = 0.01;
  o.record_wheels = false;
  const VehicleDynamicsModel model(v, nullptr, track, o.model);
  o.initial_positions.assign(model.position_count(), 0.0);
  o.initial_velocities.assign(model.position_count(), 0.0);
  o.initial_positions[model.wheelset_index(0) + 1] = gain * A * kappa;                       // psi = dy/ds
  o.initial_velocities[model.wheelset_index(0)] = o.model.speed_m_s * gain * A * kappa;     // dy/dt = V psi
  const DynamicsResult r = SimulateVehicleDynamics(model, o);
  ASSERT_EQ(r.status, DynamicsStatus::Completed) << r.message;
  double max_error = 0.0, max_y = 0.0;
  for (const DynamicsSample& smp : r.history) {
    const double s = smp.station_m + s0;
    const double expected_mm = 1e3 * gain * A * std::sin(kappa * (s - s0));
    max_error = std::max(max_error, std::fabs(smp.state[model.wheelset_index(0)] - expected_mm));
    max_y = std::max(max_y, std::fabs(smp.state[model.wheelset_index(0)]));
  }
  std::printf("alignment: peak y %.4f mm, forced response %.4f mm (A %.1f mm), max deviation %.4f mm\n", max_y,
              1e3 * gain * A, 1e3 * A, max_error);
  EXPECT_LT(max_error, 0.02 * 1e3 * gain * A);
}

// Peak |y| of the leading wheelset over [t0, t1] of the history, mm.
double Peak(const DynamicsResult& r, int index, double t0, double t1) {
  double p = 0.0;
  for (const DynamicsSample& s : r.history)
    if (s.time_s >= t0 && s.time_s <= t1) p = std::max(p, std::fabs(s.state[index]));
  return p;
}

TEST(VehicleDynamicsLinear, BogieCriticalSpeedTimeDomainAgreesWithEigenvalues) {
  const VehicleParameters v = Bogie();
  DynamicsModelOptions m;
  m.contact_kind = DynamicsContactKind::Linear;
  m.linear = Linear(0.2);
  CriticalSpeedOptions co;
  co.min_speed_m_s = 2.0;
  co.max_speed_m_s = 200.0;
  const CriticalSpeedResult crit = FindCriticalSpeed(v, m, co);
  ASSERT_TRUE(crit.found);
  const double Vc = crit.critical_speed_m_s;
  std::printf("eigenvalues: critical speed %.3f m/s (%.1f km/h), hunting frequency %.3f Hz, %d analyses\n", Vc, 3.6 * Vc,
              crit.frequency_Hz, crit.evaluations);
  // Time domain: growth of a 1 mm disturbance, judged on the peaks of the last two fifths of the run against the
  // two fifths before (after the other modes have decayed).
  auto growth = [&](double V, double* duration) {
    DynamicsOptions o;
    o.model = m;
    o.model.speed_m_s = V;
    const LinearStabilityResult eig = AnalyseLinearStability(v, o.model);
    // long enough for a factor e^1 of the least stable mode at +/- 5 %, at least 8 hunting periods
    o.duration_s = std::max(8.0 / std::max(crit.frequency_Hz, 0.1), 0.0);
    o.duration_s = std::max(o.duration_s, 1.0 / std::max(std::fabs(eig.max_real_part), 1e-3));
    o.duration_s = std::min(o.duration_s, 60.0);
    o.output_interval_s = 2e-3;
    o.record_wheels = false;
    const VehicleDynamicsModel model(v, nullptr, TrackInput{}, o.model);
    o.initial_positions.assign(model.position_count(), 0.0);
    o.initial_positions[model.wheelset_index(0)] = 1e-3;
    const DynamicsResult r = SimulateVehicleDynamics(model, o);
    EXPECT_EQ(r.status, DynamicsStatus::Completed) << r.message;
    *duration = o.duration_s;
    const double T = o.duration_s;
    return Peak(r, model.wheelset_index(0), 0.6 * T, T) / Peak(r, model.wheelset_index(0), 0.2 * T, 0.6 * T);
  };
  double T_below = 0.0, T_above = 0.0;
  const double below = growth(0.95 * Vc, &T_below), above = growth(1.05 * Vc, &T_above);
  std::printf("time domain: peak ratio %.3f at 0.95 Vc (%.1f s), %.3f at 1.05 Vc (%.1f s)\n", below, T_below, above, T_above);
  EXPECT_LT(below, 1.0);
  EXPECT_GT(above, 1.0);
  // the time-domain critical speed by bisection on the sign of the growth (for the report)
  double lo = 0.95 * Vc, hi = 1.05 * Vc, T = 0.0;
  for (int k = 0; k < 5; ++k) {
    const double mid = 0.5 * (lo + hi);
    (growth(mid, &T) > 1.0 ? hi : lo) = mid;
  }
  std::printf("time domain critical speed %.3f m/s: %+.2f %% from the eigenvalue analysis\n", 0.5 * (lo + hi),
              100.0 * (0.5 * (lo + hi) / Vc - 1.0));
  EXPECT_NEAR(0.5 * (lo + hi) / Vc, 1.0, 0.05);
}

// The running step budget (DynamicsOptions::max_steps_per_s): above the run's own step rate it changes nothing (the
// same history to the bit); below it the run stops with StepLimit as soon as the step attempts pass
// max_steps_per_s (t + grace), long before the end, and says so; a negative budget is an input error.
TEST(VehicleDynamicsLinear, RunningStepBudgetStopsARunOverItsRateOnly) {
  DynamicsOptions o = LinearRun(0.2, 20.0, 2.0, 0.01);
  const VehicleDynamicsModel model(Bogie(), nullptr, TrackInput{}, o.model);
  StartDisplaced(model, &o);
  const DynamicsResult free = SimulateVehicleDynamics(model, o);
  ASSERT_EQ(free.status, DynamicsStatus::Completed) << free.message;
  const double attempts = static_cast<double>(free.steps + free.rejected_steps);
  const double rate = attempts / o.duration_s;  // the run's mean rate of step attempts per simulated second
  std::printf("linear bogie, 2 s: %.0f step attempts, %.0f per s\n", attempts, rate);
  ASSERT_GT(attempts, 50.0);

  DynamicsOptions generous = o;
  generous.max_steps_per_s = 2.0 * rate;  // the grace (1 s) covers the start
  const DynamicsResult same = SimulateVehicleDynamics(model, generous);
  ASSERT_EQ(same.status, DynamicsStatus::Completed) << same.message;
  ASSERT_EQ(same.history.size(), free.history.size());
  for (size_t i = 0; i < free.history.size(); ++i) EXPECT_EQ(same.history[i].state, free.history[i].state) << i;

  DynamicsOptions tight = o;
  tight.max_steps_per_s = 0.25 * rate;
  tight.step_budget_grace_s = 0.1;
  const DynamicsResult stopped = SimulateVehicleDynamics(model, tight);
  EXPECT_EQ(stopped.status, DynamicsStatus::StepLimit);
  EXPECT_NE(stopped.message.find("step budget exceeded"), std::string::npos) << stopped.message;
  EXPECT_LT(stopped.simulated_time_s, 0.5 * o.duration_s);
  // it stopped at the first attempt over the budget
  const double used = static_cast<double>(stopped.steps + stopped.rejected_steps);
  EXPECT_GT(used, tight.max_steps_per_s * (stopped.simulated_time_s + tight.step_budget_grace_s));
  EXPECT_LE(used - 1.0, tight.max_steps_per_s * (stopped.simulated_time_s + tight.step_budget_grace_s) + 1.0);

  DynamicsOptions negative = o;
  negative.max_steps_per_s = -1.0;
  EXPECT_THROW(SimulateVehicleDynamics(model, negative), InputError);
}

TEST(VehicleDynamicsLinear, EigenvaluesNeedLinearContactAndStatusNamesAreDistinct) {
  DynamicsModelOptions m;  // nonlinear by default
  EXPECT_THROW(AnalyseLinearStability(Bogie(), m), InputError);
  EXPECT_STRNE(to_string(DynamicsStatus::Completed), to_string(DynamicsStatus::ContactFailed));
}

}  // namespace
}  // namespace conforma
