// The order-reduction theory from a method's tableau, and the sweep marked against it
// (analysis/studies/order_reduction.hpp has the derivation).
#include "analysis/studies/order_reduction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <tuple>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "analysis/kernel/kernel.hpp"
#include "analysis/studies/mode_stability.hpp"

namespace steplab {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The two eigenvalue moduli of a mode, omega (zeta -+ sqrt(zeta^2 - 1)) when overdamped, else omega twice.
std::pair<double, double> moduli(const Mode& m) {
  const double zeta = m.two_zeta / 2;
  if (zeta <= 1) return {m.omega, m.omega};
  const double r = std::sqrt(zeta * zeta - 1);
  return {m.omega * (zeta - r), m.omega * (zeta + r)};
}

// Stable as h |lambda| grows without bound on the negative real axis: the step map's spectral
// radius at h = 1 on u'' = -k u - c u' with k = 1e12 and zeta = 2 (h lambda = -2.7e5 and -3.7e6),
// measured on the method's own step (analysis/kernel/step_map.hpp).
bool stable_at_infinity(const MethodKernel& m) {
  const double k = 1e12, c = 4 * std::sqrt(k);
  const Eigen::MatrixXd step = m.test_matrix(k, c);
  if (!step.allFinite()) return false;
  return step.eigenvalues().cwiseAbs().maxCoeff() <= 1 + 1e-6;
}

StiffTheory runge_kutta_theory(const MethodKernel& mk, StiffTheory t) {
  const auto s = static_cast<Eigen::Index>(mk.butcher_b.size());
  const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> A(mk.butcher_a.data(), s, s);
  const Eigen::Map<const Eigen::VectorXd> b(mk.butcher_b.data(), s);
  const Eigen::VectorXd c = A.rowwise().sum(), ones = Eigen::VectorXd::Ones(s);
  const Eigen::RowVectorXd bAinv = A.transpose().partialPivLu().solve(b).transpose();  // b^T A^-1
  t.r_infinity = 1 - bAinv.dot(ones);
  // stage order q: c^k = k A c^(k-1) for every k <= q (to round-off)
  t.stage_order = 0;
  for (int k = 1; k <= t.classical; ++k) {
    const Eigen::VectorXd defect = c.array().pow(k).matrix() - k * A * c.array().pow(k - 1).matrix();
    if (defect.cwiseAbs().maxCoeff() > 1e-12) break;
    t.stage_order = k;
  }
  const int q = t.stage_order;
  t.stiffly_accurate = (b.transpose() - A.row(s - 1)).cwiseAbs().maxCoeff() < 1e-14;
  const double r = t.r_infinity;
  if (t.stiffly_accurate) {
    t.stiff = q;
    t.rule = "stiffly accurate: e = O(h^q / lambda), order q";
  } else if (std::abs(r) < 1 - 1e-12 || std::abs(r + 1) < 1e-12) {
    t.stiff = q + 1;
    t.rule = std::abs(r + 1) < 1e-12 ? "R(inf) = -1: the stage errors alternate, order q + 1" : "|R(inf)| < 1: order q + 1";
  } else {
    t.stiff = q;
    // 1 - R(z) = -z b^T (I - z A)^-1 1 -> b^T A^-2 1 / z when b^T A^-1 1 = 0: the damping a step
    t.long_run = std::abs(bAinv * A.partialPivLu().solve(ones));
    t.rule = "R(inf) = 1: the stage errors add up over t / h steps, order q (once h^2 |lambda| >= C t)";
  }
  t.stiff = std::min(t.stiff, t.classical);
  return t;
}

bool within(const OrderFit& f, double theory, double tol) { return f.fitted && std::abs(f.order - theory) <= tol; }

// `drift`: how far the order may still be from its limit (below), added to the fit's bound.
LimitCheck check(const OrderFit& f, double theory, double tol, bool reached, double drift = 0) {
  LimitCheck c;
  c.reached = reached;
  c.fitted = f.fitted;
  if (!f.fitted) return c;
  c.order = f.order, c.bound_lo = f.bound_lo - drift, c.bound_hi = f.bound_hi + drift;
  c.holds = reached && std::abs(f.order - theory) <= tol && c.bound_lo <= theory && theory <= c.bound_hi;
  return c;
}

}  // namespace

StiffTheory stiff_theory(std::size_t method) {
  const MethodKernel& mk = method_kernel(method);
  StiffTheory t;
  t.classical = mk.info.order;
  if (mk.info.exact_flow) {
    t.stiff = 0, t.rule = "the exact flow";
    return t;
  }
  if (!stable_at_infinity(mk)) {
    t.rule = "unstable once h |lambda| passes its stability interval: no stiff limit";
    return t;
  }
  if (!mk.butcher_b.empty()) return runge_kutta_theory(mk, t);
  if (!mk.starter.empty()) {  // a multistep method stable there: the BDF
    const std::optional<std::size_t> starter = find_method(mk.starter);
    const StiffTheory start = starter ? stiff_theory(*starter) : StiffTheory{};
    if (start.stiff < 0 || start.stage_order < 0) {
      t.rule = "multistep, started by a method without a stiff theory: none here";
      return t;
    }
    if (start.stiffly_accurate) {
      t.stiff = std::min(t.classical, start.stage_order);
      t.rule = fmt::format("multistep: its error O(h^p / lambda), its start's (`{}`) O(h^q / lambda): order min(p, q)", mk.starter);
    } else {
      t.stiff = start.stage_order + 1;
      t.rule = fmt::format("multistep: its own error O(h^p / lambda) vanishes; its start's (`{}`) local error "
                           "O(h^(q+1)) = O(h^{}) stays: order {} in the largest error", mk.starter, t.stiff, t.stiff);
    }
    return t;
  }
  t.rule = "stable, but declares no Butcher tableau: no theory here";
  return t;
}

ConvergenceConfig stiff_order_config(std::size_t scene, std::vector<double> params, const StiffOrderDefaults& d,
                                     std::vector<std::size_t> methods) {
  ConvergenceConfig c;
  c.scene = scene;
  c.params = std::move(params);
  c.methods = std::move(methods);
  c.t_end = d.t_end;
  c.dt_max = d.dt_max, c.dt_min = d.dt_min;
  c.points = d.points;
  c.fit_error = ErrorKind::Max;  // over the whole run: the largest error, wherever it builds up
  return c;
}

OrderReduction order_reduction(const ConvergenceConfig& config, const std::vector<double>& stiffnesses) {
  const SceneKernel& s = scene_kernel(config.scene);
  if (s.stiffness_param < 0 || !s.modes) throw std::invalid_argument("order_reduction: the scene declares no stiffness or no modes");
  return order_reduction(convergence_sweep(config, static_cast<std::size_t>(s.stiffness_param), stiffnesses));
}

OrderReduction order_reduction(ConvergenceSweep sweep) {
  OrderReduction out;
  const ConvergenceConfig& base = sweep.studies.front().config;
  const SceneKernel& scene = scene_kernel(base.scene);
  out.driven = scene.driven;
  const std::size_t nv = sweep.studies.size();
  // per value: the stiffest mode's eigenvalue moduli (|lambda| and the largest, the non-stiff
  // limit's test) and the modes themselves (each method's dt* on them)
  std::vector<double> fastest(nv, 0);
  std::vector<std::vector<Mode>> modes(nv);
  out.rates.assign(nv, 0);
  if (scene.modes)
    for (std::size_t v = 0; v < nv; ++v) {
      modes[v] = scene.modes(sweep.studies[v].config.params);
      if (!modes[v].empty()) std::tie(out.rates[v], fastest[v]) = moduli(modes[v].back());
    }
  for (std::size_t m = 0; m < base.methods.size(); ++m) {
    MethodReduction mr;
    mr.method = base.methods[m];
    mr.theory = stiff_theory(mr.method);
    const auto fit = [&](std::size_t v) -> const OrderFit& { return sweep.studies[v].fits[m].fit; };
    for (std::size_t v = 0; v < nv; ++v) {
      const OrderFit& f = fit(v);
      // the geometric mean of the window's ends in h |lambda|
      mr.h_lambda.push_back(f.fitted ? std::sqrt((f.dt_lo * out.rates[v]) * (f.dt_hi * out.rates[v])) : kNaN);
      const double dt_star = scene.modes && !method_info(mr.method).exact_flow ? modes_predicted_threshold(mr.method, modes[v])
                                                                                : std::numeric_limits<double>::infinity();
      mr.dt_star.push_back(dt_star);
      mr.past_stable.push_back(f.fitted && f.dt_hi > dt_star);
    }
    const OrderFit& first = fit(0);
    mr.non_stiff = check(first, mr.theory.classical, kNonStiffTolerance, first.fitted && first.dt_hi * fastest.front() <= kNonStiffRegime);
    if (mr.theory.stiff >= 0 && out.driven) {
      // in the stiff regime: h |lambda| >= kStiffRegime over the whole window, and for R(inf) = 1
      // the run long enough for the errors to add up undamped
      const auto stiff_regime = [&](std::size_t v) {
        const OrderFit& f = fit(v);
        bool in = f.fitted && f.dt_lo * out.rates[v] >= kStiffRegime;
        if (mr.theory.long_run > 0) in = in && f.dt_lo * f.dt_lo * out.rates[v] >= mr.theory.long_run * base.t_end;
        return in;
      };
      // The stiff limit is lambda -> infinity; at the last value the terms O(1 / (h lambda)) are
      // still there (BDF2 at stiffness 1e10 and 1e12: 3.014, 3.002, each bound excluding 3), and
      // the fit's bound, which models the next term in h, not in 1 / (h lambda), misses them. They
      // shrink as the stiffness grows, so the change from the value before (if it is in the
      // stiff regime too) bounds what is left.
      const std::size_t prev = nv >= 2 ? nv - 2 : 0;
      const double drift = nv >= 2 && stiff_regime(prev) ? std::abs(fit(nv - 1).order - fit(prev).order) : 0;
      mr.stiff = check(fit(nv - 1), mr.theory.stiff, kStiffTolerance, stiff_regime(nv - 1), drift);
    }
    // the transition, read from the values in order: the order kept from the first value on, and
    // the stiff limit's from the last value back
    mr.keeps_to = mr.reduced_from = kNaN;
    for (std::size_t v = 0; v < nv && within(fit(v), mr.theory.classical, kNonStiffTolerance); ++v) mr.keeps_to = mr.h_lambda[v];
    if (out.driven && mr.theory.stiff >= 0 && mr.theory.stiff != mr.theory.classical)
      for (std::size_t v = nv; v-- > 0 && within(fit(v), mr.theory.stiff, kStiffTolerance);) mr.reduced_from = mr.h_lambda[v];
    out.methods.push_back(std::move(mr));
  }
  out.sweep = std::move(sweep);
  return out;
}

}  // namespace steplab
