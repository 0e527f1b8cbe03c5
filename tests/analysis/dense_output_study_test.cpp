// The dense-output study (analysis/studies/dense_output.hpp) on the sheet's spring: each method's
// output between steps converges at the order theory gives it, min(p, 4) for the cubic Hermite and
// min(p, 6) for the quintic (core/dense_output.hpp), which is the step's own order p for every
// method here; and the study's rows are what a run with those outputs measures.
#include <gtest/gtest.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/dense_output.hpp"
#include "reports/data/inputs.hpp"

namespace steplab {
namespace {

TEST(DenseOutputStudy, OutputOrderIsTheStepOrderOnTheSpring) {
  DenseOutputConfig c;
  c.scene = *find_scene("spring");
  c.params = default_param_values(c.scene);
  for (const char* m : {"explicit_euler", "symplectic_euler", "velocity_verlet", "rk3", "rk4", "radau_iia5", "bdf2", "gauss_legendre4"})
    c.methods.push_back(*find_method(m));
  const DenseOutputResult r = dense_output_study(c);
  ASSERT_EQ(r.fits.size(), c.methods.size());
  for (const DenseOutputFit& f : r.fits) {
    SCOPED_TRACE(std::string(method_info(f.method).name));
    EXPECT_EQ(f.predicted, f.declared);
    ASSERT_TRUE(f.steps.fitted) << f.steps.note;
    ASSERT_TRUE(f.outputs.fitted) << f.outputs.note;
    // within 0.15 of theory: the fitted step orders' own spread on this sweep (the convergence
    // study's bounds are of that size at 8 points)
    EXPECT_NEAR(f.outputs.order, f.predicted, 0.15);
    EXPECT_NEAR(f.steps.order, f.declared, 0.15);
  }
}

}  // namespace
}  // namespace steplab
