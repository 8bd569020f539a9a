// Contact look-up table (contact_lut.hpp): exactness at the grid nodes, interpolation error against direct solves,
// two-point contact kept as two patches, HDF5 round trip, out-of-table and bad input, thread-count independence.
// test-links: lut

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>

#include <unistd.h>
#include <type_traits>

#include "conforma/contact_lut.hpp"
#include "conforma/contact_lut_check.hpp"
#include "conforma/contact_lut_io.hpp"
#include "conforma/error.hpp"
#include "conforma/kinematics_quasistatic.hpp"
#include "conforma/wheel_contact.hpp"
#include "pipeline_test_geometry.hpp"

using namespace conforma;

// the LUT is a WheelContactFunction (the curving's and the dynamics' contact evaluation)
static_assert(std::is_same<LutContactFunction, WheelContactFunction>::value, "LUT function type");

namespace {

const WheelsetTrackGeometry& Geometry() { return test::PipelineGeometry(); }

WheelContactOptions Options(ContactModel model, LoadBalance balance = LoadBalance::Pressure) {
  WheelContactOptions o;
  o.model = model;
  o.load_balance = balance;
  return o;
}

std::vector<double> Axis(double lo, double hi, double step, double scale) {
  std::vector<double> v;
  for (int k = 0; lo + k * step <= hi + 1e-9 * step; ++k) v.push_back((lo + k * step) * scale);
  return v;
}

// S1002 / 60E1 1:40 over tread and flange (flange contact from y ~ 6 mm), hertz
const ContactLut& HertzLut() {
  static const ContactLut lut = [] {
    ContactLutBuildOptions b;
    b.grid.lateral_m = Axis(-4.0, 8.0, 0.25, 1e-3);
    b.grid.yaw_rad = {-2e-3, 0.0, 2e-3};
    b.grid.load_N = {30e3, 50e3, 70e3};
    b.contact = Options(ContactModel::Hertz);
    b.wheel_profile = "S1002";
    b.rail_profile = "60E1";
    return BuildContactLut(Geometry(), b);
  }();
  return lut;
}

// the same pair with the conformal model, coarser
const ContactLut& ConformalLut() {
  static const ContactLut lut = [] {
    ContactLutBuildOptions b;
    b.grid.lateral_m = Axis(-2.0, 4.0, 0.5, 1e-3);
    b.grid.yaw_rad = {0.0, 2e-3};
    b.grid.load_N = {40e3, 60e3};
    b.contact = Options(ContactModel::Conformal);
    return BuildContactLut(Geometry(), b);
  }();
  return lut;
}

WheelsetVelocity Velocity() {  // rolling with a little lateral and axle creep and a curve's yaw rate (partial slip)
  return {10.0, 0.002, 10.0 / 2000.0, 10.0 / 0.46 * (1.0 + 2e-4)};
}

WheelContactReport Direct(Side side, double y, double psi, double Q, WheelContactOptions o) {
  o.vertical_load_N = Q;
  const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(y, psi);
  EXPECT_EQ(eq.status, EquilibriumStatus::Converged);
  return SolveWheelContact(Geometry(), side, eq.pose, Velocity(), o);
}

WheelContactReport FromLut(const ContactLut& lut, Side side, double y, double psi, double Q, WheelContactOptions o,
                           LutCellInfo* info = nullptr) {
  o.vertical_load_N = Q;
  const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(y, psi);
  return EvaluateContactLut(lut, Geometry(), side, eq.pose, Velocity(), o, info);
}

}  // namespace

// At a grid node the table holds the direct solution: the normal fields to round-off; with the hertz model the
// creep forces too (the same FASTSIM on the same ellipse with the pipeline's creepages, rebuilt from the affine map).
TEST(ContactLut, NodeValuesEqualTheDirectSolveToRoundOff) {
  const ContactLut& lut = HertzLut();
  int checked = 0, two_patch = 0;
  for (double y_mm : {-3.0, 0.0, 2.5, 5.0, 6.5, 7.25}) {
    for (Side side : {Side::Left, Side::Right}) {
      const double Q = 50e3;
      const WheelContactReport d = Direct(side, y_mm * 1e-3, 2e-3, Q, Options(ContactModel::Hertz));
      const WheelContactReport l = FromLut(lut, side, y_mm * 1e-3, 2e-3, Q, Options(ContactModel::Hertz));
      ASSERT_EQ(d.status, WheelContactStatus::Ok);
      ASSERT_EQ(l.status, d.status);
      ASSERT_EQ(l.patches.size(), d.patches.size()) << "y " << y_mm;
      two_patch += d.patches.size() == 2;
      for (size_t j = 0; j < d.patches.size(); ++j) {
        const PatchReport &a = d.patches[j], &b = l.patches[j];
        EXPECT_NEAR(b.fn_N, a.fn_N, 1e-9 * Q);
        EXPECT_NEAR(b.y_contact_rail_m, a.y_contact_rail_m, 1e-15);
        EXPECT_NEAR(b.contact_angle_rad, a.contact_angle_rad, 1e-15);
        EXPECT_NEAR(b.pmax_Pa, a.pmax_Pa, 1e-9 * a.pmax_Pa);
        EXPECT_NEAR(b.a_m, a.a_m, 1e-15);
        EXPECT_NEAR(b.xi, a.xi, 1e-15);
        EXPECT_NEAR(b.eta, a.eta, 1e-15);
        EXPECT_NEAR(b.phi_per_m, a.phi_per_m, 1e-12);
        EXPECT_NEAR(b.fx_N, a.fx_N, 1e-8 * Q);
        EXPECT_NEAR(b.fy_N, a.fy_N, 1e-8 * Q);
        EXPECT_NEAR(b.mz_Nm, a.mz_Nm, 1e-8 * Q * 1e-3);
        ++checked;
      }
      EXPECT_NEAR(l.vertical_force_N, d.vertical_force_N, 1e-8 * Q);
      EXPECT_NEAR(l.lateral_force_N, d.lateral_force_N, 1e-8 * Q);
    }
  }
  EXPECT_GE(checked, 12);
  EXPECT_GE(two_patch, 1);  // the flange region holds two-point contact
}

// The conformal model's normal solution at a node is the direct one; its creep forces come from the curved-patch
// FASTSIM scheme on the patch's stations, which are the KP solution's strips for a one-lobe patch (kLutStations =
// kDefaultKpStrips), with the traction bound carrying the surface pressure integral as in the direct solve: the same
// forces to round-off (docs/physics-reference.md §17.3; with 12 stations and the bound scaled to F_n the difference
// reached 1-6 % of mu Q at the flange root of S1002 / 50E4 1:20).
TEST(ContactLut, ConformalNodeCreepForcesEqualTheDirectSolve) {
  const ContactLut& lut = ConformalLut();
  int checked = 0;
  for (double y_mm : {-2.0, 0.5, 3.0, 4.0}) {
    const double Q = 60e3;
    const WheelContactReport d = Direct(Side::Left, y_mm * 1e-3, 2e-3, Q, Options(ContactModel::Conformal));
    const WheelContactReport l = FromLut(lut, Side::Left, y_mm * 1e-3, 2e-3, Q, Options(ContactModel::Conformal));
    ASSERT_EQ(l.patches.size(), d.patches.size());
    for (size_t j = 0; j < d.patches.size(); ++j) {
      EXPECT_NEAR(l.patches[j].fn_N, d.patches[j].fn_N, 1e-9 * Q);
      EXPECT_NEAR(l.patches[j].y_contact_rail_m, d.patches[j].y_contact_rail_m, 1e-15);
      EXPECT_NEAR(l.patches[j].fx_N, d.patches[j].fx_N, 1e-6 * 0.3 * Q) << "y " << y_mm;
      EXPECT_NEAR(l.patches[j].fy_N, d.patches[j].fy_N, 1e-6 * 0.3 * Q) << "y " << y_mm;
      // the table's spin moment is the curvilinear sum (x p_s - s p_x) dA, the direct one the moment of the strips on
      // the curved surface about the reference point: they differ by the surface's curvature (measured <= 2.4e-4)
      EXPECT_NEAR(l.patches[j].mz_Nm, d.patches[j].mz_Nm, 1e-3 * std::fabs(d.patches[j].mz_Nm) + 1e-3) << "y " << y_mm;
      ++checked;
    }
  }
  EXPECT_GE(checked, 4);
}

// Between the nodes of single-topology cells on the tread (0.25 mm, 2 mrad, 20 kN steps): the targets,
// normal force within 1 % of Q, contact position within 0.1 mm, creep forces within 1 % of mu Q.
TEST(ContactLut, InterpolationBetweenNodesMeetsTheTargetsOnTheTread) {
  const ContactLut& lut = HertzLut();
  int checked = 0;
  for (double y_mm : {-3.37, -1.12, 0.61, 1.88, 3.13, 4.41}) {
    for (double psi : {-1.3e-3, 0.7e-3}) {
      for (Side side : {Side::Left, Side::Right}) {
        const double Q = 43.7e3;
        LutCellInfo info;
        const WheelContactReport l = FromLut(lut, side, y_mm * 1e-3, psi, Q, Options(ContactModel::Hertz), &info);
        if (!info.single_topology) continue;
        const WheelContactReport d = Direct(side, y_mm * 1e-3, psi, Q, Options(ContactModel::Hertz));
        ASSERT_EQ(l.patches.size(), d.patches.size());
        for (size_t j = 0; j < d.patches.size(); ++j) {
          EXPECT_NEAR(l.patches[j].fn_N, d.patches[j].fn_N, 0.01 * Q) << "y " << y_mm;
          EXPECT_NEAR(l.patches[j].y_contact_rail_m, d.patches[j].y_contact_rail_m, 0.1e-3) << "y " << y_mm;
          EXPECT_NEAR(l.patches[j].fx_N, d.patches[j].fx_N, 0.01 * 0.3 * Q) << "y " << y_mm;
          EXPECT_NEAR(l.patches[j].fy_N, d.patches[j].fy_N, 0.01 * 0.3 * Q) << "y " << y_mm;
        }
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 16);
}

// Two-point contact of S1002 on 60E1 (1:40, hertz, rigid flange) pushed towards the flange: tread (0.12-0.14 rad)
// and flange root (0.29-0.32 rad) together at y = 4.75-5.25 mm, the flange root alone up to 6.25 mm, then the jump
// onto the flange (1.2 rad, the tread lifted). Inside a cell whose corners all have the two patches the LUT keeps
// them apart (never one averaged patch); in a cell where the topology changes it takes the nearest node's and
// interpolates only among the corners sharing it (each angle within those corners' angles).
TEST(ContactLut, TwoPointContactKeepsTwoPatches) {
  const ContactLut& lut = HertzLut();
  const ContactLutGrid& g = lut.grid;
  const std::vector<LutNode>& nodes = lut.nodes[side_index(Side::Left)];
  int two_patch_cells = 0, jump_cells = 0, emerging_cells = 0, tread_and_flange = 0;
  for (size_t iy = 0; iy + 1 < g.lateral_m.size(); ++iy) {
    const size_t ip = 1, iq = 1;  // yaw 0 .. 2 mrad, load 50 .. 70 kN
    int two = 0;
    for (int c = 0; c < 8; ++c)
      two += nodes[g.index(iy + (c >> 2 & 1), ip + (c >> 1 & 1), iq + (c & 1))].patches.size() == 2;
    if (two == 0) continue;
    for (double t : {0.3, 0.7}) {
      const double y = g.lateral_m[iy] + t * (g.lateral_m[iy + 1] - g.lateral_m[iy]);
      const double psi = 0.9e-3, Q = 61e3;
      LutCellInfo info;
      const WheelContactReport l = FromLut(lut, Side::Left, y, psi, Q, Options(ContactModel::Hertz), &info);
      ASSERT_EQ(l.status, WheelContactStatus::Ok);
      if (two == 8) {
        ++two_patch_cells;
        ASSERT_EQ(l.patches.size(), 2u) << "y " << y;
        // two separate patches (also two tread patches of two rigid gap minima elsewhere on the tread)
        EXPECT_GT(std::fabs(l.patches[0].reference_s_on_rail_m - l.patches[1].reference_s_on_rail_m), 2e-3);
        const double lo = std::min(l.patches[0].contact_angle_rad, l.patches[1].contact_angle_rad);
        const double hi = std::max(l.patches[0].contact_angle_rad, l.patches[1].contact_angle_rad);
        if (hi > 0.25) {  // tread (0.12-0.14 rad) and flange root (0.29-0.32 rad)
          ++tread_and_flange;
          EXPECT_LT(lo, 0.2);
        }
        const WheelContactReport d = Direct(Side::Left, y, psi, Q, Options(ContactModel::Hertz));
        ASSERT_EQ(d.patches.size(), 2u) << "y " << y;
        for (size_t j = 0; j < 2; ++j) {
          EXPECT_NEAR(l.patches[j].contact_angle_rad, d.patches[j].contact_angle_rad, 0.05);
          EXPECT_NEAR(l.patches[j].fn_N, d.patches[j].fn_N, 0.05 * Q);
        }
      } else if (info.union_topology) {
        ++emerging_cells;
        EXPECT_FALSE(info.single_topology);
        // an emerging patch: the corner with the most patches decides the topology, and the patch's normal force
        // lies between zero and its largest corner value (it enters with zero force where a corner lacks it)
        size_t most = 0;
        for (int c = 0; c < 8; ++c)
          most = std::max(most, nodes[g.index(iy + (c >> 2 & 1), ip + (c >> 1 & 1), iq + (c & 1))].patches.size());
        ASSERT_EQ(l.patches.size(), most) << "y " << y;
        for (const PatchReport& p : l.patches) {
          EXPECT_GT(p.fn_N, 0.0);
          EXPECT_LT(p.fn_N, 1.2 * Q);
        }
      } else {
        ++jump_cells;
        EXPECT_FALSE(info.single_topology);
        // the nearest corner's topology (psi: t = 0.45 -> lower, Q: t = 0.55 -> upper), each patch's angle within
        // those of the corners sharing it: nothing averaged across a topology change
        const LutNode& nearest = nodes[g.index(iy + (t > 0.5 ? 1 : 0), ip, iq + 1)];
        ASSERT_EQ(l.patches.size(), nearest.patches.size()) << "y " << y;
        for (size_t j = 0; j < l.patches.size(); ++j) {
          double lo = 1e9, hi = -1e9;
          for (int c = 0; c < 8; ++c) {
            const LutNode& n = nodes[g.index(iy + (c >> 2 & 1), ip + (c >> 1 & 1), iq + (c & 1))];
            if (n.patches.size() != nearest.patches.size()) continue;
            lo = std::min(lo, n.patches[j].contact_angle_rad);
            hi = std::max(hi, n.patches[j].contact_angle_rad);
          }
          EXPECT_GE(l.patches[j].contact_angle_rad, lo - 1e-12);
          EXPECT_LE(l.patches[j].contact_angle_rad, hi + 1e-12);
        }
      }
    }
  }
  std::printf("two-patch cells %d, emerging-patch cells %d, jump cells %d\n", two_patch_cells, emerging_cells, jump_cells);
  EXPECT_GE(tread_and_flange, 2);
  EXPECT_GE(jump_cells + emerging_cells, 4);
}

// Every cell of the table with a topology change and all corners Ok (patch tracks, union topology): the wheel's
// normal force is continuous across the cell (no step where the nearest corner changes: a total-force balance has a
// root), whether a flange patch emerges or the tread's contact point moves to another place; a cell with a corner
// that is not Ok keeps the nearest corner's topology.
TEST(ContactLut, TopologyChangesAreContinuousAcrossTheCell) {
  const ContactLut& lut = HertzLut();
  const ContactLutGrid& g = lut.grid;
  int emerging = 0, jumps = 0;
  for (size_t iy = 0; iy + 1 < g.lateral_m.size(); ++iy)
    for (size_t ip = 0; ip + 1 < g.yaw_rad.size(); ++ip) {
      const double psi = 0.5 * (g.yaw_rad[ip] + g.yaw_rad[ip + 1]) + 1e-5, Q = 0.5 * (g.load_N[0] + g.load_N[1]) + 1e3;
      const double ym = 0.5 * (g.lateral_m[iy] + g.lateral_m[iy + 1]), eps = 1e-9;
      LutCellInfo a_info, b_info;
      // the pressure balance: the interpolated normal solution itself (the total balance adds its secant's tolerance)
      const WheelContactOptions o = Options(ContactModel::Hertz, LoadBalance::Pressure);
      const WheelContactReport a = FromLut(lut, Side::Left, ym - eps, psi, Q, o, &a_info);
      const WheelContactReport b = FromLut(lut, Side::Left, ym + eps, psi, Q, o, &b_info);
      if (a_info.single_topology || a.status != WheelContactStatus::Ok || b.status != WheelContactStatus::Ok) continue;
      double fa = 0.0, fb = 0.0;
      for (const PatchReport& p : a.patches) fa += p.fn_N;
      for (const PatchReport& p : b.patches) fb += p.fn_N;
      if (a_info.union_topology) {
        ++emerging;
        EXPECT_TRUE(b_info.union_topology);
        EXPECT_EQ(a.patches.size(), b.patches.size());
        // continuous: the change over the 2e-9 m step across the mid-plane is that of the same step beside it (the
        // force may move steeply between two patches, but it does not jump)
        const WheelContactReport c = FromLut(lut, Side::Left, ym + 3.0 * eps, psi, Q, o);
        double fc = 0.0;
        for (const PatchReport& p : c.patches) fc += p.fn_N;
        EXPECT_LE(std::fabs(fb - fa), 2.0 * std::fabs(fc - fb) + 1e-9 * Q) << "y " << ym;
      } else {
        ++jumps;
        EXPECT_FALSE(b_info.union_topology);
      }
    }
  std::printf("cells with a topology change at the y midpoint: %d emerging-patch, %d jump\n", emerging, jumps);
  EXPECT_GE(emerging, 4);
}

// With the total-force balance the LUT's wheel carries the load (pressure and creep forces) like the direct solve.
TEST(ContactLut, TotalForceBalanceCarriesTheLoad) {
  const ContactLut& lut = HertzLut();
  const double Q = 47e3;
  const WheelContactOptions o = Options(ContactModel::Hertz, LoadBalance::Total);
  const WheelContactReport l = FromLut(lut, Side::Left, 1.1e-3, 0.5e-3, Q, o);
  const WheelContactReport d = Direct(Side::Left, 1.1e-3, 0.5e-3, Q, o);
  ASSERT_EQ(l.status, WheelContactStatus::Ok);
  EXPECT_NEAR(l.vertical_force_N, Q, 1e-5 * Q);
  EXPECT_NEAR(l.pressure_vertical_force_N, d.pressure_vertical_force_N, 0.01 * Q);
  EXPECT_NEAR(l.lateral_force_N, d.lateral_force_N, 0.01 * Q);
}

TEST(ContactLut, FileRoundTripIsExact) {
  const ContactLut& lut = ConformalLut();
  const std::string path = (std::filesystem::temp_directory_path() /
                                ("conforma_test_contact_lut_" + std::to_string(getpid()) + ".h5")).string();
  SaveContactLut(lut, path);
  const ContactLut back = LoadContactLut(path);
  std::filesystem::remove(path);
  EXPECT_EQ(back.grid.lateral_m, lut.grid.lateral_m);
  EXPECT_EQ(back.grid.yaw_rad, lut.grid.yaw_rad);
  EXPECT_EQ(back.grid.load_N, lut.grid.load_N);
  EXPECT_EQ(back.header.model, lut.header.model);
  EXPECT_EQ(back.header.rail_origin_eta_m, lut.header.rail_origin_eta_m);
  EXPECT_EQ(back.header.max_touching_contact_angle_rad, lut.header.max_touching_contact_angle_rad);
  for (int s = 0; s < 2; ++s) {
    ASSERT_EQ(back.nodes[s].size(), lut.nodes[s].size());
    for (size_t k = 0; k < lut.nodes[s].size(); ++k) {
      const LutNode &a = lut.nodes[s][k], &b = back.nodes[s][k];
      ASSERT_EQ(a.status, b.status);
      ASSERT_EQ(a.vertical_m, b.vertical_m);
      ASSERT_EQ(a.roll_rad, b.roll_rad);
      ASSERT_EQ(a.patches.size(), b.patches.size());
      for (size_t j = 0; j < a.patches.size(); ++j) {
        const LutPatch &p = a.patches[j], &q = b.patches[j];
        EXPECT_EQ(p.model, q.model);
        EXPECT_EQ(p.fn_N, q.fn_N);
        EXPECT_EQ(p.y_contact_rail_m, q.y_contact_rail_m);
        EXPECT_EQ(p.pressure_lateral_N, q.pressure_lateral_N);
        EXPECT_EQ(p.a_m, q.a_m);
        EXPECT_EQ(p.centre_s_m, q.centre_s_m);
        EXPECT_EQ(p.creepage_map, q.creepage_map);
        EXPECT_EQ(p.slip_map, q.slip_map);
        EXPECT_EQ(p.stations, q.stations);
        EXPECT_EQ(p.station_s_max_m, q.station_s_max_m);
      }
    }
  }
  const WheelContactReport x = FromLut(lut, Side::Right, 1.3e-3, 1e-3, 50e3, Options(ContactModel::Conformal));
  const WheelContactReport y = FromLut(back, Side::Right, 1.3e-3, 1e-3, 50e3, Options(ContactModel::Conformal));
  ASSERT_EQ(x.patches.size(), y.patches.size());
  for (size_t j = 0; j < x.patches.size(); ++j) EXPECT_EQ(x.patches[j].fy_N, y.patches[j].fy_N);
}

TEST(ContactLut, OutsideTheTableIsAnInputErrorNamingTheAxis) {
  const ContactLut& lut = HertzLut();
  auto message = [&](double y, double psi, double Q) {
    try {
      FromLut(lut, Side::Left, y, psi, Q, Options(ContactModel::Hertz));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message(9e-3, 0.0, 50e3).find("lateral shift y = 9 mm"), std::string::npos) << message(9e-3, 0.0, 50e3);
  EXPECT_NE(message(0.0, 3e-3, 50e3).find("yaw psi"), std::string::npos);
  EXPECT_NE(message(0.0, 0.0, 90e3).find("wheel load Q"), std::string::npos);
}

TEST(ContactLut, BadInputIsAnInputError) {
  const ContactLut& lut = HertzLut();
  const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(0.0, 0.0);
  WheelContactOptions o = Options(ContactModel::Hertz);
  o.vertical_load_N = -1.0;  // approach mode is not tabulated
  EXPECT_THROW(EvaluateContactLut(lut, Geometry(), Side::Left, eq.pose, Velocity(), o), InputError);
  o.vertical_load_N = 50e3;
  o.model = ContactModel::Kpec;  // not the table's model
  EXPECT_THROW(EvaluateContactLut(lut, Geometry(), Side::Left, eq.pose, Velocity(), o), InputError);
  o.model = ContactModel::Hertz;
  // another elastic flange than the table's: named in degrees, the rigid flange as such (a 300-digit number before)
  WheelContactOptions elastic = o;
  elastic.max_touching_contact_angle_rad = lut.header.max_touching_contact_angle_rad <
                                                   WheelsetTrackGeometry::kAllContactAngles
                                               ? WheelsetTrackGeometry::kAllContactAngles
                                               : 60.0 * M_PI / 180.0;
  try {
    EvaluateContactLut(lut, Geometry(), Side::Left, eq.pose, Velocity(), elastic);
    ADD_FAILURE() << "another elastic flange was accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("elastic flange (--elastic-flange-deg)"), std::string::npos) << what;
    EXPECT_NE(what.find("none: rigid flange"), std::string::npos) << what;
    EXPECT_LT(what.size(), 200u) << what;
  }
  o.vertical_load_N = 0.0;  // unloaded: no contact, as the pipeline
  EXPECT_EQ(EvaluateContactLut(lut, Geometry(), Side::Left, eq.pose, Velocity(), o).status,
            WheelContactStatus::NoContact);
  EXPECT_THROW(LoadContactLut("/nonexistent/folder/no_such_table.h5"), InputError);
  ContactLutBuildOptions b;
  b.grid.lateral_m = {0.0, 1e-3};
  b.grid.yaw_rad = {0.0, 0.0};  // not increasing
  b.grid.load_N = {40e3, 60e3};
  EXPECT_THROW(BuildContactLut(Geometry(), b), InputError);
  b.grid.yaw_rad = {0.0, 1e-3};
  b.grid.load_N = {-10e3, 60e3};  // negative load
  EXPECT_THROW(BuildContactLut(Geometry(), b), InputError);
  EXPECT_THROW(MakeLutContactFunction(nullptr), InputError);
}

// Each node is solved on its own and written into its slot: 1 and 2 threads give the identical table.
TEST(ContactLut, GenerationIsIndependentOfTheThreadCount) {
  ContactLutBuildOptions b;
  b.grid.lateral_m = Axis(4.0, 8.0, 0.5, 1e-3);
  b.grid.yaw_rad = {0.0, 2e-3};
  b.grid.load_N = {40e3, 60e3};
  b.contact = Options(ContactModel::Kpec);
  b.threads = 1;
  const ContactLut one = BuildContactLut(Geometry(), b);
  b.threads = 2;
  const ContactLut two = BuildContactLut(Geometry(), b);
  for (int s = 0; s < 2; ++s)
    for (size_t k = 0; k < one.nodes[s].size(); ++k) {
      ASSERT_EQ(one.nodes[s][k].patches.size(), two.nodes[s][k].patches.size());
      EXPECT_EQ(one.nodes[s][k].vertical_m, two.nodes[s][k].vertical_m);
      for (size_t j = 0; j < one.nodes[s][k].patches.size(); ++j) {
        EXPECT_EQ(one.nodes[s][k].patches[j].fn_N, two.nodes[s][k].patches[j].fn_N);
        EXPECT_EQ(one.nodes[s][k].patches[j].slip_map, two.nodes[s][k].patches[j].slip_map);
      }
    }
}

// As a WheelContactFunction the LUT gives what EvaluateContactLut gives.
TEST(ContactLut, ContactFunctionWrapsTheEvaluation) {
  auto lut = std::make_shared<const ContactLut>(HertzLut());
  const WheelContactFunction f = MakeLutContactFunction(lut);
  WheelContactOptions o = Options(ContactModel::Hertz);
  o.vertical_load_N = 55e3;
  const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(2.2e-3, 0.3e-3);
  const WheelContactReport a = f(Geometry(), Side::Right, eq.pose, Velocity(), o);
  const WheelContactReport b = EvaluateContactLut(*lut, Geometry(), Side::Right, eq.pose, Velocity(), o);
  ASSERT_EQ(a.patches.size(), b.patches.size());
  EXPECT_EQ(a.lateral_force_N, b.lateral_force_N);
}

// The tabulated rigid equilibrium: at a node the table's roll is the rigid solve's; between nodes within the
// bilinear interpolation's error of it (roll varies smoothly on the tread: a few microradians over a 0.25 mm step).
TEST(ContactLut, TabulatedRigidPoseMatchesTheRigidSolve) {
  const ContactLut& lut = HertzLut();
  const WheelsetTrackGeometry& g = Geometry();
  const LutPoseFunction pose = MakeLutPoseFunction(std::make_shared<const ContactLut>(lut));
  EquilibriumOptions eo;
  eo.max_touching_contact_angle_rad = lut.header.max_touching_contact_angle_rad;
  const double y_node = lut.grid.lateral_m[8], psi_node = lut.grid.yaw_rad[1];
  const EquilibriumResult at_node = pose(g, y_node, psi_node, eo);
  const EquilibriumResult direct_node = g.SolveRigidEquilibrium(y_node, psi_node, WheelsetPose{}, eo);
  ASSERT_EQ(at_node.status, EquilibriumStatus::Converged);
  EXPECT_NEAR(at_node.pose.roll_rad, direct_node.pose.roll_rad, 1e-12);
  double worst = 0.0;
  for (double y_mm : {-3.1, -0.6, 1.3, 2.9, 4.4}) {
    const EquilibriumResult t = pose(g, y_mm * 1e-3, 0.7e-3, eo);
    const EquilibriumResult d = g.SolveRigidEquilibrium(y_mm * 1e-3, 0.7e-3, WheelsetPose{}, eo);
    ASSERT_EQ(t.status, EquilibriumStatus::Converged);
    EXPECT_EQ(t.pose.lateral_m, y_mm * 1e-3);
    worst = std::max(worst, std::fabs(t.pose.roll_rad - d.pose.roll_rad));
  }
  std::printf("tabulated roll against the rigid solve on the tread: worst %.3g urad\n", worst * 1e6);
  EXPECT_LT(worst, 2e-5);
  EXPECT_THROW(pose(g, 0.5, 0.0, eo), InputError);  // outside the table
  eo.max_touching_contact_angle_rad = 1.0;          // not the table's touching rule
  EXPECT_THROW(pose(g, 0.0, 0.0, eo), InputError);
}

// Polach's closed form as the table's creep force (LutEvaluationOptions): the same normal solution; the creep forces
// within Polach's documented distance from FASTSIM (docs/physics-reference.md §7.3: 0.15 mu N without spin, 0.25 mu N
// up to a moderate normalised spin; a tread's spin is small); the total-force balance still carries the load; no
// creepage gives no force; a slip-dependent friction law is refused.
TEST(ContactLut, PolachCreepForceIsCloseToFastsimAndCarriesTheLoad) {
  const ContactLut& lut = HertzLut();
  LutEvaluationOptions polach;
  polach.creep_force = LutCreepForce::Polach;
  const WheelContactOptions o = Options(ContactModel::Hertz, LoadBalance::Total);
  int compared = 0;
  for (double y_mm : {-3.0, -1.0, 0.5, 2.0, 4.0}) {
    for (Side side : {Side::Left, Side::Right}) {
      const double Q = 55e3;
      WheelContactOptions oq = o;
      oq.vertical_load_N = Q;
      const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(y_mm * 1e-3, 1e-3);
      const WheelContactReport f = EvaluateContactLut(lut, Geometry(), side, eq.pose, Velocity(), oq);
      const WheelContactReport p = EvaluateContactLut(lut, Geometry(), side, eq.pose, Velocity(), oq, nullptr, polach);
      ASSERT_EQ(p.status, WheelContactStatus::Ok);
      EXPECT_NEAR(p.vertical_force_N, Q, 1e-5 * Q);
      ASSERT_EQ(p.patches.size(), f.patches.size());
      for (size_t j = 0; j < p.patches.size(); ++j) {
        const PatchReport &a = f.patches[j], &b = p.patches[j];
        const double muN = o.friction_coefficient * b.fn_N;
        EXPECT_NEAR(b.fx_N, a.fx_N, 0.25 * muN) << "y " << y_mm;
        EXPECT_NEAR(b.fy_N, a.fy_N, 0.25 * muN) << "y " << y_mm;
        EXPECT_LE(std::hypot(b.fx_N, b.fy_N), muN * (1.0 + 1e-9));
        EXPECT_GE(b.frictional_power_W, 0.0);
        ++compared;
      }
    }
  }
  EXPECT_GE(compared, 10);
  // rolling without creepage: no creep force
  WheelContactOptions free = o;
  free.vertical_load_N = 50e3;
  free.creepages_given = true;
  free.creepages = Creepages{0.0, 0.0, 0.0};
  const EquilibriumResult eq = Geometry().SolveRigidEquilibrium(0.0, 0.0);
  const WheelContactReport z = EvaluateContactLut(lut, Geometry(), Side::Left, eq.pose, Velocity(), free, nullptr, polach);
  ASSERT_EQ(z.status, WheelContactStatus::Ok);
  for (const PatchReport& p : z.patches) {
    EXPECT_EQ(p.fx_N, 0.0);
    EXPECT_EQ(p.fy_N, 0.0);
  }
  WheelContactOptions law = o;
  law.vertical_load_N = 50e3;
  law.friction_law = FrictionLaw::F1a(0.3, 0.4, 0.5);
  EXPECT_THROW(EvaluateContactLut(lut, Geometry(), Side::Left, eq.pose, Velocity(), law, nullptr, polach), InputError);
  EXPECT_EQ(ParseLutCreepForce("polach"), LutCreepForce::Polach);
  EXPECT_THROW(ParseLutCreepForce("kalker"), InputError);
}

// A query on the face of an emerging-patch cell where only zero-weight corners have the patch (t = 0 exactly): the
// patch is not there, and nothing is NaN (it was: its geometry averaged over a zero weight).
TEST(ContactLut, EmergingPatchOnACellFaceIsAbsentNotNaN) {
  const ContactLut& lut = HertzLut();
  const ContactLutGrid& g = lut.grid;
  const std::vector<LutNode>& nodes = lut.nodes[side_index(Side::Left)];
  int checked = 0;
  for (size_t iy = 0; iy + 1 < g.lateral_m.size(); ++iy)
    for (size_t ip = 0; ip + 1 < g.yaw_rad.size(); ++ip) {
      const size_t n0 = nodes[g.index(iy, ip, 0)].patches.size(), n1 = nodes[g.index(iy + 1, ip, 0)].patches.size();
      if (n0 >= n1) continue;  // the patch emerges towards iy + 1: query exactly on the iy face
      const double psi = g.yaw_rad[ip], Q = g.load_N[0];
      LutCellInfo info;
      const WheelContactReport r = FromLut(lut, Side::Left, g.lateral_m[iy], psi, Q,
                                           Options(ContactModel::Hertz, LoadBalance::Pressure), &info);
      if (r.status != WheelContactStatus::Ok) continue;
      ++checked;
      EXPECT_EQ(r.patches.size(), n0) << "y " << g.lateral_m[iy];
      for (const PatchReport& p : r.patches) {
        EXPECT_TRUE(std::isfinite(p.y_contact_rail_m) && std::isfinite(p.contact_angle_rad) && std::isfinite(p.fx_N) &&
                    std::isfinite(p.fy_N));
        EXPECT_GT(p.fn_N, 0.0);
      }
    }
  std::printf("emerging-patch cells queried on their face: %d\n", checked);
  EXPECT_GE(checked, 2);
}

// `conforma lut check` (CheckContactLut): every random pose is recorded; the records' categories add up to the
// result's counts, their largest single-topology errors are the percentiles' maxima (the same pose named), and the
// tread errors stay within issue 16's 1 % (forces) and 0.1 mm; the CSV has one row per pose.
TEST(ContactLut, CheckRecordsEveryPoseConsistentlyWithItsSummary) {
  ContactLutCheckOptions o;
  o.samples = 40;
  o.seed = 3;
  o.threads = 2;
  o.contact = Options(ContactModel::Hertz);
  const ContactLutCheckResult r = CheckContactLut(HertzLut(), Geometry(), o);
  ASSERT_EQ(r.sample_records.size(), 40u);
  int single = 0, jumps = 0, status = 0, both = 0;
  double fx_max = -1.0, fn_max = -1.0;
  const ContactLutCheckSample* worst_fx = nullptr;
  for (const ContactLutCheckSample& s : r.sample_records) {
    const std::string c = s.category;
    if (c == "single") {
      ++single;
      EXPECT_TRUE(std::isfinite(s.fx_rel) && std::isfinite(s.fn_rel) && std::isfinite(s.rail_y_m));
      if (s.fx_rel > fx_max) fx_max = s.fx_rel, worst_fx = &s;
      fn_max = std::max(fn_max, s.fn_rel);
      EXPECT_GT(s.direct_fn_N, 0.0);
    } else {
      EXPECT_TRUE(std::isnan(s.fx_rel)) << c;
    }
    jumps += c == "jump_same" || c == "jump_corner" || c == "jump_outside";
    status += c == "status_mismatch";
    both += c == "both_failed";
  }
  EXPECT_EQ(single, r.single_topology - r.single_topology_mismatch);
  EXPECT_EQ(jumps, r.jump_samples);
  EXPECT_EQ(status, r.status_mismatch);
  EXPECT_EQ(both, r.both_failed);
  ASSERT_GT(single, 20);
  ASSERT_NE(worst_fx, nullptr);
  EXPECT_EQ(fx_max, r.fx_rel.max);
  EXPECT_EQ(fn_max, r.normal_force_rel.max);
  EXPECT_EQ(worst_fx->y_m, r.fx_rel.worst_y_m);
  EXPECT_EQ(worst_fx->yaw_rad, r.fx_rel.worst_yaw_rad);
  EXPECT_LT(r.normal_force_rel.p50, 0.01);
  EXPECT_LT(r.fx_rel.p50, 0.01);
  EXPECT_LT(r.rail_y_m.p50, 0.1e-3);
  std::ostringstream csv;
  WriteContactLutCheckSamplesCsv(csv, r);
  const std::string text = csv.str();
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 41);
  EXPECT_EQ(text.find("nan"), std::string::npos);
}
