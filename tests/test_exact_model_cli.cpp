// `conforma contact --model exact` as a user runs it: the BEM normal problem and Kalker's exact tangential theory on
// the Manchester tread and flange cases, their convergence in the JSON, the former model name, the fields export.
// test-links: app

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_run.hpp"

namespace {

using conforma::test::RunCli;
namespace fs = std::filesystem;

nlohmann::json Patch(const std::string& args) {
  const auto run = RunCli("contact --side left --json " + args);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json j = nlohmann::json::parse(run.out);
  EXPECT_EQ(j["wheels"][0]["status"], "ok");
  EXPECT_EQ(j["wheels"][0]["patches"].size(), 1u);
  return j["wheels"][0]["patches"][0];
}

// Tread (y = 0): partial slip; both solves converged and reported.
TEST(ExactModelCli, TreadCaseConvergesAndReportsIterations) {
  const nlohmann::json p = Patch("--model exact");
  EXPECT_EQ(p["model"], "exact");
  EXPECT_EQ(p["normal_status"], "ok");
  EXPECT_EQ(p["tangential_status"], "ok");
  EXPECT_GT(p["normal_iterations"].get<int>(), 0);
  EXPECT_LT(p["normal_residual"].get<double>(), 1e-6);
  EXPECT_GT(p["tangential_iterations"].get<int>(), 0);
  EXPECT_LT(p["tangential_residual"].get<double>(), 1e-5);
  EXPECT_GT(p["adhesion_area_m2"].get<double>(), 0.0);
  EXPECT_GT(p["slip_area_m2"].get<double>(), 0.0);
  // the Coulomb bound holds for the patch as a whole
  EXPECT_LT(std::hypot(p["fx_N"].get<double>(), p["fy_N"].get<double>()), 0.3 * p["fn_N"].get<double>());
  // the former name gives the same solution
  const nlohmann::json again = Patch("--model reference");
  EXPECT_EQ(again["model"], "exact");
  EXPECT_EQ(again["fx_N"], p["fx_N"]);
  EXPECT_EQ(again["fy_N"], p["fy_N"]);
}

// Flange (y = 7 mm, yaw 16.8 mrad): the creepage saturates the flange patch: full slip, |F| = mu Fn up to the curvature
// of the patch (the lateral traction follows the local tangent; fy is its t0 component).
TEST(ExactModelCli, FlangeCaseSaturates) {
  const nlohmann::json p = Patch("--model exact --y-mm 7 --yaw-mrad 16.8");
  EXPECT_EQ(p["tangential_status"], "full_slip");
  const double force = std::hypot(p["fx_N"].get<double>(), p["fy_N"].get<double>());
  EXPECT_NEAR(force, 0.3 * p["fn_N"].get<double>(), 0.01 * 0.3 * p["fn_N"].get<double>());
  EXPECT_EQ(p["adhesion_area_m2"].get<double>(), 0.0);
}

// The per-element fields of the exact solution: one row per loaded BEM element, forces integrate to the patch's.
TEST(ExactModelCli, FieldsExportIntegratesToThePatchForces) {
  const fs::path dir = fs::temp_directory_path() / ("conforma_exact_fields_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto run = RunCli("contact --side left --model exact --json --fields '" + dir.string() + "'");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json p = nlohmann::json::parse(run.out)["wheels"][0]["patches"][0];
  std::ifstream in(dir / "left_patch0.csv");
  ASSERT_TRUE(in.good());
  std::string line;
  std::getline(in, line);
  std::vector<std::string> header;
  {
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) header.push_back(cell);
  }
  auto column = [&](const std::string& name) {
    for (size_t k = 0; k < header.size(); ++k)
      if (header[k].rfind(name, 0) == 0) return k;
    ADD_FAILURE() << "no column " << name << " in " << line;
    return size_t{0};
  };
  const size_t area = column("area_m2"), tx = column("traction_x_Pa");
  double fx = 0.0;
  int rows = 0;
  while (std::getline(in, line)) {
    std::vector<double> v;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) v.push_back(std::atof(cell.c_str()));
    fx += v[tx] * v[area];
    ++rows;
  }
  EXPECT_GT(rows, 100);
  EXPECT_NEAR(fx, p["fx_N"].get<double>(), 1e-6 * p["fn_N"].get<double>());
  fs::remove_all(dir);
}

}  // namespace

namespace {

// A grid over the memory budget is an input error naming the grid, the budget and the flag that changes it.
TEST(ExactModelCli, GridOverTheBudgetIsAnInputError) {
  const auto run = conforma::test::RunCli("contact --side left --model exact --exact-element-mm 0.01");
  EXPECT_EQ(run.exit_code, 2) << run.err;
  EXPECT_NE(run.err.find("exceeds the memory budget"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--exact-element-mm"), std::string::npos) << run.err;
}

}  // namespace
