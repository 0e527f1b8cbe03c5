#include "analysis/studies/convergence.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "analysis/kernel/kernel.hpp"
#include "analysis/kernel/shard.hpp"

namespace steplab {

std::string_view to_string(ErrorKind k) {
  switch (k) {
    case ErrorKind::Final: return "final";
    case ErrorKind::Max: return "max";
    case ErrorKind::Rms: return "rms";
  }
  return "?";
}

std::vector<double> sweep_steps(double t_end, double dt_max, double dt_min, int points) {
  std::vector<double> dts;
  long long last_n = -1;
  for (int i = 0; i < points; ++i) {
    const double frac = points == 1 ? 0.0 : static_cast<double>(i) / (points - 1);
    const double nominal = dt_max * std::pow(dt_min / dt_max, frac);
    const long long n = std::max(1LL, std::llround(t_end / nominal));
    if (n == last_n) continue;
    last_n = n;
    dts.push_back(t_end / static_cast<double>(n));
  }
  return dts;
}

double roundoff_floor(double scale, long long steps) {
  return std::numeric_limits<double>::epsilon() * std::max(1.0, scale) * static_cast<double>(std::max(1LL, steps));
}

namespace {

constexpr double kReferenceMargin = 100;  // a fitted error stands this far above the reference's

RunSpec convergence_spec(double dt, double t_end, const ConvergenceResult& study) {
  RunSpec spec;
  spec.dt = dt;
  spec.steps = steps_for(t_end, dt);
  spec.errors = !study.uses_reference;
  spec.settings = study.config.settings;
  return spec;
}

// The size of the study's solution, max(|x(0)|, |x(t_end)|), x(t_end) exact or the reference's:
// the scale of its round-off floor and of its blow-up test.
double solution_scale(const ConvergenceResult& study) {
  const ConvergenceConfig& c = study.config;
  const SceneKernel& s = scene_kernel(c.scene);
  const double target_norm = study.uses_reference
                                 ? s.norm(Eigen::Map<const Eigen::VectorXd>(study.reference.x.data(), std::ssize(study.reference.x)))
                                 : s.norm(s.exact(c.params, c.t_end).x);
  return std::max(s.norm(s.initial(c.params).x), target_norm);
}

// The record of a run of `method` at dt: its errors against the exact solution or the
// reference, its round-off floor, and Diverged if it blew up (scale: solution_scale).
ConvergenceRecord record_of(std::size_t method, double dt, double t_end, const AnyResult& r, const ConvergenceResult& study,
                            double scale) {
  const SceneKernel& s = scene_kernel(study.config.scene);
  const long long steps = steps_for(t_end, dt);
  ConvergenceRecord rec{method,         dt,          steps,       r.status, r.failed_step, r.error_final,
                        r.error_v_final, r.error_max, r.error_rms, 0};
  if (study.uses_reference) {
    const Eigen::Map<const Eigen::VectorXd> x(study.reference.x.data(), std::ssize(study.reference.x)),
        v(study.reference.v.data(), std::ssize(study.reference.v));
    rec.error_final = s.norm(r.final.x - x);
    rec.error_v_final = s.norm(r.final.v - v);
    rec.error_max = rec.error_rms = std::numeric_limits<double>::quiet_NaN();  // known at t_end alone
  }
  rec.floor = roundoff_floor(scale, steps);
  const double largest = study.uses_reference ? rec.error_final : rec.error_max;
  if (rec.status == RunStatus::Ok && blown_up(largest, scale)) rec.status = RunStatus::Diverged;
  if (rec.status != RunStatus::Ok)
    rec.error_final = rec.error_v_final = rec.error_max = rec.error_rms = std::numeric_limits<double>::infinity();
  return rec;
}

}  // namespace

ReferenceSolution reference_solution(const SceneKernel& s, const std::vector<double>& params, double t_end, int frames) {
  ReferenceSolution ref;
  AdaptiveSpec spec;
  spec.t_end = t_end;
  spec.errors = false;
  spec.max_samples = frames > 0 ? frames + 1 : 0;  // dense output: the steps are the same
  spec.tol = {ref.rtol, ref.rtol};
  const AnyAdaptiveResult fine = s.dopri5(params, spec);
  spec.tol = {ref.check_rtol, ref.check_rtol};
  const AnyAdaptiveResult check = s.dopri5(params, spec);
  const auto complete = [&](const AnyAdaptiveResult& r) { return r.run.status == RunStatus::Ok && std::ssize(r.run.samples) == spec.max_samples; };
  if (!complete(fine) || !complete(check)) throw std::runtime_error("the reference solution (dopri5 at rtol 1e-13) did not reach t_end");
  ref.steps = fine.stats.accepted;
  ref.check_steps = check.stats.accepted;
  ref.estimated_error = s.norm(fine.run.final.x - check.run.final.x);
  ref.floor = kReferenceMargin * ref.estimated_error;
  ref.x.assign(fine.run.final.x.begin(), fine.run.final.x.end());
  ref.v.assign(fine.run.final.v.begin(), fine.run.final.v.end());
  for (std::size_t k = 0; k < fine.run.samples.size(); ++k) {
    ref.frames.push_back(fine.run.samples[k].x);
    ref.frames_error = std::max(ref.frames_error, (fine.run.samples[k].x - check.run.samples[k].x).cwiseAbs().maxCoeff());
  }
  return ref;
}

double error_of(const ConvergenceRecord& r, ErrorKind k) {
  switch (k) {
    case ErrorKind::Final: return r.error_final;
    case ErrorKind::Max: return r.error_max;
    case ErrorKind::Rms: return r.error_rms;
  }
  return r.error_final;
}

namespace {

// One run at a time (no other run competing for the core), the integration alone (what a user
// pays; the exact solution evaluated for the errors would dominate a cheap method's time),
// repeated until kTimingSeconds and 3 repetitions; the median is kept.
void time_runs(ConvergenceResult& out) {
  const ConvergenceConfig& c = out.config;
  for (ConvergenceRecord& rec : out.records) {
    if (!applies(rec.method, c.scene)) continue;
    RunSpec spec;  // the integration alone: no exact solution evaluated along the way
    spec.dt = rec.dt;
    spec.steps = rec.steps;
    spec.errors = false;
    spec.settings = c.settings;
    std::vector<double> times = pair_kernel(rec.method, c.scene).timings(c.params, spec, 3, kTimingSeconds);
    std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
    rec.seconds = times[times.size() / 2];
  }
}

}  // namespace

ConvergenceResult convergence_study(const ConvergenceConfig& config) {
  ConvergenceResult out;
  out.config = config;
  out.dts = sweep_steps(config.t_end, config.dt_max, config.dt_min, config.points);
  const std::size_t nd = out.dts.size(), nm = config.methods.size();
  out.records.resize(nm * nd);

  const SceneKernel& scene = scene_kernel(config.scene);
  out.uses_reference = config.reference || !scene.has_exact;
  if (out.uses_reference && config.fit_error != ErrorKind::Final)
    throw std::invalid_argument("a reference solution gives the final error only");
  if (out.uses_reference) out.reference = reference_solution(scene, config.params, config.t_end);
  const double scale = solution_scale(out);
  // a task per method: its dt sweep, the smallest dt (the longest run) first; a method that does
  // not apply to the scene leaves its records empty
  const auto sweeps = study_map<std::vector<ConvergenceRecord>>(nm, config.workers, [&](std::size_t m) {
    const std::size_t method = config.methods[m];
    std::vector<ConvergenceRecord> sweep(nd);
    if (!applies(method, config.scene)) return sweep;
    std::vector<BatchRun> runs;  // the smallest dt (the longest run) first: a pack's lanes then end together
    for (std::size_t i = nd; i-- > 0;) runs.push_back({config.params, convergence_spec(out.dts[i], config.t_end, out)});
    const std::vector<AnyResult> results = run_all(pair_kernel(method, config.scene), runs, config.pack_width);
    for (std::size_t i = 0; i < nd; ++i) sweep[i] = record_of(method, out.dts[i], config.t_end, results[nd - 1 - i], out, scale);
    return sweep;
  }, implicit_first(config.methods));
  for (std::size_t m = 0; m < nm; ++m)
    std::copy(sweeps[m].begin(), sweeps[m].end(), out.records.begin() + static_cast<std::ptrdiff_t>(m * nd));

  if (config.timing) time_runs(out);

  for (std::size_t m = 0; m < nm; ++m) {
    std::vector<ErrorPoint> pts;
    for (std::size_t i = 0; i < nd; ++i) {
      const ConvergenceRecord& r = out.records[m * nd + i];
      const double floor = out.uses_reference ? std::max(r.floor, out.reference.floor) : r.floor;
      pts.push_back({r.dt, error_of(r, config.fit_error), floor, r.status != RunStatus::Ok});
    }
    out.fits.push_back({config.methods[m], fit_order(pts)});
  }
  return out;
}

ConvergenceSweep convergence_sweep(const ConvergenceConfig& config, std::size_t param, const std::vector<double>& values) {
  ConvergenceSweep out{param, values, {}};
  for (double value : values) {
    ConvergenceConfig c = config;
    c.params[param] = value;
    out.studies.push_back(convergence_study(c));
  }
  return out;
}

}  // namespace steplab
