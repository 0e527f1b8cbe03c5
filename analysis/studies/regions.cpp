#include "analysis/studies/regions.hpp"

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/parallel.hpp"
#include "analysis/studies/stability.hpp"

namespace steplab {
double region_rho(std::size_t method, double re, double im) {
  const MethodKernel& k = method_kernel(method);
  if (k.info.exact_flow) return 0.0;
  return spectral_radius(k.test_matrix(re * re + im * im, -2 * re));  // the linear test equation's step map
}

RegionResult stability_regions(const RegionConfig& c) {
  RegionResult out;
  out.config = c;
  for (int i = 0; i < c.re_points; ++i) out.re.push_back(c.re_min + (c.re_max - c.re_min) * i / (c.re_points - 1));
  for (int j = 0; j < c.im_points; ++j) out.im.push_back(c.im_max * j / (c.im_points - 1));
  for (std::size_t m : c.methods)
    if (has_stability_function(method_info(m))) out.regions.push_back({m, {}});
  const std::size_t nr = out.re.size(), ni = out.im.size();
  for (StabilityRegion& r : out.regions) r.rho.assign(ni, std::vector<double>(nr));
  // one task per (method, im) row
  parallel_for(out.regions.size() * ni, c.workers, [&](std::size_t task) {
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
