#include "analysis/regions.hpp"

#include <array>
#include <span>
#include <string_view>

#include <Eigen/Eigenvalues>

#include "analysis/parallel.hpp"
#include "analysis/stability.hpp"
#include "analysis/step_map.hpp"
#include "core/methods.hpp"

namespace steplab {
namespace {

// u'' = -k u - c u' with m = 1, for any real k and c (negative ones make a growing test mode).
struct LinearTest {
  static constexpr int dim = 1;
  static constexpr std::string_view name = "linear_test";
  static constexpr std::array<ParamSpec, 2> params{{{"k", 1.0, Bound::Any, "stiffness"}, {"c", 0.0, Bound::Any, "damping"}}};
  double k, c;
  explicit LinearTest(std::span<const double> p) : k(p[0]), c(p[1]) {}
  Vec<1> mass() const { return Vec<1>::Ones(); }
  Vec<1> inverse_mass() const { return Vec<1>::Ones(); }
  Vec<1> force(const Vec<1>& x, const Vec<1>& v) const { return Vec<1>::Constant(-k * x[0] - c * v[0]); }
  Jacobians<1> jacobians(const Vec<1>&, const Vec<1>&) const { return {Mat<1>::Constant(-k), Mat<1>::Constant(-c)}; }
  bool velocity_dependent() const { return c != 0; }
  double energy(const Vec<1>& x, const Vec<1>& v) const { return 0.5 * (v[0] * v[0] + k * x[0] * x[0]); }
  State<1> initial() const { return {Vec<1>::Ones(), Vec<1>::Zero()}; }
};
static_assert(Scene<LinearTest>);

}  // namespace

double region_rho(std::size_t method, double re, double im) {
  const std::array<double, 2> p{re * re + im * im, -2 * re};
  const LinearTest s(p);
  return with_method(method, [&]<class M>() -> double {
    if constexpr (M::info.exact_flow) {
      return 0.0;
    } else {
      constexpr int n = map_size<M>();
      Eigen::MatrixXd m(n, n);
      for (int j = 0; j < n; ++j) m.col(j) = step_flat<M>(s, Eigen::VectorXd::Unit(n, j), 1.0);  // linear: M e_j
      return spectral_radius(m);
    }
  });
}

RegionResult stability_regions(const RegionConfig& c) {
  RegionResult out;
  out.config = c;
  for (int i = 0; i < c.re_points; ++i) out.re.push_back(c.re_min + (c.re_max - c.re_min) * i / (c.re_points - 1));
  for (int j = 0; j < c.im_points; ++j) out.im.push_back(c.im_max * j / (c.im_points - 1));
  for (std::size_t m : c.methods)
    if (has_stability_function(method_infos[m])) out.regions.push_back({m, {}});
  const std::size_t nr = out.re.size(), ni = out.im.size();
  for (StabilityRegion& r : out.regions) r.rho.assign(ni, std::vector<double>(nr));
  // one task per (method, im) row
  parallel_for(out.regions.size() * ni, c.threads, [&](std::size_t task) {
    StabilityRegion& r = out.regions[task / ni];
    const std::size_t j = task % ni;
    for (std::size_t i = 0; i < nr; ++i) r.rho[j][i] = region_rho(r.method, out.re[i], out.im[j]);
  });
  return out;
}

bool left_half_plane_stable(const RegionResult& r, const StabilityRegion& region) {
  for (std::size_t j = 0; j < r.im.size(); ++j)
    for (std::size_t i = 0; i < r.re.size(); ++i)
      if (r.re[i] <= 0 && !(region.rho[j][i] <= 1 + kRegionTolerance)) return false;
  return true;
}

}  // namespace steplab
