// JSON documents and printed tables of the studies. Field names are an interface (README).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "analysis/convergence.hpp"

namespace steplab {

using Json = nlohmann::ordered_json;

Json scene_params_json(std::size_t scene, const std::vector<double>& values);

Json convergence_json(const ConvergenceResult& r);   // schema steplab.convergence/1
std::string convergence_table(const ConvergenceResult& r);

}  // namespace steplab

#include "analysis/local_error.hpp"

namespace steplab {
// The old framework's error_measurement tables, %.5e.
std::string local_error_tables(const LocalErrorResult& r);
}  // namespace steplab
