// C API: one wheelset pose (both wheels) per call, as a multibody code calls it each time step. Target
// (issue 7): <= 100 us median for the conformal model. Load control (10 kN per wheel) and given approach.
// CPU column: the whole process's CPU time (MeasureProcessCPUTime: both threads of the _parallel cases, which set
// parallel_wheels = 1, the wheels on two OpenMP threads); Time column: the wall time.
#include <benchmark/benchmark.h>

#include "capi_bench_pose.hpp"
#include "conforma_c.h"

namespace {

void BM_CApiWheelset(benchmark::State& state, const char* model_name, int mode, double lateral_m, int kp_strips = 31,
                     int fastsim_elements = 30, double load_tolerance = 0.0, int parallel_wheels = 0) {
  conforma_track_params track;
  conforma_contact_params contact;
  conforma_default_track_params(&track);
  conforma_default_contact_params(&contact);
  contact.model = model_name;
  contact.kp_strips = kp_strips;
  contact.fastsim_elements = fastsim_elements;
  conforma_model* model = nullptr;
  char error[CONFORMA_ERROR_TEXT];
  if (conforma_model_create(&track, &contact, &model, error, sizeof error) != CONFORMA_OK) {
    state.SkipWithError(error);
    return;
  }
  conforma_wheelset_state s = conforma_bench::CApiBenchState(lateral_m);
  conforma_evaluation_options o;
  conforma_default_evaluation_options(&o);
  if (load_tolerance > 0.0) o.load_tolerance = load_tolerance;  // else the default (1e-6)
  o.parallel_wheels = parallel_wheels;
  // the pose a multibody code would pass: rigid contact, then (approach mode) 50 um below it
  conforma_bench::SetRigidPose(model, o, mode == CONFORMA_GIVEN_APPROACH ? 50e-6 : 0.0, &s);
  conforma_wheelset_result r;
  o.normal_mode = mode;
  for (auto _ : state) {
    const int status = conforma_evaluate(model, &s, &o, &r);
    if (status != CONFORMA_OK) {
      state.SkipWithError(r.error_message);
      break;
    }
    benchmark::ClobberMemory();
  }
  state.counters["patches_left"] = r.wheel[0].patches_found;
  state.counters["Fz_left_N"] = r.wheel[0].force_track_N[2];
  state.counters["load_evaluations"] = r.wheel[0].load_iterations + r.wheel[1].load_iterations;
  conforma_model_destroy(model);
}

BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_load_y3mm, "conformal", CONFORMA_LOAD_CONTROL, 3e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_load_y7mm_flange, "conformal", CONFORMA_LOAD_CONTROL, 7e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
// load tolerance 1e-4 (the accuracy asks |F_z - load| <= 1e-3 load): fewer load-control evaluations
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_load_y3mm_tol1e-4, "conformal", CONFORMA_LOAD_CONTROL, 3e-3, 31, 30, 1e-4)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_load_y7mm_flange_tol1e-4, "conformal", CONFORMA_LOAD_CONTROL, 7e-3, 31, 30,
                  1e-4)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_approach_y3mm, "conformal", CONFORMA_GIVEN_APPROACH, 3e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_approach_y7mm_flange, "conformal", CONFORMA_GIVEN_APPROACH, 7e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
// coarser discretisation (the C API's contact params): strips across the contact / FASTSIM elements per strip
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_approach_y3mm_strips15_el15, "conformal", CONFORMA_GIVEN_APPROACH, 3e-3,
                  15, 15)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_approach_y7mm_strips15_el15, "conformal", CONFORMA_GIVEN_APPROACH, 7e-3,
                  15, 15)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_approach_y3mm_strips11_el11, "conformal", CONFORMA_GIVEN_APPROACH, 3e-3,
                  11, 11)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_load_y3mm_parallel, "conformal", CONFORMA_LOAD_CONTROL, 3e-3, 31, 30, 0.0, 1)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, conformal_load_y7mm_flange_parallel, "conformal", CONFORMA_LOAD_CONTROL, 7e-3, 31,
                  30, 0.0, 1)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, hertz_load_y3mm, "hertz", CONFORMA_LOAD_CONTROL, 3e-3)
    ->Unit(benchmark::kMicrosecond)
    ->MeasureProcessCPUTime();
// auto: per patch from its undeformed geometry (Hertz on a flat tread patch, KP where it is conformal, §9.2)
BENCHMARK_CAPTURE(BM_CApiWheelset, auto_load_y3mm, "auto", CONFORMA_LOAD_CONTROL, 3e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();
BENCHMARK_CAPTURE(BM_CApiWheelset, auto_load_y7mm_flange, "auto", CONFORMA_LOAD_CONTROL, 7e-3)
    ->Unit(benchmark::kMicrosecond)->MeasureProcessCPUTime();

}  // namespace
