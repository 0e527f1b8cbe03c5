// Local (one-step) errors, as the old framework's `-testcase error_measurement` printed them:
// from the exact state at t0, ONE step of each method for h = step, step/2, ... (count values);
// the velocity change v - v_start and the displacement p - p_start beside the exact ones; the
// local error (norm of the position and velocity errors after the step) and its observed order,
// which for a method of global order p is p + 1.
#pragma once

#include <vector>

#include "analysis/fits/order_fit.hpp"

namespace steplab {

struct LocalErrorConfig {
  std::vector<double> params;        // Spring parameters, table order
  std::vector<std::size_t> methods;
  double t0 = 0.1;
  double step = 0.003;
  int count = 10;
};

struct LocalErrorColumn {
  std::size_t method;
  std::vector<double> dv, dx, error;
  OrderFit order;
};

struct LocalErrorResult {
  LocalErrorConfig config;
  std::vector<double> steps;
  std::vector<double> exact_dv, exact_dx;
  std::vector<LocalErrorColumn> columns;
};

LocalErrorResult local_error_study(const LocalErrorConfig& config);

}  // namespace steplab
