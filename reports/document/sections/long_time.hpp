// What the long-time section (long_time.cpp) shares with the hand-in's long run (long_run.cpp).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/studies/defaults.hpp"
#include "analysis/studies/long_time.hpp"
#include "reports/document/section.hpp"

namespace steplab {

// Its runs as data files lt_<scene>_<method>.dat: t in periods, each invariant's largest relative
// error up to t, the position error where the scene has an exact solution.
void write_long_time_data(const LongTimeResult& r, const DataDir& dat);
// The figure's sentence of what to see: at the first steps a period, the run that ends with the
// largest energy error and the one with the least, each an extreme claim of `section` (its data
// folder too) where `l` is given.
std::string extremes_sentence(const LongTimeResult& r, Ledger* l = nullptr, const std::string& section = "");
// The energy error from which the report calls an orbit (or a swing) lost (energy_verdict).
inline constexpr double kLostAt = 0.1;
// The runs by their energy error (energy_verdict at kLostAt): bounded, drifting, unclear, lost; the highest order that drifts and the lowest that stays bounded;
// whether every bounded one is symplectic and every drifting one not (by_structure), and whether
// the orders overlap across the two sides as well (not_by_order).
struct LongTimeSides {
  std::vector<std::size_t> bounded, drifting, unclear, lost;
  std::optional<std::size_t> high_drift, low_bounded;
  bool by_structure = false, not_by_order = false;
};
LongTimeSides sides(const LongTimeResult& r);
// Which runs' energy errors are bounded and which drift, and whether the structure or the order
// decides it: one paragraph computed from the runs.
// Where the symplectic ones are the bounded ones, whatever the order: that symmetry alone is not
// told apart from symplecticity here (said once, after the answers).
std::string symmetry_note(const LongTimeResult& r);
// Its claims go to `l` (where set) as `id`.bounded, .drifting, .lost and .symplectic.
class Ledger;
std::string structure_answer(const LongTimeResult& r, Ledger* l = nullptr, const std::string& id = "", const std::string& section = "");

}  // namespace steplab
