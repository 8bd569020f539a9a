// Profile update: mass-conserving smoothing, scaling to the cap, removal along the normal,
// re-parametrisation and validity (paper 003 §6 eqs. 18-19, paper 001 §6.2 eqs. 28-30).
// test-links: wear  (CMakeLists.txt links the test with this library only; the layers below come with it)

#include <gtest/gtest.h>

#include <functional>

#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "conforma/error.hpp"
#include "conforma/profile_update.hpp"
#include "conforma/standard_profiles.hpp"

using namespace conforma;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Circular arc of radius R (centre (0, -R)), angles [-half_angle, half_angle] from +z, s from -y to +y.
Profile circle_arc(double R, double half_angle, ProfileKind kind = ProfileKind::Rail) {
  std::vector<Eigen::Vector2d> pts;
  const int n = 2001;
  for (int i = 0; i < n; ++i) {
    const double t = -half_angle + 2 * half_angle * i / (n - 1);
    pts.emplace_back(R * std::sin(t), R * std::cos(t) - R);
  }
  ProfileFitOptions fit;
  fit.function_of_y = false;
  return Profile::FromPoints(pts, kind, fit, "circle");
}

Profile flat_line(double length) {
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i <= 100; ++i) pts.emplace_back(-0.5 * length + length * i / 100, 0.0);
  return Profile::FromPoints(pts, ProfileKind::Rail);
}

double gauss(double x, double centre, double sigma) { return std::exp(-0.5 * std::pow((x - centre) / sigma, 2)); }

// Synthetic tread + flange wear on an S1002-type wheel, as a function of the lateral position y [m]:
// tread band around the taping line (y = 0) and a narrower band on the flange flank, plus per-node
// noise (the numerical noise the paper's smoothing is for).
WearDistribution tread_flange_depth(const Profile& wheel, double spacing, unsigned seed, double noise) {
  WearDistribution d = WearDistribution::ForProfile(wheel, spacing);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (size_t i = 0; i < d.size(); ++i) {
    const double y = wheel.position(d.s(i)).x();
    const double clean = 1.0e-6 * gauss(y, 0.0, 8e-3) + 0.35e-6 * gauss(y, -38e-3, 2.5e-3);
    d.depth_m[i] = clean * (1.0 + noise * (u(rng) - 0.5));
  }
  return d;
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3e", v);
  return buf;
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

}  // namespace

TEST(ProfileUpdate, SmoothingConservesAreaAndIsNonNegative) {
  const WearDistribution grid = WearDistribution::Zero(0.14, 0.1e-3);
  // 1. spiky: isolated single-node spikes of random height (worst case for ringing)
  WearDistribution spiky = grid;
  std::mt19937 rng(7);
  std::uniform_int_distribution<size_t> node(0, grid.size() - 1);
  for (int k = 0; k < 40; ++k) spiky.depth_m[node(rng)] += 1e-6 * (1 + k % 5);
  // 2. smooth: a wide Gaussian
  WearDistribution smooth = grid;
  for (size_t i = 0; i < grid.size(); ++i) smooth.depth_m[i] = 2e-6 * gauss(grid.s(i), 0.07, 10e-3);
  // 3. realistic two peaks (tread + flange) with noise and sharp edges (contact band limits)
  WearDistribution two = grid;
  for (size_t i = 0; i < grid.size(); ++i) {
    const double s = grid.s(i);
    double v = (std::abs(s - 0.085) < 0.015 ? 1e-6 * (1 - std::pow((s - 0.085) / 0.015, 2)) : 0.0) +
               (std::abs(s - 0.035) < 0.003 ? 0.4e-6 : 0.0);
    two.depth_m[i] = v * (1.0 + 0.5 * std::sin(1.3e4 * s));
  }
  const char* names[3] = {"spiky", "smooth", "two_peak"};
  int k = 0;
  for (const WearDistribution* d : {&spiky, &smooth, &two}) {
    const DepthSmoothingResult r = SmoothDepthMassConserving(*d, DepthSmoothingOptions{});
    const double err = relative(r.depth.area_m2(), d->area_m2());
    RecordProperty(std::string("area_error_") + names[k++], sci(err));
    EXPECT_LT(err, 0.005);
    EXPECT_LT(err, 1e-9);  // exact up to rounding by construction
    for (double v : r.depth.depth_m) EXPECT_GE(v, 0.0);
    EXPECT_LE(r.depth.max_depth_m(), d->max_depth_m() * (1 + 1e-9));
  }
  // the spikes must actually be smoothed (max drops) and the ringing clipped
  const DepthSmoothingResult r = SmoothDepthMassConserving(spiky, DepthSmoothingOptions{});
  EXPECT_LT(r.depth.max_depth_m(), 0.2 * spiky.max_depth_m());
  EXPECT_GT(r.clipped_nodes, 0u);
}

TEST(ProfileUpdate, SmoothingGainIsHalfAtTheCutoffWavelength) {
  // Whittaker smoother: gain 1 / (1 + 16 lambda sin^4(pi h / L)) = 1/2 at L = cutoff (interior).
  const WearDistribution grid = WearDistribution::Zero(0.2, 0.1e-3);
  const double cutoff = 5e-3;
  for (double wavelength : {cutoff, 4 * cutoff, 0.25 * cutoff}) {
    WearDistribution d = grid;
    for (size_t i = 0; i < d.size(); ++i) d.depth_m[i] = 1e-6 * (1.0 + 0.5 * std::sin(2 * kPi * d.s(i) / wavelength));
    const DepthSmoothingResult r = SmoothDepthMassConserving(d, DepthSmoothingOptions{cutoff});
    const size_t mid = d.size() / 2;
    double amplitude = 0.0;  // measured amplitude in the middle (away from the ends)
    for (size_t i = mid - 500; i < mid + 500; ++i) amplitude = std::max(amplitude, std::abs(r.depth.depth_m[i] - 1e-6));
    const double sine = std::sin(kPi * 0.1e-3 / wavelength), s4 = std::pow(std::sin(kPi * 0.1e-3 / cutoff), 4);
    const double expected = 0.5e-6 / (1.0 + std::pow(sine, 4) / s4);
    EXPECT_NEAR(amplitude, expected, 0.01 * 0.5e-6) << wavelength;
  }
}

TEST(ProfileUpdate, SmoothingKeepsLinearFields) {
  // D2 annihilates linear functions: a linear depth ramp is a fixed point of the smoother (ends included)
  WearDistribution ramp = WearDistribution::Zero(0.1, 0.1e-3);
  for (size_t i = 0; i < ramp.size(); ++i) ramp.depth_m[i] = 1e-6 * (0.2 + 3.0 * ramp.s(i));
  const DepthSmoothingResult r = SmoothDepthMassConserving(ramp, DepthSmoothingOptions{});
  for (size_t i = 0; i < ramp.size(); ++i) EXPECT_NEAR(r.depth.depth_m[i], ramp.depth_m[i], 1e-12 * 1e-6);
  EXPECT_EQ(r.clipped_nodes, 0u);
}

TEST(ProfileUpdate, UniformDepthOnCircleAndLine) {
  const double R = 0.02, d = 0.4e-3;
  const Profile arc = circle_arc(R, 1.0);
  WearDistribution depth = WearDistribution::ForProfile(arc, 0.1e-3);
  std::fill(depth.depth_m.begin(), depth.depth_m.end(), d);
  const Profile worn = RemoveAlongNormal(arc, depth);
  // every point of the new profile (its stored samples and between them) lies on the circle R - d
  double worst = 0.0;
  for (int i = 0; i <= 4000; ++i) {
    const Eigen::Vector2d p = worn.position(worn.length() * i / 4000.0);
    worst = std::max(worst, std::abs((p - Eigen::Vector2d(0, -R)).norm() - (R - d)));
  }
  RecordProperty("circle_radius_error_m", sci(worst));
  EXPECT_LT(worst, 1e-6);
  // The length shrinks by (R - d)/R up to the end normals: the natural-spline end conditions of Profile tilt
  // the end tangent by about kappa h / 3 (1.7e-3 rad here), which moves each end point d * 1.7e-3 = 0.7 um
  // ALONG the circle (the radius stays exact).
  EXPECT_NEAR(worn.length(), arc.length() * (R - d) / R, 2e-6);
  EXPECT_NEAR(worn.curvature(worn.length() / 2), 1.0 / (R - d), 1e-3 / (R - d));

  const Profile line = flat_line(0.1);
  WearDistribution dl = WearDistribution::ForProfile(line, 0.1e-3);
  std::fill(dl.depth_m.begin(), dl.depth_m.end(), d);
  const Profile lowered = RemoveAlongNormal(line, dl);
  for (int i = 0; i <= 1000; ++i) EXPECT_NEAR(lowered.position(lowered.length() * i / 1000.0).y(), -d, 1e-9);
  // a depth grid for another profile is rejected
  EXPECT_THROW(RemoveAlongNormal(line, depth), InputError);
}

TEST(ProfileUpdate, StepScalesToTheCapAndSetsTheDistance) {
  // accumulated depth 1.6 um uniform over 50 km -> cap 0.4 mm reached after 12500 km; circle R -> R - 0.4 mm
  const double R = 0.3;
  const Profile arc = circle_arc(R, 0.15);
  WearDistribution acc = WearDistribution::ForProfile(arc, 0.1e-3);
  std::fill(acc.depth_m.begin(), acc.depth_m.end(), 1.6e-6);
  const ProfileUpdateResult r = UpdateProfile(arc, acc, 50e3);
  ASSERT_EQ(r.status, ProfileUpdateStatus::Updated) << r.message;
  EXPECT_NEAR(r.max_depth_m, 0.4e-3, 1e-12);
  EXPECT_NEAR(r.distance_step_m, 12500e3, 1e-3);
  double worst = 0.0;
  for (const auto& p : r.profile.samples()) worst = std::max(worst, std::abs((p - Eigen::Vector2d(0, -R)).norm() - (R - 0.4e-3)));
  EXPECT_LT(worst, 1e-6);
  // distance limit binds: half the distance, half the depth
  ProfileUpdateOptions o;
  o.max_distance_step_m = 6250e3;
  const ProfileUpdateResult half = UpdateProfile(arc, acc, 50e3, o);
  EXPECT_NEAR(half.max_depth_m, 0.2e-3, 1e-12);
  // no wear: unchanged, status says so
  std::fill(acc.depth_m.begin(), acc.depth_m.end(), 0.0);
  const ProfileUpdateResult none = UpdateProfile(arc, acc, 50e3);
  EXPECT_EQ(none.status, ProfileUpdateStatus::NoWear);
  EXPECT_EQ(none.profile.length(), arc.length());
}

TEST(ProfileUpdate, KinkIsReportedWithTheStep) {
  // an unsmoothed V-notch (0.4 mm deep, 2 mm wide) has a corner at its bottom: invalid, the message names
  // the step and the kink
  const Profile line = flat_line(0.05);
  WearDistribution acc = WearDistribution::ForProfile(line, 0.1e-3);
  const size_t mid = acc.size() / 2;
  for (size_t i = mid - 10; i <= mid + 10; ++i) acc.depth_m[i] = 1e-6 * (1.0 - std::abs(double(i) - double(mid)) / 10.0);
  ProfileUpdateOptions o;
  o.smoothing.cutoff_wavelength_m = 0.0;
  o.step_index = 7;
  const ProfileUpdateResult r = UpdateProfile(line, acc, 1.0, o);
  EXPECT_EQ(r.status, ProfileUpdateStatus::InvalidProfile);
  EXPECT_NE(r.message.find("wear step 7"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("kink"), std::string::npos) << r.message;
  // with the default smoothing the same field is a smooth dent: valid
  o.smoothing = DepthSmoothingOptions{};
  const ProfileUpdateResult ok = UpdateProfile(line, acc, 1.0, o);
  EXPECT_EQ(ok.status, ProfileUpdateStatus::Updated) << ok.message;
  EXPECT_NEAR(ok.max_depth_m, 0.4e-3, 1e-12);
}

TEST(ProfileUpdate, S1002TwentyStepsStayValid) {
  Profile wheel = MakeS1002();
  const Profile original = wheel;
  ProfileUpdateOptions o;
  double total_distance = 0.0, worst_area = 0.0, worst_cap = 0.0, max_kappa = 0.0;
  for (int step = 1; step <= 20; ++step) {
    o.step_index = step;
    const WearDistribution acc = tread_flange_depth(wheel, 0.1e-3, step, 0.6);
    const ProfileUpdateResult r = UpdateProfile(wheel, acc, 1000.0, o);
    ASSERT_EQ(r.status, ProfileUpdateStatus::Updated) << r.message;
    worst_cap = std::max(worst_cap, relative(r.max_depth_m, o.max_depth_per_step_m));
    worst_area = std::max(worst_area, relative(r.removed_area_m2, r.scale_factor * acc.area_m2()));
    max_kappa = std::max(max_kappa, r.validity.max_abs_curvature_1_m);
    EXPECT_EQ(r.validity.y_folds_after, 0);
    total_distance += r.distance_step_m;
    wheel = r.profile;
  }
  RecordProperty("worst_cap_error", sci(worst_cap));
  RecordProperty("worst_area_error", sci(worst_area));
  RecordProperty("max_abs_curvature_1_m", sci(max_kappa));
  EXPECT_LT(worst_cap, 0.01);
  EXPECT_LT(worst_area, 0.005);
  // the tread lost about 20 x 0.4 mm at its peak (the field is fixed in y): radius at y = 0 down by 7-8 mm
  const double drop = *original.height_at(0.0) - *wheel.height_at(0.0);
  RecordProperty("tread_drop_mm", sci(drop * 1e3));
  // the active flange flank (around y = -38 mm, outward normal towards +z and +y) moved towards the flange
  // back (-y): the flange is thinner at z = 15 mm
  auto flank_y = [](const Profile& p, double z) {  // first y (from the flange back) where the flank passes z
    double lo = -0.045, hi = -0.030;  // bisection on the flank between the flange tip and the root
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (*p.height_at(mid) > z ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  };
  const double flank_shift = flank_y(wheel, 15e-3) - flank_y(original, 15e-3);
  RecordProperty("flank_shift_mm", sci(flank_shift * 1e3));
  RecordProperty("s1002_height_at_minus38_mm", sci(*original.height_at(-0.038) * 1e3));
  EXPECT_LT(flank_shift, -0.5e-3);
  EXPECT_GT(drop, 7.0e-3);
  EXPECT_LT(drop, 8.0e-3 + 1e-6);
  // the flange back and the outer tread end are untouched
  EXPECT_NEAR(*wheel.height_at(0.055), *original.height_at(0.055), 1e-6);
  EXPECT_GT(total_distance, 0.0);
}

namespace conforma {
namespace {

TEST(ProfileUpdate, OverhangCutRemovesOnlyTheLipAndReportsItsArea) {
  // A face descending in z with y increasing, except a lip: y = 2.0 and 1.5 above a recess at 1.2 (mm).
  // The reverse running minimum moves the lip back to y = 1.2: cut areas (2.0 - 1.2) * 1 + (1.5 - 1.2) * 1 mm^2.
  std::vector<Eigen::Vector2d> p;
  const double y[] = {0.0, 1.0, 2.0, 1.5, 1.2, 3.0, 4.0};
  for (int k = 0; k < 7; ++k) p.emplace_back(1e-3 * y[k], 1e-3 * (10.0 - k));
  const std::vector<Eigen::Vector2d> before = p;
  const double area = CutOverhangs(&p);
  EXPECT_NEAR(area, 1.1e-6, 1e-18);
  for (size_t k = 0; k + 1 < p.size(); ++k) EXPECT_LE(p[k].x(), p[k + 1].x());  // single-valued in y now
  for (size_t k = 0; k < p.size(); ++k) {
    EXPECT_LE(p[k].x(), before[k].x());       // material removed only (towards -y)
    EXPECT_EQ(p[k].y(), before[k].y());       // heights kept
  }
  EXPECT_NEAR(p[2].x(), 1.2e-3, 1e-15);
  EXPECT_NEAR(p[3].x(), 1.2e-3, 1e-15);
  // a curve without folds is left exactly as it is
  std::vector<Eigen::Vector2d> monotone = before;
  monotone[2].x() = 1.1e-3, monotone[3].x() = 1.15e-3;
  const std::vector<Eigen::Vector2d> copy = monotone;
  EXPECT_EQ(CutOverhangs(&monotone), 0.0);
  for (size_t k = 0; k < copy.size(); ++k) EXPECT_EQ(monotone[k], copy[k]);
}

// A wheel-like step with a vertical face: tread z = 10 mm, rounded (2 mm) into a face at y = 0 down to z = 0, then
// rounded out to the flat at z = 0; `face_y(z)` shifts the face's points laterally (m).
Profile vertical_face_profile(const std::function<double(double)>& face_y) {
  std::vector<Eigen::Vector2d> pts;
  const double r = 2e-3, h = 0.05e-3;
  for (int k = 0; k < 360; ++k) pts.emplace_back(-20e-3 + k * h, 10e-3);  // up to y = -2.05 mm
  for (int i = 0; i <= 60; ++i) {  // convex quarter: centre (-r, 8 mm)
    const double t = 0.5 * kPi * i / 60;
    pts.emplace_back(-r + r * std::sin(t), 8e-3 + r * std::cos(t));
  }
  for (int k = 1; k < 120; ++k) pts.emplace_back(face_y(8e-3 - k * h), 8e-3 - k * h);  // z = 7.95 ... 2.05 mm
  for (int i = 0; i <= 60; ++i) {  // concave quarter: centre (r, 2 mm)
    const double t = 0.5 * kPi * i / 60;
    pts.emplace_back(r - r * std::cos(t), 2e-3 - r * std::sin(t));
  }
  for (int k = 1; k <= 360; ++k) pts.emplace_back(r + k * h, 0.0);
  ProfileFitOptions fit;
  fit.function_of_y = false;
  return Profile::FromPoints(pts, ProfileKind::Wheel, fit, "vertical face");
}

// Folds are reversals of y beyond fold_tolerance_m (1 um): sub-um wiggles of a vertical face (what the former smoothing
// refit after an overhang cut left: the Aosta run stopped on 0.45 um peak to peak; here 0.5 um) are not folds, a face leaning back by 5 um is -- although
// each of its 0.05 mm segments leans by only 8e-4 of its length (the former per-segment rule, 1e-3, missed it).
TEST(ProfileUpdate, FoldsAreReversalsOfYBeyondTheTolerance) {
  const Profile base = vertical_face_profile([](double) { return 0.0; });
  const ProfileValidity self = CheckProfileValidity(base, base);
  EXPECT_TRUE(self.valid) << self.reason;
  EXPECT_EQ(self.y_folds_after, 0);
  const Profile wiggled = vertical_face_profile([](double z) { return 0.25e-6 * std::sin(2 * kPi * z / 0.6e-3); });
  const ProfileValidity w = CheckProfileValidity(wiggled, base);
  EXPECT_EQ(w.y_folds_after, 0) << w.reason;
  EXPECT_TRUE(w.valid) << w.reason;
  const Profile leaning = vertical_face_profile([](double z) { return -5e-6 * (8e-3 - z) / 6e-3; });
  const ProfileValidity l = CheckProfileValidity(leaning, base);
  EXPECT_FALSE(l.valid);
  EXPECT_GE(l.y_folds_after, 1);
  EXPECT_NE(l.reason.find("single-valued"), std::string::npos) << l.reason;
  ProfileValidityOptions bad;
  bad.fold_tolerance_m = 0.0;
  EXPECT_THROW(CheckProfileValidity(base, base, bad), InputError);
}


// Signed distance of q from the profile along its outward normal at the closest point (> 0: outside the body) [m].
double outside_distance(const Profile& profile, const Eigen::Vector2d& q) {
  const double s = profile.closest_s(q);
  return (q - profile.position(s)).dot(profile.normal(s));
}

// Area enclosed between two profiles with the same end points: the polygon old -> new reversed (shoelace) [m^2].
double area_between(const Profile& before, const Profile& after) {
  std::vector<Eigen::Vector2d> loop = before.samples();
  const std::vector<Eigen::Vector2d> a = after.samples();
  loop.insert(loop.end(), a.rbegin(), a.rend());
  double twice = 0.0;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Eigen::Vector2d& p = loop[i];
    const Eigen::Vector2d& q = loop[(i + 1) % loop.size()];
    twice += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * std::abs(twice);
}

// A wheel-like step: tread z = 10 mm (18 mm long), rounded (2 mm, convex) into a 6 mm straight face that leans
// `lean` from the vertical (y grows downwards), rounded (2 mm, concave) out to a 18 mm flat; built from the heading
// angle of each 0.05 mm segment, so the face meets both arcs tangentially.
Profile leaning_face_profile(double lean) {
  const double h = 0.05e-3, r = 2e-3, turn = 0.5 * kPi - lean;
  std::vector<Eigen::Vector2d> pts{{-20e-3, 10e-3}};
  double heading = 0.0;  // of the tangent, from +y
  auto walk = [&](double length, double curvature) {  // curvature > 0 turns counter-clockwise
    const int n = static_cast<int>(std::lround(length / h));
    const double ds = length / n;
    for (int k = 0; k < n; ++k) {  // exact chord of the arc (or the line)
      const double mid = heading + 0.5 * curvature * ds;
      const double chord = curvature == 0.0 ? ds : 2.0 * std::sin(0.5 * curvature * ds) / curvature;
      pts.push_back(pts.back() + chord * Eigen::Vector2d(std::cos(mid), std::sin(mid)));
      heading += curvature * ds;
    }
  };
  walk(18e-3, 0.0);
  walk(r * turn, -1.0 / r);
  walk(6e-3, 0.0);
  walk(r * turn, 1.0 / r);
  walk(18e-3, 0.0);
  ProfileFitOptions fit;
  fit.function_of_y = false;
  return Profile::FromPoints(pts, ProfileKind::Wheel, fit, "leaning face");
}

// A flange face leaning 5 degrees from the vertical (y grows by tan 5 deg per unit of descent) loses a band around the
// middle of the face (Gaussian in z, sigma 1.5 mm, 0.4 mm at its centre, no depth smoothing): the band's lateral shift
// grows downwards by up to 0.16 per unit of descent, more than the face's 0.087, so the face above the band overhangs
// by up to ~0.1 mm and is cut (a large cut, ~0.2 mm^2). The profile after the update must be single-valued in y at a
// tolerance 1000x below ProfileValidityOptions::fold_tolerance_m (the rounding of the cut corner must not leave the
// 1-um wiggles the Aosta run stopped on), lie inside the old profile and inside the profile the removal alone gives
// (the cut and its rounding remove material only), and the area between the old and the new profile must be the
// removed area plus the reported cut area.
TEST(ProfileUpdate, OverhangCutOfAFaceWornPastVerticalIsSingleValuedAndInside) {
  const Profile wheel = leaning_face_profile(5.0 * kPi / 180.0);
  const double z_mid = wheel.position(0.5 * wheel.length()).y();  // the middle of the face
  WearDistribution acc = WearDistribution::ForProfile(wheel, 0.05e-3);
  for (size_t i = 0; i < acc.size(); ++i) {
    const Eigen::Vector2d p = wheel.position(acc.s(i));
    acc.depth_m[i] = 1e-6 * gauss(p.y(), z_mid, 1.5e-3);
  }
  ProfileUpdateOptions o;
  o.smoothing.cutoff_wavelength_m = 0.0;
  const ProfileUpdateResult r = UpdateProfile(wheel, acc, 1.0, o);
  ASSERT_EQ(r.status, ProfileUpdateStatus::Updated) << r.message;
  RecordProperty("overhang_cut_mm2", sci(r.overhang_cut_area_m2 * 1e6));
  RecordProperty("removed_mm2", sci(r.removed_area_m2 * 1e6));
  EXPECT_GT(r.overhang_cut_area_m2, 0.1e-6);  // a large cut
  // single-valued in y at 1 nm
  ProfileValidityOptions strict;
  strict.fold_tolerance_m = 1e-9;
  const ProfileValidity v = CheckProfileValidity(r.profile, wheel, strict);
  EXPECT_EQ(v.y_folds_after, 0) << v.reason;
  const std::vector<Eigen::Vector2d> pts = r.profile.samples();
  double worst_back = 0.0;  // largest step back in y along the samples
  for (size_t i = 1; i < pts.size(); ++i) worst_back = std::max(worst_back, pts[i - 1].x() - pts[i].x());
  RecordProperty("worst_y_step_back_m", sci(worst_back));
  EXPECT_LE(worst_back, 0.0);
  // material removed only: no sample outside the old profile (1 nm), nor outside the profile the removal alone gives
  double worst_outside = -1.0;
  for (const auto& q : pts) worst_outside = std::max(worst_outside, outside_distance(wheel, q));
  RecordProperty("worst_outside_old_m", sci(worst_outside));
  EXPECT_LE(worst_outside, 1e-9);
  const Profile removed_only = RemoveAlongNormal(wheel, r.removed_depth);  // folded: what the cut starts from
  double worst_outside_removed = -1.0;
  for (const auto& q : pts) worst_outside_removed = std::max(worst_outside_removed, outside_distance(removed_only, q));
  RecordProperty("worst_outside_removed_only_m", sci(worst_outside_removed));
  // (the refit is an interpolating cubic through the rounded samples: next to the ends of the rounding it bulges by
  // up to ~30 nm, 3e-4 of the 0.1 mm spacing; the former smoothing-spline rounding put the profile 8 um outside)
  EXPECT_LE(worst_outside_removed, 0.1e-6);
  // bookkeeping: the area between the profiles is the removed area plus the cut area
  const double between = area_between(wheel, r.profile);
  RecordProperty("area_between_mm2", sci(between * 1e6));
  EXPECT_NEAR(between, r.removed_area_m2 + r.overhang_cut_area_m2, 0.005 * (r.removed_area_m2 + r.overhang_cut_area_m2));
}


// The area-conserving cut (ProfileUpdateOptions::cut_conserves_area, docs/physics-reference.md §8.7): on the same
// leaning face and band as above, the lip the cut removes counts as the step's wear, so the material the step takes
// (smoothed removal + cut) equals the removal alone without the option, to the 1e-3 the bisection stops at; the step's
// distance is the same (the scale factor is fixed before the cut), the profile is still single-valued and inside the
// old one, and the cut is smaller than the one made on top of the full removal (wear_off).
TEST(ProfileUpdate, AreaConservingCutKeepsTheStepsWearArea) {
  const Profile wheel = leaning_face_profile(5.0 * kPi / 180.0);
  const double z_mid = wheel.position(0.5 * wheel.length()).y();
  WearDistribution acc = WearDistribution::ForProfile(wheel, 0.05e-3);
  for (size_t i = 0; i < acc.size(); ++i) acc.depth_m[i] = 1e-6 * gauss(wheel.position(acc.s(i)).y(), z_mid, 1.5e-3);
  ProfileUpdateOptions o;
  o.smoothing.cutoff_wavelength_m = 0.0;
  o.cut_conserves_area = false;
  const ProfileUpdateResult off = UpdateProfile(wheel, acc, 1.0, o);
  o.cut_conserves_area = true;
  const ProfileUpdateResult on = UpdateProfile(wheel, acc, 1.0, o);
  ASSERT_EQ(off.status, ProfileUpdateStatus::Updated) << off.message;
  ASSERT_EQ(on.status, ProfileUpdateStatus::Updated) << on.message;
  RecordProperty("wear_off_removed_plus_cut_mm2", sci((off.removed_area_m2 + off.overhang_cut_area_m2) * 1e6));
  RecordProperty("conserve_removed_mm2", sci(on.removed_area_m2 * 1e6));
  RecordProperty("conserve_cut_mm2", sci(on.overhang_cut_area_m2 * 1e6));
  RecordProperty("cut_area_scale", sci(on.cut_area_scale));
  EXPECT_EQ(off.cut_area_scale, 1.0);
  ASSERT_GT(off.overhang_cut_area_m2, 0.1e-6);  // the case makes a large cut
  EXPECT_TRUE(on.cut_area_conserved);
  EXPECT_GT(on.cut_area_scale, 0.0);
  EXPECT_LT(on.cut_area_scale, 1.0);
  EXPECT_EQ(on.scale_factor, off.scale_factor);  // the step stands for the same distance
  EXPECT_NEAR(on.removed_area_m2 + on.overhang_cut_area_m2, off.removed_area_m2, 1e-3 * off.removed_area_m2);
  EXPECT_LT(on.overhang_cut_area_m2, off.overhang_cut_area_m2);
  // the profile: single-valued in y at 1 nm, inside the old one, the area between = removal + cut (as above)
  ProfileValidityOptions strict;
  strict.fold_tolerance_m = 1e-9;
  EXPECT_EQ(CheckProfileValidity(on.profile, wheel, strict).y_folds_after, 0);
  double worst_outside = -1.0;
  for (const auto& q : on.profile.samples()) worst_outside = std::max(worst_outside, outside_distance(wheel, q));
  EXPECT_LE(worst_outside, 1e-9);
  EXPECT_NEAR(area_between(wheel, on.profile), off.removed_area_m2, 0.005 * off.removed_area_m2);
}


// The samples of a profile taken back as nodes (what UpdateProfile does after cutting the refit of an overhang cut)
// give the same curve: the nodes exactly, the length to the polyline's (chord) error, points between nodes to ~nm.
TEST(ProfileUpdate, FromArcLengthSamplesKeepsTheNodes) {
  const Profile arc = circle_arc(0.3, 0.2);
  const std::vector<Eigen::Vector2d> nodes = arc.samples();
  const Profile back = Profile::FromArcLengthSamples(nodes, arc.kind(), "samples");
  const std::vector<Eigen::Vector2d> again = back.samples();
  ASSERT_EQ(again.size(), nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) EXPECT_EQ(again[i], nodes[i]);
  // chord vs arc: relative length deficit h^2 / (24 R^2) = 4.6e-9 at h = 0.1 mm, R = 0.3 m
  EXPECT_NEAR(back.length(), arc.length(), 1e-8 * arc.length());
  for (double s = 0.5 * back.spacing(); s < back.length(); s += 37.3 * back.spacing())
    EXPECT_LT((back.position(s) - arc.position(s)).norm(), 1e-9);
  EXPECT_THROW(Profile::FromArcLengthSamples({nodes[0], nodes[1], nodes[2]}, arc.kind()), InputError);
}

}  // namespace
}  // namespace conforma
