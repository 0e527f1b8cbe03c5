// The text of `steplab check`: what a method's row claims against what was measured.
#pragma once

#include <string>
#include <vector>

#include "analysis/studies/check.hpp"

namespace steplab {

struct ClaimLine {
  bool holds;
  std::string text;  // the claim and its figures
};

// One line per claim, in a fixed order: order and convergence on each scene, energy, A-stability,
// dt* at each damping, rest at equilibrium. A claim holds exactly when its CheckResult part does.
std::vector<ClaimLine> check_lines(const CheckResult& r);

// A heading naming the row's claims, "PASS  ..." or "FAIL  ..." per claim, and a count.
std::string check_text(const CheckResult& r);

}  // namespace steplab
