// The stress suite's cases and checks (stress.hpp).
#include <omp.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>

#include "conforma/validation/benchmark_cases.hpp"
#include "conforma/error.hpp"
#include "conforma/validation/stress.hpp"
#include "conforma/wheel_contact.hpp"

namespace conforma {

namespace {

// Running hash of result numbers (FNV-1a over the bytes) and a finiteness flag.
struct ResultHash {
  std::uint64_t h = 1469598103934665603ull;
  bool finite = true;
  void add(double v) {
    if (!std::isfinite(v)) finite = false;
    unsigned char b[sizeof v];
    std::memcpy(b, &v, sizeof v);
    for (unsigned char c : b) h = (h ^ c) * 1099511628211ull;
  }
};

void AddReport(const WheelContactReport& r, ResultHash* h) {
  h->add(static_cast<double>(r.status));
  h->add(r.vertical_force_N), h->add(r.pressure_vertical_force_N), h->add(r.lateral_force_N);
  h->add(r.pose.vertical_m);
  for (const PatchReport& p : r.patches) {
    for (double v : {p.fn_N, p.fx_N, p.fy_N, p.mz_Nm, p.pmax_Pa, p.p0_Pa, p.area_m2, p.a_m, p.b_m, p.width_m,
                     p.length_m, p.approach_m, p.contact_angle_rad, p.y_contact_rail_m, p.z_contact_rail_m,
                     p.y_contact_wheel_m, p.rolling_radius_m, p.lead_m, p.xi, p.eta, p.phi_per_m, p.alpha_c_deg,
                     p.adhesion_area_m2, p.slip_area_m2, p.frictional_power_W, p.vertical_force_N, p.lateral_force_N,
                     p.reference_s_on_rail_m})
      h->add(v);
  }
}

void AddSolution(const BenchPatchResult& s, ResultHash* h) {
  for (double v : {s.pmax_Pa, s.area_m2, s.fn_N, s.fx_N, s.fy_N, s.wear_index_N, s.approach_m, s.alpha_c_deg})
    h->add(v);
}

double LogUniform(std::mt19937_64& rng, double lo, double hi) {
  return std::exp(std::uniform_real_distribution<double>(std::log(lo), std::log(hi))(rng));
}
double Uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }

FastsimCreepages RandomCreepages(std::mt19937_64& rng) {
  auto signed_creep = [&] { return (rng() & 1 ? 1.0 : -1.0) * LogUniform(rng, 1e-6, 0.1); };
  FastsimCreepages c;
  c.xi = signed_creep();
  c.eta = signed_creep();
  c.phi_per_m = Uniform(rng, -10.0, 10.0);
  return c;
}

struct CaseOutcome {
  std::uint64_t digest = 0;
  bool wheel = false, patch = false, degenerate = false;
  long patches = 0;
  bool non_finite = false, crash = false, input_error = false, unexpected_input_error = false;
  bool no_contact = false, not_converged = false;
  bool continuity_pair = false, continuity_jump = false, continuity_steep = false, continuity_violation = false;
  double continuity_fraction = 0.0;
  std::string failure;
};

// Largest change of the lateral force and of each patch's normal and creep forces between two solutions; *jump when
// the contact point jumps (patch count changes or a reference point moves more than jump_distance on the rail).
double ForceChange(const WheelContactReport& r, const WheelContactReport& s, double jump_distance, bool* jump) {
  *jump = r.patches.size() != s.patches.size();
  double change = std::fabs(r.lateral_force_N - s.lateral_force_N);
  for (size_t k = 0; !*jump && k < r.patches.size(); ++k) {
    const PatchReport &a = r.patches[k], &b = s.patches[k];
    *jump = std::fabs(a.reference_s_on_rail_m - b.reference_s_on_rail_m) > jump_distance;
    change = std::max({change, std::fabs(a.fn_N - b.fn_N), std::fabs(a.fx_N - b.fx_N), std::fabs(a.fy_N - b.fy_N)});
  }
  return change;
}

const char* kModelNames[] = {"hertz", "kp", "kpec", "conformal"};

// Common end of a case: a non-finite value anywhere in the results is a failure; the digest feeds the
// thread-count determinism check.
void FinishCase(const ResultHash& h, const std::string& what, CaseOutcome* out) {
  if (!h.finite) {
    out->non_finite = true;
    out->failure = what + ": NaN/inf in the result";
  }
  out->digest = h.h;
}

void RunWheelCase(const StressSetup& setup, const StressOptions& o, long i, std::mt19937_64& rng, CaseOutcome* out) {
  out->wheel = true;
  const int kind = static_cast<int>(i % 8);
  const WheelsetTrackGeometry* geometry = nullptr;
  WheelContactOptions w;
  WheelsetPose pose;
  std::vector<Side> sides;
  double load = 0.0;
  std::string pair;
  if (o.wheelset_mode) {
    geometry = i % 2 ? setup.worn_pair.get() : setup.new_pair.get();
    pair = i % 2 ? "worn" : "new";
    w.model = ContactModel::Conformal;
    pose.lateral_m = Uniform(rng, -12e-3, 12e-3);
    pose.yaw_rad = Uniform(rng, -25e-3, 25e-3);
    load = LogUniform(rng, 1e3, 150e3);
    sides = {Side::Left, Side::Right};
  } else {
    const int p = kind % 3;
    geometry = p == 0 ? setup.new_pair.get() : p == 1 ? setup.worn_pair.get() : setup.noisy_pair.get();
    pair = p == 0 ? "new" : p == 1 ? "worn" : "noisy";
    w.model = ParseContactModel(kModelNames[(i / 8) % 4]);
    pose.lateral_m = Uniform(rng, -12e-3, 12e-3);
    pose.yaw_rad = Uniform(rng, -25e-3, 25e-3);
    pose.roll_rad = Uniform(rng, -3e-3, 3e-3);
    load = LogUniform(rng, 100.0, 200e3);
    sides = {rng() & 1 ? Side::Left : Side::Right};
    if (rng() & 1) {
      w.creepages_given = true;
      const FastsimCreepages c = RandomCreepages(rng);
      w.creepages = {c.xi, c.eta, c.phi_per_m};
    }
  }
  w.vertical_load_N = load;
  const double drive = o.wheelset_mode ? 0.0 : Uniform(rng, -0.01, 0.01);
  const WheelsetVelocity velocity{20.0, 0.0, 0.0, 20.0 / 0.46 * (1.0 + drive)};
  char what[200];
  std::snprintf(what, sizeof what, "case %ld: %s pair, %s, y %.4f mm, yaw %.2f mrad, roll %.2f mrad, load %.0f N", i,
                pair.c_str(), to_string(w.model), pose.lateral_m * 1e3, pose.yaw_rad * 1e3, pose.roll_rad * 1e3, load);
  ResultHash h;
  const bool continuity = o.continuity_every > 0 && i % o.continuity_every == 0;
  try {
    for (Side side : sides) {
      const WheelContactReport r = SolveWheelContact(*geometry, side, pose, velocity, w);
      AddReport(r, &h);
      out->patches += static_cast<long>(r.patches.size());
      out->no_contact |= r.status == WheelContactStatus::NoContact;
      out->not_converged |= r.status == WheelContactStatus::NotConverged;
      if (!continuity || r.status != WheelContactStatus::Ok) continue;
      auto solve_shifted = [&](double dy) {
        WheelsetPose shifted = pose;
        shifted.lateral_m += dy;
        WheelContactReport t = SolveWheelContact(*geometry, side, shifted, velocity, w);
        AddReport(t, &h);
        return t;
      };
      const WheelContactReport s = solve_shifted(o.continuity_step_m);
      if (s.status != WheelContactStatus::Ok) continue;
      out->continuity_pair = true;
      bool jump = false;
      const double change = ForceChange(r, s, o.jump_distance_m, &jump);
      out->continuity_jump |= jump;
      if (jump) continue;
      out->continuity_fraction = std::max(out->continuity_fraction, change / load);
      if (change <= o.continuity_bound_fraction * load) continue;
      // Stiff but continuous (two-point load sharing at a small approach, a fast-moving contact point): the change
      // must shrink with the step. A discontinuity keeps its size (or vanishes) when the step is quartered.
      const WheelContactReport q = solve_shifted(0.25 * o.continuity_step_m);
      bool jump_q = false;
      const double change_q = q.status == WheelContactStatus::Ok ? ForceChange(r, q, o.jump_distance_m, &jump_q) : change;
      if (!jump_q && change_q < 0.5 * change) {
        out->continuity_steep = true;
        continue;
      }
      out->continuity_violation = true;
      out->failure = std::string(what) + ": force change " + std::to_string(change) + " N over " +
                     std::to_string(o.continuity_step_m * 1e6) + " um, " + std::to_string(change_q) + " N over a quarter";
    }
  } catch (const InputError& e) {
    out->input_error = out->unexpected_input_error = true;
    out->failure = std::string(what) + ": InputError " + e.what();
  } catch (const std::exception& e) {
    out->crash = true;
    out->failure = std::string(what) + ": exception " + e.what();
  }
  FinishCase(h, what, out);
}

PatchGeometry UniformPatch(int strips, double ds, double gap_curvature) {
  PatchGeometry p;
  p.ds_m = ds;
  for (int j = 0; j < strips; ++j) {
    const double s = (j - 0.5 * (strips - 1)) * ds;
    p.s_m.push_back(s);
    p.gap_m.push_back(gap_curvature * s * s);
    p.longitudinal_curvature_per_m.push_back(0.5 / 0.46);
    p.wheel_radius_m.push_back(0.46);
    p.alpha_rad.push_back(0.0);
    p.x_offset_m.push_back(0.0);
  }
  return p;
}

void RunPatchCase(long i, std::mt19937_64& rng, CaseOutcome* out) {
  const bool degenerate = i % 8 == 7;
  (degenerate ? out->degenerate : out->patch) = true;
  BenchCase c;
  int kind = 0;
  if (!degenerate) {
    const double u = LogUniform(rng, 1e-4, 0.5);
    c = MakeGrooveBenchCases({10e-3 * (1.0 + u)}, LogUniform(rng, 100.0, 200e3)).front();
  } else {
    kind = static_cast<int>(rng() % 5);
    switch (kind) {
      case 0: c.patch = UniformPatch(1, 0.1e-3, 5.0); break;             // one strip
      case 1: c.patch = UniformPatch(5, 0.0, 5.0); break;                // zero width
      case 2: c.patch = UniformPatch(2, 0.1e-3, 5.0); break;             // two strips
      case 3: c.patch = UniformPatch(21, 0.1e-3, 0.0); break;            // flat: zero gap everywhere
      default:                                                           // a strip without longitudinal curvature
        c.patch = UniformPatch(21, 0.1e-3, 5.0);
        c.patch.longitudinal_curvature_per_m[10] = 0.0;
        break;
    }
    c.normal_load_N = LogUniform(rng, 100.0, 200e3);
    c.hertz_A_per_m = 0.5 / 0.46;
    c.hertz_B_per_m = kind == 3 ? 0.0 : 5.0;
  }
  c.creepages = RandomCreepages(rng);
  PatchSolveOptions o;
  o.model = ParseContactModel(kModelNames[degenerate ? rng() % 4 : 1 + rng() % 3]);
  char what[160];
  std::snprintf(what, sizeof what, "case %ld: %s patch%s, %s, load %.0f N", i, degenerate ? "degenerate" : "groove",
                degenerate ? (" kind " + std::to_string(kind)).c_str() : "", to_string(o.model), c.normal_load_N);
  ResultHash h;
  try {
    const BenchPatchResult s = SolveBenchCase(c, o);
    AddSolution(s, &h);
    out->patches += s.in_contact;
    out->no_contact |= !s.in_contact;
  } catch (const InputError& e) {
    out->input_error = true;
    out->unexpected_input_error = !degenerate;
    if (!degenerate) out->failure = std::string(what) + ": InputError " + e.what();
    h.add(-1.0);
  } catch (const std::exception& e) {
    out->crash = true;
    out->failure = std::string(what) + ": exception " + e.what();
  }
  FinishCase(h, what, out);
}

}  // namespace

StressSummary RunStress(const StressSetup& setup, const StressOptions& o) {
  o.validate();
  if (!setup.new_pair || !setup.worn_pair || !setup.noisy_pair) throw InputError("stress: setup not made");
  const auto start = std::chrono::steady_clock::now();
  std::vector<CaseOutcome> outcomes(static_cast<size_t>(o.cases));
  const int threads = o.threads > 0 ? o.threads : omp_get_max_threads();
  ProgressCounter progress(o.on_progress, static_cast<double>(o.cases));
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
  for (long k = 0; k < o.cases; ++k) {
    const long i = o.first_case + k;
    const ProgressCounter::Unit counted(progress, "case " + std::to_string(i));
    // generator seeded by (seed, i) only: the same case whatever the thread or the batch
    std::seed_seq seq{static_cast<std::uint32_t>(o.seed), static_cast<std::uint32_t>(o.seed >> 32),
                      static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(static_cast<std::uint64_t>(i) >> 32)};
    std::mt19937_64 rng(seq);
    if (o.wheelset_mode || i % 8 < 6) RunWheelCase(setup, o, i, rng, &outcomes[k]);
    else RunPatchCase(i, rng, &outcomes[k]);
  }
  StressSummary s;
  s.digest = 1469598103934665603ull;
  for (const CaseOutcome& c : outcomes) {
    ++s.cases;
    s.wheel_cases += c.wheel, s.patch_cases += c.patch, s.degenerate_cases += c.degenerate;
    s.patches += c.patches;
    s.non_finite += c.non_finite, s.crashes += c.crash;
    s.input_errors += c.input_error, s.unexpected_input_errors += c.unexpected_input_error;
    s.no_contact += c.no_contact, s.not_converged += c.not_converged;
    s.continuity_pairs += c.continuity_pair, s.continuity_jumps += c.continuity_jump;
    s.continuity_violations += c.continuity_violation, s.continuity_steep += c.continuity_steep;
    s.max_continuity_fraction = std::max(s.max_continuity_fraction, c.continuity_fraction);
    s.digest = (s.digest ^ c.digest) * 1099511628211ull;
    if (!c.failure.empty() && s.failures.size() < 20) s.failures.push_back(c.failure);
  }
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return s;
}

}  // namespace conforma
