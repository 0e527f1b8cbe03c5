// How a generated translation unit fills the kernel table (analysis/kernel/kernel.hpp): make_pair<M, S>
// instantiates the run loop and everything the studies need of method M on scene S, once;
// make_method<M> and make_scene<S> what needs only one of them. Included by the generated
// files alone (tools/kernels.cmake), never by a study.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string_view>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/invariants_run.hpp"
#include "analysis/kernel/step_map.hpp"
#include "analysis/kernel/timing.hpp"
#include "core/batch.hpp"
#include "core/dopri5.hpp"
#include "core/simulate.hpp"
#include "core/springs.hpp"
#include "core/stepper.hpp"

namespace steplab {

// Whether method M can run on scene S: the exact flow needs a scene that has one, an implicit
// method the scene's Jacobians, and so does a method with an implicit stage (velocity Verlet's
// damped kick) on a scene of run-time size (a fixed-size one differences its force: core/scene.hpp),
// a method on the springs a scene made of them (core/springs.hpp).
template <class M, class S> constexpr bool applies() {
  if constexpr (M::info.exact_flow) return HasExact<S>;
  else if constexpr (M::info.on_springs) return MassSpring<S>;
  else if constexpr (M::info.implicit || (solve_stages<M>() > 0 && S::dim == Eigen::Dynamic)) return HasJacobians<S>;
  else return true;
}

// A scene that counts what a method asks of it, and each Newton iteration with its factorisations
// and linear solves (count_iteration, core/method.hpp); otherwise the scene itself.
template <Scene S> struct Counted : S {
  explicit Counted(std::span<const double> p) : S(p) {}
  mutable long long forces = 0, jacobian_calls = 0, newton = 0, factorisations = 0, solves = 0;
  void counted_iteration(const SolveCounts& did) const { ++newton, factorisations += did.factorisations, solves += did.solves; }
  // Each form the scene has (core/scene.hpp), counted; a reference where the scene gives one.
  using Ref = Eigen::Ref<const Eigen::VectorXd>;
  Vec<S::dim> force(const Vec<S::dim>& x, const Vec<S::dim>& v) const requires ForceByValue<S> {
    ++forces;
    return S::force(x, v);
  }
  void force(Ref x, Ref v, Eigen::Ref<Eigen::VectorXd> f) const requires ForceInto<S> {
    ++forces;
    S::force(x, v, f);
  }
  void acceleration(Ref x, Ref v, Eigen::Ref<Eigen::VectorXd> a) const requires AccelerationInto<S> {
    ++forces;
    S::acceleration(x, v, a);
  }
  decltype(auto) jacobians(const Vec<S::dim>& x, const Vec<S::dim>& v) const
    requires(!Driven<S> && requires(const S& s) { s.jacobians(x, v); }) {
    ++jacobian_calls;
    return S::jacobians(x, v);
  }
  void jacobians(Ref x, Ref v, Jacobians<S::dim>& j) const requires(!Driven<S> && JacobiansInto<S>) {
    ++jacobian_calls;
    S::jacobians(x, v, j);
  }
  Vec<S::dim> force(double t, const Vec<S::dim>& x, const Vec<S::dim>& v) const requires DrivenByValue<S> {
    ++forces;
    return S::force(t, x, v);
  }
  void force(double t, Ref x, Ref v, Eigen::Ref<Eigen::VectorXd> f) const requires DrivenInto<S> {
    ++forces;
    S::force(t, x, v, f);
  }
  decltype(auto) jacobians(double t, const Vec<S::dim>& x, const Vec<S::dim>& v) const
    requires(Driven<S> && requires(const S& s) { s.jacobians(t, x, v); }) {
    ++jacobian_calls;
    return S::jacobians(t, x, v);
  }
  void jacobians(double t, Ref x, Ref v, Jacobians<S::dim>& j) const requires(Driven<S> && JacobiansInto<S>) {
    ++jacobian_calls;
    S::jacobians(t, x, v, j);
  }
};

// u'' = -k u - c u' with m = 1, for any real k and c (negative ones make a growing test mode):
// the test equation of the stability regions (analysis/studies/regions.hpp). Also a mass-spring
// scene (core/springs.hpp), for the methods on springs: one spring of stiffness k and dashpot c
// to a fixed point, rest length 0.
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
  int links() const { return 1; }
  Link link(int) const { return {0, -1, 0.0, k, c}; }
  double external(int, double) const { return 0.0; }
};

// The per-step record of an observed run (Observed in analysis/kernel/kernel.hpp). A bounce: the mass
// leaves the ground; the rebound height is known once the flight turns down (its apex); a
// flight cut off by t_end, or by the next contact before the apex, leaves it NaN.
template <Scene S> struct Observer {
  const S& s;
  Observed& o;
  double e0, flight_max = 0;
  bool was_in_contact = false;
  void operator()(long long, double t, const State<S::dim>& y) {
    o.max_abs_x = std::max(o.max_abs_x, y.x.cwiseAbs().maxCoeff());
    if constexpr (HasContact<S>) {
      const double p = s.penetration(y.x);
      const bool in_contact = p > 0;  // level - y > 0 exactly when y < level (Ground::touching)
      o.max_penetration = std::max(o.max_penetration, p);
      if constexpr (S::dim == 1) {
        std::vector<BounceEvent>& b = o.bounces;
        if (was_in_contact && !in_contact && b.size() < o.max_bounces) {
          b.push_back({t, s.energy(y.x, y.v) / e0, std::numeric_limits<double>::quiet_NaN()});
          flight_max = y.x[0];
        }
        if (!in_contact && !b.empty() && std::isnan(b.back().rebound_height)) {
          flight_max = std::max(flight_max, y.x[0]);
          if (y.v[0] <= 0) b.back().rebound_height = flight_max;
        }
      }
      was_in_contact = in_contact;
    }
  }
};

template <class M, Scene S> struct PairCode {
  static AnyResult run(Params p, const RunSpec& spec) { return to_any(simulate<M>(S(p), spec)); }

  static AnyResult run_counted(Params p, const RunSpec& spec, Counts& n) {
    const Counted<S> s(p);
    AnyResult r = to_any(simulate<M>(s, spec));
    n = {.steps = r.steps, .forces = s.forces, .jacobians = s.jacobian_calls, .factorisations = s.factorisations,
         .solves = s.solves, .newton = s.newton};
    return r;
  }

  static AnyResult run_observed(Params p, const RunSpec& spec, Observed& o) {
    const S s(p);
    o.bounces.clear();
    o.bounces.reserve(o.max_bounces);  // before the loop: the observer never allocates
    const State<S::dim> y0 = s.initial();
    return to_any(simulate<M>(s, spec, Observer<S>{s, o, s.energy(y0.x, y0.v)}));
  }

  static std::vector<double> timings(Params p, const RunSpec& spec, std::size_t repeats, double seconds) {
    const S s(p);
    return repeated_timings(
        [&] {
          const RunResult<S::dim> r = simulate<M>(s, spec);
          asm volatile("" : : "r"(r.steps) : "memory");  // the run is used: not optimised away
        },
        repeats, seconds);
  }

  static void time_steps(Params p, double h, long long n, int restart) {
    const S s(p);
    State<S::dim> y = s.initial();
    Stepper<M, S> stepper;
    int k = 0;
    for (long long i = 0; i < n; ++i) {
      stepper.step(s, y, k * h, h);
      asm volatile("" : "+m"(y) : : "memory");  // Google Benchmark's DoNotOptimize, for GCC and Clang
      if (++k == restart) k = 0, y = s.initial(), stepper.forget();
    }
  }

  static Eigen::VectorXd step_flat(Params p, const Eigen::VectorXd& z, double h) {
    return steplab::step_flat<M>(S(p), z, h);
  }

  static Eigen::VectorXd at_rest_flat(Params p, double x, double v) {
    return steplab::at_rest_flat<M>(S(p), State<1>{Vec<1>::Constant(x), Vec<1>::Constant(v)});
  }

  static StepStatus exact_step(Params p, double t0, double h, AnyState& out) {
    const S s(p);
    State<1> y = exact(s, t0);
    Stepper<M, S> stepper;  // a multistep method remembers the exact past: y(t0 - k h)
    if constexpr (Multistep<M>) stepper.memory = M::remember(s, [&](int k) { return exact(s, t0 - k * h); }, t0, h);
    const StepStatus st = stepper.step(s, y, t0, h);
    out = {y.x, y.v};
    return st;
  }

  static StepStatus steps_from(Params p, double x, double v, double h, int n, double* xs, double* vs) {
    const S s(p);
    State<1> y{Vec<1>::Constant(x), Vec<1>::Constant(v)};
    Stepper<M, S> stepper;
    StepStatus first = StepStatus::Ok;
    for (int i = 0; i < n; ++i) {
      const StepStatus st = stepper.step(s, y, i * h, h);
      if (first == StepStatus::Ok) first = st;
      xs[i] = y.x[0], vs[i] = y.v[0];
    }
    return first;
  }
};

// The batched runs (core/batch.hpp), the loop compiled once per instruction set, each with
// the pack of its register width, and flattened (everything it calls inlined, so compiled for
// that instruction set, but for the noipa bookkeeping of a lane). The target names instruction
// sets, not an arch=: GCC inlines no function into one whose arch differs. Not flattened in the
// sanitized build (STEPLAB_NO_FLATTEN, CMakeLists.txt), which compiles at -O1: what is not
// inlined there runs at the plain x86-64 width, with the same bits (a pack is passed by
// reference: core/pack.hpp).
#if defined(STEPLAB_NO_FLATTEN)
#define STEPLAB_FLATTEN
#else
#define STEPLAB_FLATTEN gnu::flatten
#endif
template <class M, Scene S> struct BatchCode {
  template <int W> [[gnu::always_inline]] static inline void body(std::span<const BatchRun> runs, AnyResult* out) {
    BatchRunner<M, S, Pack<W>> batch(runs, out);
    batch.run();
  }
  [[STEPLAB_FLATTEN]] static void sse2(std::span<const BatchRun> runs, AnyResult* out) { body<2>(runs, out); }
#if defined(__x86_64__) && defined(__GNUC__)
  [[gnu::target("avx2,fma"), STEPLAB_FLATTEN]] static void avx2(std::span<const BatchRun> runs, AnyResult* out) {
    body<4>(runs, out);
  }
  [[gnu::target("avx512f,avx512dq,avx512vl,avx512bw,avx2,fma"), STEPLAB_FLATTEN]] static void avx512(
      std::span<const BatchRun> runs, AnyResult* out) {
    body<8>(runs, out);
  }
#endif
  static void run_batch(std::span<const BatchRun> runs, AnyResult* out, int width) {
#if defined(__x86_64__) && defined(__GNUC__)
    // A loop wider than kMaxPackWidth (core/batch.hpp) is not named, so not instantiated.
    if constexpr (kMaxPackWidth >= 4)
      if (width == 4) return avx2(runs, out);
    if constexpr (kMaxPackWidth >= 8)
      if (width == 8) return avx512(runs, out);
#endif
    sse2(runs, out);
  }
};
#undef STEPLAB_FLATTEN

// The counting run only where a study counts (the work-precision study on scenes with an exact
// solution, the scaling study on scenes of run-time size), the observed run only where the
// studies observe (the fixed-size scenes with ground contact; a 1-D scene's amplitude): each is
// one more instantiation of the run loop.
template <class M, Scene S> constexpr PairKernel make_pair() {
  using C = PairCode<M, S>;
  PairKernel k{.run = &C::run, .timings = &C::timings, .time_steps = &C::time_steps};
  if constexpr (PackedStep<M, S>) k.run_batch = &BatchCode<M, S>::run_batch;
  if constexpr (HasExact<S> || S::dim == Eigen::Dynamic) k.run_counted = &C::run_counted;
  if constexpr ((HasContact<S> && S::dim != Eigen::Dynamic) || S::dim == 1) k.run_observed = &C::run_observed;
  if constexpr (HasInvariants<S>) k.invariants_run = &invariants_run<M, S>;
  if constexpr (S::dim == 1) {
    k.step_flat = &C::step_flat;
    k.at_rest_flat = &C::at_rest_flat;
    k.steps_from = &C::steps_from;
    if constexpr (HasExact<S>) k.exact_step = &C::exact_step;
  }
  return k;
}

// M's kernel on S; where M does not apply to S (the exact flow on a scene without one), one
// whose entries are all null.
template <class M, class S> constexpr PairKernel pair_or_none() {
  if constexpr (applies<M, S>()) return make_pair<M, S>();
  else return PairKernel{};
}

template <class M> struct MethodCode {
  static Eigen::MatrixXd test_matrix(double k, double c) {
    constexpr int n = map_size<M>();
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    if constexpr (!M::info.exact_flow) {
      const std::array<double, 2> p{k, c};
      const LinearTest s(p);
      for (int j = 0; j < n; ++j) m.col(j) = steplab::step_flat<M>(s, Eigen::VectorXd::Unit(n, j), 1.0);  // linear: M e_j
    }
    return m;
  }
};

// A method's Butcher A, row by row, in one array the table can point to.
template <class M> struct FlatTableau {
  static constexpr std::size_t s = M::tableau.b.size();
  static constexpr std::array<double, s * s> a = [] {
    std::array<double, s * s> out{};
    for (std::size_t i = 0; i < s; ++i)
      for (std::size_t j = 0; j < s; ++j) out[i * s + j] = M::tableau.a[i][j];
    return out;
  }();
};

template <class M> constexpr MethodKernel make_method() {
  MethodKernel k{.info = M::info, .map_size = map_size<M>(), .test_matrix = &MethodCode<M>::test_matrix};
  if constexpr (requires { M::tableau.b; }) {
    k.butcher_a = FlatTableau<M>::a;
    k.butcher_b = M::tableau.b;
  }
  if constexpr (requires { typename M::Starter; }) k.starter = M::Starter::info.name;
  return k;
}

template <Scene S> struct SceneCode {
  static AnyState initial(Params p) {
    const State<S::dim> y = S(p).initial();
    return {y.x, y.v};
  }
  static AnyState exact_at(Params p, double t) {
    const State<S::dim> y = exact(S(p), t);
    return {y.x, y.v};
  }
  static double norm(const Eigen::VectorXd& x) { return Vec<S::dim>(x).norm(); }
  static AnyAdaptiveResult dopri5(Params p, const AdaptiveSpec& spec) {
    AdaptiveResult<S::dim> r = simulate_dopri5(S(p), spec);
    return {to_any(std::move(r.run)), r.stats};
  }
  static std::vector<double> dopri5_timings(Params p, const AdaptiveSpec& spec, std::size_t repeats, double seconds) {
    const S s(p);
    return repeated_timings(
        [&] {
          const AdaptiveResult<S::dim> r = simulate_dopri5(s, spec);
          asm volatile("" : : "r"(r.run.steps) : "memory");  // the run is used: not optimised away
        },
        repeats, seconds);
  }
};

template <MassSpring S> SpringMeasures spring_measures(Params p, std::span<const AnyState> states) {
  constexpr int d = coords_per_mass<S>();
  const S s(p);
  SpringMeasures out;
  out.springs = s.links();
  for (const AnyState& y : states) {
    const Vec<S::dim> x = y.x, v = y.v;
    double stretch = 0;
    for (int q = 0; q < s.links(); ++q)
      if (const Link l = s.link(q); l.rest > 0) stretch = std::max(stretch, link_at<d>(l, x).c / l.rest);
    out.stretch.push_back(stretch);
    out.energy.push_back(s.energy(x, v));
  }
  return out;
}

// A scene of run-time size as MadeSceneCode (analysis/kernel/kernel.hpp) reaches it.
template <Scene S> struct MadeCode {
  static const S& of(const void* s) { return *static_cast<const S*>(s); }
  static std::shared_ptr<const void> make(Params p) { return std::make_shared<const S>(p); }
  static Eigen::VectorXd force(const void* s, const Eigen::VectorXd& x, const Eigen::VectorXd& v) { return force_value(of(s), 0.0, x, v); }
  static Jacobians<Eigen::Dynamic> jacobians(const void* s, const Eigen::VectorXd& x, const Eigen::VectorXd& v) {
    if constexpr (HasJacobians<S>) return of(s).jacobians(x, v);
    else throw std::logic_error("jacobians: the scene declares none");  // peer_scenes keeps the CVODE peers off it
  }
  static const Eigen::VectorXd& inverse_mass(const void* s) { return of(s).inverse_mass(); }
  static State<Eigen::Dynamic> initial(const void* s) { return of(s).initial(); }
  static constexpr MadeSceneCode code{&force, &jacobians, &inverse_mass, &initial};
};

template <Scene S> constexpr SceneKernel make_scene() {
  using C = SceneCode<S>;
  SceneKernel k{.name = S::name,
                .title = scene_title<S>(),
                .old_name = scene_old_name<S>(),
                .equation = scene_equation<S>(),
                .params = std::span<const ParamSpec>(S::params),
                .dim = S::dim,
                .has_exact = HasExact<S>,
                .driven = Driven<S>,
                .has_jacobians = HasJacobians<S>,
                .size_param = size_param_index<S>(),
                .coords_per_mass = coords_per_mass<S>(),
                .jacobian_bandwidth = jacobian_bandwidth<S>(),
                .stiffness_param = stiffness_param_index<S>(),
                .damping_param = damping_param_index<S>(),
                .initial = &C::initial,
                .exact = nullptr,
                .norm = &C::norm,
                .dopri5 = &C::dopri5,
                .dopri5_timings = &C::dopri5_timings};
  if constexpr (HasExact<S>) k.exact = &C::exact_at;
  if constexpr (HasModes<S>) k.modes = [](Params p) { return S(p).modes(); };
  if constexpr (HasStiffLimit<S>) k.stiff_limit_scene = S::stiff_limit_scene, k.stiff_limit = [](Params p) { return S::stiff_limit(p); };
  if constexpr (S::dim == Eigen::Dynamic) k.make = &MadeCode<S>::make, k.made = &MadeCode<S>::code;
  if constexpr (MassSpring<S>) k.spring_measures = &spring_measures<S>;
  if constexpr (HasInvariants<S>) {
    k.invariant_names = S::invariant_names;
    k.period = [](Params p) { return S(p).period(); };
    k.extent = [](Params p) { return S(p).extent(); };
  }
  return k;
}

}  // namespace steplab
