// The convergence bars every method is held to where its declared order should show (the
// spring, the non-stiff target): fitted, within `tol` of the declared order, the declared order
// inside the fit's bound. Call as ASSERT_NO_FATAL_FAILURE(expect_declared_order(f, tol)).
#pragma once

#include <gtest/gtest.h>

#include "analysis/studies/convergence.hpp"
#include "analysis/kernel/kernel.hpp"

namespace steplab {

inline void expect_declared_order(const ConvergenceFit& f, double tol) {
  const MethodInfo& info = method_info(f.method);
  ASSERT_TRUE(f.fit.fitted) << info.name << ": " << f.fit.note;
  EXPECT_NEAR(f.fit.order, info.order, tol) << info.name;
  EXPECT_LE(f.fit.bound_lo, info.order) << info.name;
  EXPECT_GE(f.fit.bound_hi, info.order) << info.name;
}

}  // namespace steplab
