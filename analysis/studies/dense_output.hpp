// Dense-output study: the order of each fixed-step method's output between steps (core/
// dense_output.hpp) beside the order of its steps. Per method and step h of a geometric sweep,
// one run of the scene (default the sheet's spring) to t_end against its exact solution:
//   at the steps    the largest position error over the steps (RunResult::error_max)
//   between steps   the largest over `outputs` evenly spaced times t_k = k t_end / (outputs - 1),
//                   each interpolated inside its step (the count is prime, so the times fall at
//                   every fraction of a step as h shrinks, not on the steps)
// and each error's order fitted over the sweep as the convergence study fits one (analysis/
// fits/order_fit.hpp). The output's predicted order, min(p, 4) for the cubic Hermite taken
// below order 3 and min(p, 6) for the quintic from order 3 up, is the claim it checks.
#pragma once

#include <cstddef>
#include <vector>

#include "analysis/fits/order_fit.hpp"
#include "analysis/kernel/parallel.hpp"
#include "core/simulate.hpp"

namespace steplab {

struct DenseOutputConfig {
  std::size_t scene = 0;
  std::vector<double> params;        // table order
  std::vector<std::size_t> methods;
  double t_end = 10;
  double dt_max = 0.1, dt_min = 0.002;
  int points = 8;                    // steps in the sweep (geometric, t_end a whole number of each)
  int outputs = 98;                  // 97 intervals: a prime
  Workers workers;
};

struct DenseOutputRow {
  std::size_t method = 0;
  double dt = 0;
  long long steps = 0;
  RunStatus status = RunStatus::Ok;
  double error_steps = 0, error_outputs = 0;  // largest position error at the steps, at the outputs
  double floor = 0;                           // round-off's: errors below are not fitted
};

struct DenseOutputFit {
  std::size_t method = 0;
  int declared = 0;         // the method's order
  bool quintic = false;     // its output rule (core/dense_output.hpp)
  int predicted = 0;        // the output's order by theory
  OrderFit steps, outputs;  // fitted over the sweep
};

struct DenseOutputResult {
  DenseOutputConfig config;
  std::vector<DenseOutputRow> rows;  // method-major, dt decreasing
  std::vector<DenseOutputFit> fits;  // one per method
};

// The methods the study runs on `scene` by default: those of `from` in the ODE studies (not the
// exact flow, not the position-based ones) that apply to it.
std::vector<std::size_t> dense_output_methods(std::size_t scene, const std::vector<std::size_t>& from);
DenseOutputResult dense_output_study(const DenseOutputConfig& c);

}  // namespace steplab
