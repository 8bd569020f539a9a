// C API with a contact look-up table of the conformal (and hertz) model (conforma_model_create_with_lut): the same
// wheelset poses and load control as bench_capi.cpp's conformal_load_* cases, read from a table instead of solved
// (issue 15 item 6 asks <= 100 us for the solve; the table is the fast path of issue 16, docs/physics-reference.md
// §17). The table (S1002 / 60E1 1:40, y 1 ... 9 mm by 0.25 mm, yaw 0 ... 2 mrad, Q 5 ... 15 kN, both wheels) is
// built once per process into a temporary file (a few s on 2 cores), outside the timing. Counters: the table's wheel
// forces against the direct solve of the same pose (Fz, Fy of the left wheel, N), so the speed is read with its
// error; the _polach cases take the table's creep forces from Polach's closed form (table_creep_force = 1).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

#include <unistd.h>

#include "conforma/contact_lut.hpp"
#include "conforma/contact_lut_io.hpp"
#include "conforma/standard_profiles.hpp"
#include "capi_bench_pose.hpp"
#include "conforma_c.h"

namespace {

// The table of `model` (conforma::ContactModel::Conformal or Hertz), built once per process.
std::string TableFile(conforma::ContactModel model) {
  static std::map<conforma::ContactModel, std::string> files;  // (the benchmarks run one after another)
  std::string& path = files[model];
  if (path.empty()) {
    const conforma::WheelsetTrackGeometry g(conforma::MakeSymmetricTrack(
        conforma::MakeS1002(), conforma::MakeRail(conforma::RailSection::R60E1, 0.0),
        conforma::rail_inclination_1in40()));
    conforma::ContactLutBuildOptions b;
    for (int k = 0; k <= 32; ++k) b.grid.lateral_m.push_back(1e-3 + 0.25e-3 * k);
    b.grid.yaw_rad = {0.0, 1e-3, 2e-3};
    b.grid.load_N = {5e3, 10e3, 15e3};
    b.contact.model = model;
    path = (std::filesystem::temp_directory_path() / ("conforma_bench_capi_lut_" + std::to_string(getpid()) + "_" +
                                                      conforma::to_string(model) + ".h5")).string();
    conforma::SaveContactLut(conforma::BuildContactLut(g, b), path);
    static const struct Remove {  // the files go with the process
      ~Remove() {
        for (const auto& f : files) std::filesystem::remove(f.second);
      }
    } remove;
  }
  return path;
}

void BM_CApiWheelsetLut(benchmark::State& state, const char* model_name, conforma::ContactModel model,
                        double lateral_m, int table_creep_force = 0) {
  conforma_track_params track;
  conforma_contact_params contact;
  conforma_default_track_params(&track);
  conforma_default_contact_params(&contact);
  contact.model = model_name;
  conforma_model *table = nullptr, *direct = nullptr;
  char error[CONFORMA_ERROR_TEXT];
  const std::string file = TableFile(model);
  if (conforma_model_create_with_lut(&track, &contact, file.c_str(), &table, error, sizeof error) != CONFORMA_OK ||
      conforma_model_create(&track, &contact, &direct, error, sizeof error) != CONFORMA_OK) {
    state.SkipWithError(error);
    conforma_model_destroy(table);
    return;
  }
  conforma_wheelset_state s = conforma_bench::CApiBenchState(lateral_m);
  conforma_evaluation_options o;
  conforma_default_evaluation_options(&o);  // load control, 10 kN per wheel
  o.table_creep_force = table_creep_force;   // 0: FASTSIM (as the solve), 1: Polach
  // the pose a multibody code would pass (as bench_capi.cpp); the table takes its own vertical position and roll
  conforma_bench::SetRigidPose(direct, o, 0.0, &s);
  conforma_wheelset_result r, exact;
  for (auto _ : state) {
    if (conforma_evaluate(table, &s, &o, &r) != CONFORMA_OK) {
      state.SkipWithError(r.error_message);
      break;
    }
    benchmark::ClobberMemory();
  }
  if (conforma_evaluate(direct, &s, &o, &exact) == CONFORMA_OK) {  // (the direct solve: FASTSIM)
    state.counters["dFz_left_N"] = r.wheel[0].force_track_N[2] - exact.wheel[0].force_track_N[2];
    state.counters["dFy_left_N"] = r.wheel[0].force_track_N[1] - exact.wheel[0].force_track_N[1];
    state.counters["Fy_left_N"] = exact.wheel[0].force_track_N[1];
  }
  state.counters["patches_left"] = r.wheel[0].patches_found;
  state.counters["table_reads"] = r.wheel[0].load_iterations + r.wheel[1].load_iterations;  // both wheels
  conforma_model_destroy(table);
  conforma_model_destroy(direct);
}

BENCHMARK_CAPTURE(BM_CApiWheelsetLut, conformal_table_load_y3mm, "conformal", conforma::ContactModel::Conformal, 3e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelsetLut, conformal_table_load_y7mm_flange, "conformal", conforma::ContactModel::Conformal,
                  7e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelsetLut, conformal_table_polach_load_y3mm, "conformal", conforma::ContactModel::Conformal,
                  3e-3, 1)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelsetLut, conformal_table_polach_load_y7mm_flange, "conformal",
                  conforma::ContactModel::Conformal, 7e-3, 1)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelsetLut, hertz_table_load_y3mm, "hertz", conforma::ContactModel::Hertz, 3e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();

}  // namespace
