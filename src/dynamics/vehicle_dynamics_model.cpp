// Equations of motion of the time-domain lateral vehicle model (vehicle_dynamics_model.hpp).
#include "conforma/vehicle_dynamics_model.hpp"

#include <cmath>
#include <utility>

#include "conforma/error.hpp"

namespace conforma {

const char* to_string(DynamicsContactKind kind) {
  switch (kind) {
    case DynamicsContactKind::Nonlinear: return "nonlinear";
    case DynamicsContactKind::Linear: return "linear";
  }
  return "?";
}

void DynamicsModelOptions::validate() const {
  require_positive(speed_m_s, "speed_m_s");
  require_finite(start_position_m, "start_position_m");
  require_non_negative(friction_coefficient, "friction_coefficient");
  require_positive(gravity_m_s2, "gravity_m_s2");
  require_positive(cant_base_m, "cant_base_m");
  require_finite(axle_torque_Nm, "axle_torque_Nm");
  if (contact_kind == DynamicsContactKind::Linear) linear.validate();
  else contact.validate();
}

VehicleDynamicsModel::VehicleDynamicsModel(const VehicleParameters& vehicle, const WheelsetTrackGeometry* geometry,
                                           TrackInput track, const DynamicsModelOptions& options,
                                           WheelContactFunction contact, RigidPoseFunction pose)
    : vehicle_(vehicle), geometry_(geometry), track_(std::move(track)), options_(options), contact_(std::move(contact)),
      pose_(std::move(pose)) {
  vehicle_.validate();
  options_.validate();
  require_positive(vehicle_.bogie_frame_mass_kg, "vehicle bogie_frame_mass_kg (time-domain model)");
  if (vehicle_.bogie_count > 1) require_positive(vehicle_.carbody_mass_per_bogie_kg, "vehicle carbody_mass_per_bogie_kg (time-domain model)");
  if (options_.contact_kind == DynamicsContactKind::Nonlinear) {
    if (!geometry_) throw InputError("vehicle dynamics: nonlinear contact needs a wheelset-track geometry");
    if (!contact_) throw InputError("vehicle dynamics: nonlinear contact needs a contact function");
    for (double r : geometry_->setup().nominal_radius_m)
      if (std::fabs(r - vehicle_.nominal_wheel_radius_m) > 1e-6)
        throw InputError("vehicle field 'nominal_wheel_radius_m' differs from the track set-up's nominal wheel radius");
  }
  options_.contact.friction_coefficient = options_.friction_coefficient;
  W_ = vehicle_.wheelset_count();
  B_ = vehicle_.bogie_count;
  C_ = B_ > 1 ? B_ - 1 : 0;
  nq_ = 2 * (W_ + B_ + C_);
  spin_ = options_.contact_kind == DynamicsContactKind::Nonlinear && options_.free_axle_rotation;
  r0_ = vehicle_.nominal_wheel_radius_m;
  b0_ = vehicle_.contact_half_distance_m;
  Q0_ = vehicle_.static_wheel_load_N(options_.gravity_m_s2);
  const double L = vehicle_.bogie_centre_distance_m, a = 0.5 * vehicle_.wheelbase_m, bx = 0.5 * vehicle_.lateral_axlebox_spacing_m;
  x_.assign(W_ + B_ + C_, 0.0);
  mass_.assign(W_ + B_ + C_, 0.0);
  inertia_.assign(W_ + B_ + C_, 0.0);
  frame_load_mass_.assign(B_, 0.0);
  for (int i = 0; i < B_; ++i) {
    const int b = W_ + i;
    x_[b] = -i * L;
    mass_[b] = vehicle_.bogie_frame_mass_kg;
    inertia_[b] = vehicle_.bogie_frame_yaw_inertia_kgm2;
    for (int k = 0; k < 2; ++k) {
      const int j = 2 * i + k;
      x_[j] = x_[b] + (k == 0 ? a : -a);
      mass_[j] = vehicle_.wheelset_mass_kg;
      inertia_[j] = vehicle_.wheelset_yaw_inertia_kgm2;
      Link p;  // primary: per wheelset two axleboxes
      p.parent = b;
      p.child = j;
      p.d = x_[j] - x_[b];
      p.stage.lateral_stiffness_N_m = 2.0 * vehicle_.primary_lateral_stiffness_N_m;
      p.stage.lateral_damping_Ns_m = 2.0 * vehicle_.primary_lateral_damping_Ns_m;
      p.stage.yaw_stiffness_Nm_rad = 2.0 * vehicle_.primary_longitudinal_stiffness_N_m * bx * bx;
      p.stage.yaw_damping_Nms_rad = 2.0 * vehicle_.primary_longitudinal_damping_Ns_m * bx * bx;
      links_.push_back(p);
    }
  }
  // secondary stages: each bogie's stage shared equally by the carbodies resting on it
  for (int i = 0; i < B_; ++i) {
    std::vector<int> bodies;
    if (C_ == 0) bodies.push_back(-1);
    if (C_ > 0 && i > 0) bodies.push_back(W_ + B_ + i - 1);
    if (C_ > 0 && i < B_ - 1) bodies.push_back(W_ + B_ + i);
    const double share = 1.0 / static_cast<double>(bodies.size());
    for (int c : bodies) {
      Link s;
      s.parent = c;
      s.child = W_ + i;
      s.d = c < 0 ? 0.0 : x_[W_ + i] - (-(c - W_ - B_ + 0.5) * L);
      s.stage.lateral_stiffness_N_m = share * vehicle_.secondary_lateral_stiffness_N_m;
      s.stage.lateral_damping_Ns_m = share * vehicle_.secondary_lateral_damping_Ns_m;
      s.stage.yaw_stiffness_Nm_rad = share * vehicle_.secondary_yaw_stiffness_Nm_rad;
      s.stage.yaw_damping_Nms_rad = share * vehicle_.secondary_yaw_damping_Nms_rad;
      links_.push_back(s);
      if (c >= 0) mass_[c] += share * vehicle_.carbody_mass_per_bogie_kg;
    }
    if (C_ == 0) frame_load_mass_[i] = vehicle_.carbody_mass_per_bogie_kg;
  }
  for (int k = 0; k < C_; ++k) {
    const int c = W_ + B_ + k;
    x_[c] = -(k + 0.5) * L;
    inertia_[c] = mass_[c] * vehicle_.carbody_yaw_gyration_radius_m * vehicle_.carbody_yaw_gyration_radius_m;
  }
}

int VehicleDynamicsModel::wheelset_of_state(int k) const {
  if (k < 2 * W_) return k / 2;
  if (k >= nq_ && k < nq_ + 2 * W_) return (k - nq_) / 2;
  if (k >= 2 * nq_) return k - 2 * nq_;
  return -1;
}

double VehicleDynamicsModel::unbalanced_acceleration(double s) const {
  const double V = options_.speed_m_s;
  return V * V * track_.curvature(s) - options_.gravity_m_s2 * (track_.cant(s) + track_.cross_level(s)) / options_.cant_base_m;
}

WheelsetDynamicsForces VehicleDynamicsModel::WheelsetForces(const Eigen::VectorXd& x, double t, int j) const {
  WheelsetDynamicsForces out;
  const double V = options_.speed_m_s;
  const double s = reference_station_m(t) + x_[j];
  const double y = 1e-3 * x[2 * j], psi = 1e-3 * x[2 * j + 1];
  const double yd = 1e-3 * x[nq_ + 2 * j], psid = 1e-3 * x[nq_ + 2 * j + 1];
  const double w = spin_ ? 1e-3 * x[2 * nq_ + j] : 0.0;
  const double c = track_.curvature(s);
  const double y_irr = track_.alignment(s), y_irr_slope = track_.alignment_derivative(s);
  const double y_r = y - y_irr, psi_r = psi - y_irr_slope, yd_r = yd - V * y_irr_slope;
  // quasi-static wheel loads with the lateral load transfer (vehicle.hpp)
  const double a_nc = unbalanced_acceleration(s);
  const double dQ = vehicle_.carried_mass_per_wheelset_kg() * a_nc * vehicle_.load_transfer_height_m / (2.0 * b0_);
  out.load_N = {Q0_ - dQ, Q0_ + dQ};
  if (out.load_N[0] <= 0.0 || out.load_N[1] <= 0.0) {
    out.failure = "wheelset " + std::to_string(j) + " at s = " + std::to_string(s) + " m: a wheel is unloaded by the load transfer";
    return out;
  }
  const double Omega = V / r0_ * (1.0 + w);
  if (options_.contact_kind == DynamicsContactKind::Linear) {
    const LinearWheelsetContact& k = options_.linear;
    const double yaw_term = b0_ * (psid + V * c) / V;
    const double xi_L = -(k.conicity * y_r / r0_ + yaw_term) - w, xi_R = (k.conicity * y_r / r0_ + yaw_term) - w;
    const double eta = yd_r / V - psi_r;
    const double W = out.load_N[0] + out.load_N[1];
    const double gravity_stiffness = W * k.contact_angle_parameter / b0_;
    out.lateral_N = -2.0 * k.f22_N * eta - gravity_stiffness * y_r;
    const double FxL = -k.f11_N * xi_L, FxR = -k.f11_N * xi_R;
    out.yaw_moment_Nm = -b0_ * (FxL - FxR);
    out.axle_torque_Nm = r0_ * (FxL + FxR);
    const double roll_coefficient = k.roll_coefficient_per_m < 0.0 ? k.conicity / b0_ : k.roll_coefficient_per_m;
    if (options_.gyroscopic) out.gyroscopic_moment_Nm = -vehicle_.wheelset_spin_inertia_kgm2 * Omega * roll_coefficient * yd_r;
    for (int i = 0; i < 2; ++i) {
      const double sigma = i == 0 ? 1.0 : -1.0;
      const double xi = i == 0 ? xi_L : xi_R;
      out.wheel_lateral_N[i] = 0.5 * out.lateral_N;  // the linear model does not split Y between the wheels: half each
      out.y_over_q[i] = -sigma * out.wheel_lateral_N[i] / out.load_N[i];  // + towards the track centre (-sigma y)
      out.wear_number_N[i] = k.f11_N * xi * xi + k.f22_N * eta * eta;
    }
    out.ok = true;
    return out;
  }
  WheelsetVelocity velocity;
  velocity.forward_speed_m_s = V;
  velocity.lateral_velocity_m_s = yd_r;
  velocity.yaw_rate_rad_s = psid + V * c;
  velocity.axle_angular_velocity_rad_s = Omega;
  const WheelsetContactForces f =
      EvaluateWheelsetContactForces(*geometry_, contact_, options_.contact, out.load_N, y_r, psi_r, velocity, pose_);
  out.contact_evaluations = f.contact_evaluations;
  if (!f.ok) {
    out.failure = "wheelset " + std::to_string(j) + " at s = " + std::to_string(s) + " m, t = " + std::to_string(t) +
                  " s, y = " + std::to_string(1e3 * y_r) + " mm, psi = " + std::to_string(1e3 * psi_r) + " mrad: " +
                  (f.contact_evaluations == 0 ? std::string("rigid equilibrium not converged")
                                              : std::string("wheel contact ") +
                                                    to_string(f.report[f.contact_evaluations - 1].status));
    return out;
  }
  out.lateral_N = f.lateral_N;
  out.yaw_moment_Nm = f.yaw_moment_Nm;
  out.axle_torque_Nm = f.axle_torque_Nm;
  if (options_.gyroscopic && yd_r != 0.0) {
    // dphi/dt = (dphi/dy) dy_r/dt, dphi/dy by a forward difference of the rigid equilibrium over 10 um
    const double h = 1e-5;
    EquilibriumOptions eo;
    eo.max_touching_contact_angle_rad = options_.contact.max_touching_contact_angle_rad;
    const EquilibriumResult eq = SolveRigidPose(*geometry_, pose_, y_r + h, psi_r, eo, f.pose);
    if (eq.status == EquilibriumStatus::Converged)
      out.gyroscopic_moment_Nm = -vehicle_.wheelset_spin_inertia_kgm2 * Omega * (eq.pose.roll_rad - f.pose.roll_rad) / h * yd_r;
  }
  for (int i = 0; i < 2; ++i) {
    const WheelContactReport& r = f.report[i];
    out.wheel_lateral_N[i] = (i == 0 ? 1.0 : -1.0) * r.lateral_force_N;
    out.y_over_q[i] = -r.lateral_force_N / out.load_N[i];  // side frame eta + towards the field side
    double power = 0.0;
    for (const PatchReport& p : r.patches) power += p.frictional_power_W;
    out.wear_number_N[i] = power / V;
  }
  out.ok = true;
  return out;
}

void VehicleDynamicsModel::Assemble(const Eigen::VectorXd& x, double t, const std::vector<WheelsetDynamicsForces>& f,
                                    Eigen::VectorXd* dxdt) const {
  const double V = options_.speed_m_s;
  const double s_ref = reference_station_m(t);
  const int nb = W_ + B_ + C_;
  Eigen::VectorXd force = Eigen::VectorXd::Zero(nb), moment = Eigen::VectorXd::Zero(nb);
  auto body = [&](int b) {
    SuspensionBodyState s;  // the track (b < 0): zero
    if (b >= 0) {
      s.y_m = 1e-3 * x[2 * b];
      s.psi_rad = 1e-3 * x[2 * b + 1];
      s.y_rate_m_s = 1e-3 * x[nq_ + 2 * b];
      s.psi_rate_rad_s = 1e-3 * x[nq_ + 2 * b + 1];
    }
    return s;
  };
  for (const Link& l : links_) {
    const double xp = l.parent < 0 ? x_[l.child] : x_[l.parent];
    const SuspensionForces s = EvaluateSuspension(track_, V, s_ref + xp, l.d, l.stage, body(l.parent), body(l.child));
    force[l.child] += s.child_lateral_N;
    moment[l.child] += s.child_yaw_Nm;
    if (l.parent >= 0) {
      force[l.parent] += s.parent_lateral_N;
      moment[l.parent] += s.parent_yaw_Nm;
    }
  }
  for (int j = 0; j < W_; ++j) {
    force[j] += f[j].lateral_N;
    moment[j] += f[j].yaw_moment_Nm + f[j].gyroscopic_moment_Nm;
  }
  dxdt->resize(state_size());
  for (int b = 0; b < nb; ++b) {
    const double s = s_ref + x_[b];
    double F = force[b];
    if (b >= W_ && b < W_ + B_) F -= frame_load_mass_[b - W_] * unbalanced_acceleration(s);
    (*dxdt)[2 * b] = x[nq_ + 2 * b];
    (*dxdt)[2 * b + 1] = x[nq_ + 2 * b + 1];
    (*dxdt)[nq_ + 2 * b] = 1e3 * (F / mass_[b] - unbalanced_acceleration(s));
    (*dxdt)[nq_ + 2 * b + 1] = 1e3 * (moment[b] / inertia_[b] - V * V * track_.curvature_derivative(s));
  }
  if (spin_)
    for (int j = 0; j < W_; ++j)
      (*dxdt)[2 * nq_ + j] = 1e3 * r0_ / (V * vehicle_.wheelset_spin_inertia_kgm2) *
                              (options_.axle_torque_Nm - f[j].axle_torque_Nm);
}

bool VehicleDynamicsModel::Derivative(const Eigen::VectorXd& x, double t, Eigen::VectorXd* dxdt,
                                      std::vector<WheelsetDynamicsForces>* f, std::string* failure,
                                      int* contact_evaluations) const {
  f->resize(W_);
  for (int j = 0; j < W_; ++j) {
    (*f)[j] = WheelsetForces(x, t, j);
    if (contact_evaluations) *contact_evaluations += (*f)[j].contact_evaluations;
    if (!(*f)[j].ok) {
      if (failure) *failure = (*f)[j].failure;
      return false;
    }
  }
  Assemble(x, t, *f, dxdt);
  return true;
}

}  // namespace conforma
