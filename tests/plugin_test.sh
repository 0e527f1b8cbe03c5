#!/usr/bin/env bash
# The README's walk-through "check your own integrator", from an empty folder: install steplab
# into a temporary prefix, write a method (Heun's), the same method declared one order too high,
# and docs/scenes.md's scene without an exact solution (a damped pendulum, named arm) into a new project, build it with
# steplab_add_executable(), and ask the tool about them:
#   mysteplab check --method heun            exit 0 (every claim holds)
#   mysteplab check --method heun_claims_3   exit 1 (the order claim fails, and the symplectic one
#                                            on Kepler's orbit: its energy drifts)
#   mysteplab check --method heun_frozen_time  exit 1 (its order on the driven target fails alone)
#   mysteplab study convergence --scene arm --methods heun,rk4
#                                            against the reference solution (no exact one):
#                                            fitted orders 2 and 4 within 0.1
#   mysteplab study stability --methods heun,rk4 --lanes 1 and --lanes 2
#                                            the same JSON (Heun is written over the scalar,
#                                            so the spring's runs step two at a time)
#   mysteplab report --methods heun,explicit_euler,explicit_midpoint,rk4 --sections ...
#                                            its own report: those methods, the full report's numbers
#   mysteplab report --scenes arm ...        a report on the user's scene: its convergence, the
#                                            sections it cannot feed left out with one line each
# and a scene of run-time size (beads on a string, exact modes) that run and the studies of
# convergence, stability and scaling take by what it declares; and docs/scenes.md's worked
# examples (the Duffing oscillator, no Jacobians; the arm, with its invariant), their commands
# printing what the page shows.
# Usage: plugin_test.sh BUILD_DIR [extra cmake arguments for the project]
set -euo pipefail
build=$1
shift
docs=$(cd "$(dirname "$0")/.." && pwd)/docs/scenes.md  # its worked example of a scene
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake --install "$build" --prefix "$tmp/prefix" >/dev/null
mkdir "$tmp/mine"
cd "$tmp/mine"

cat > heun.hpp <<'EOF'
#pragma once
#include <steplab/core/method.hpp>

// Heun's method (the explicit trapezoidal rule): a predictor step of explicit Euler, then the
// average of the slopes at both ends.
//   y* = y_n + h f(y_n),   y_{n+1} = y_n + h/2 (f(y_n) + f(y*))
struct Heun {
  static constexpr steplab::MethodInfo info{.name = "heun", .order = 2, .family = steplab::Family::ExplicitRungeKutta,
                                            .summary = "Heun's method: explicit trapezoidal rule"};
  // Over the scalar T: one run (double), or a pack of runs where the scene has packs (the spring).
  template <class S, class T>
  static steplab::StepStatus step(const S& s, steplab::State<S::dim, T>& y, steplab::Time<T> t, steplab::Time<T> h) {
    using V = steplab::Vec<S::dim, T>;
    const V kx1 = y.v, kv1 = steplab::acceleration(s, t, y.x, y.v);
    const V xp = y.x + h * kx1, vp = y.v + h * kv1;
    const V kx2 = vp, kv2 = steplab::acceleration(s, t + h, xp, vp);
    y.x += (h / 2) * (kx1 + kx2);
    y.v += (h / 2) * (kv1 + kv2);
    return steplab::StepStatus::Ok;
  }
};

STEPLAB_METHOD(Heun);
EOF

cat > heun_claims_3.hpp <<'EOF'
#pragma once
#include "heun.hpp"

// The same step, declared third order and symplectic: `check` must say no to both.
struct HeunClaims3 : Heun {
  static constexpr steplab::MethodInfo info{.name = "heun_claims_3", .order = 3, .family = steplab::Family::ExplicitRungeKutta,
                                            .symplectic = true, .summary = "Heun's method declared one order too high, and symplectic"};
};

STEPLAB_METHOD(HeunClaims3);
EOF

cat > heun_frozen_time.hpp <<'EOF'
#pragma once
#include "heun.hpp"

// A classic slip: the corrector's slope taken at the step's start time, not at t + h. Invisible
// on every autonomous scene; on a driven one (the target) it is first order.
struct HeunFrozenTime {
  static constexpr steplab::MethodInfo info{.name = "heun_frozen_time", .order = 2, .family = steplab::Family::ExplicitRungeKutta,
                                            .summary = "Heun's method with its corrector at the wrong time"};
  template <class S, class T>
  static steplab::StepStatus step(const S& s, steplab::State<S::dim, T>& y, steplab::Time<T> t, steplab::Time<T> h) {
    using V = steplab::Vec<S::dim, T>;
    const V kv1 = steplab::acceleration(s, t, y.x, y.v);
    const V xp = y.x + h * y.v, vp = y.v + h * kv1;
    const V kv2 = steplab::acceleration(s, t, xp, vp);  // should be t + h
    y.x += (h / 2) * (y.v + vp);
    y.v += (h / 2) * (kv1 + kv2);
    return steplab::StepStatus::Ok;
  }
};

STEPLAB_METHOD(HeunFrozenTime);
EOF

cat > beads.hpp <<'EOF'
#pragma once
#include <array>
#include <cmath>
#include <numbers>
#include <span>
#include <string_view>
#include <vector>

#include <steplab/core/scene.hpp>
#include <steplab/core/scenes/oscillator.hpp>

// N beads on a taut string between two fixed walls, transverse displacements u_i (u_0 = u_{N+1}
// = 0), a refinement of one string: total mass M (m = M/N each), k = K (N + 1) between
// neighbours, damping gamma (c = gamma/N on each bead, mass-proportional):
//   m u_i'' = k (u_{i-1} - 2 u_i + u_{i+1}) - c u_i'
// Its modes: phi_j(i) = sin(i j pi / (N+1)), lambda_j = 4 sin^2(j pi / (2 (N+1))),
// omega_j^2 = k lambda_j / m, each a damped oscillator; the exact flow projects on them
// (sum_i phi_j(i) phi_l(i) = (N+1)/2 delta_jl), O(N^2).
struct Beads {
  static constexpr int dim = Eigen::Dynamic;
  static constexpr std::string_view name = "beads";
  static constexpr std::string_view title = "String of N beads";
  static constexpr std::string_view size_param = "beads";
  static constexpr std::string_view stiffness_param = "stiffness";
  static constexpr std::string_view damping_param = "damping";
  static constexpr int jacobian_bandwidth = 1;
  static constexpr std::array<steplab::ParamSpec, 4> params{{
      {"beads", 8, steplab::Bound::Positive, "number of beads N (a whole number, 1 to 10000)", true, 1e4},
      {"mass", 1.0, steplab::Bound::Positive, "total mass M"},
      {"stiffness", 1.0, steplab::Bound::Positive, "string stiffness K (K (N+1) between neighbours)"},
      {"damping", 0.05, steplab::Bound::NonNegative, "damping gamma shared by the beads"},
  }};
  int n;
  double m, k, c;
  Eigen::VectorXd m_all, inv_all;
  steplab::Jacobians<Eigen::Dynamic> jac;
  explicit Beads(std::span<const double> p)
      : n(static_cast<int>(p[0])), m(p[1] / n), k(p[2] * (n + 1)), c(p[3] / n), m_all(Eigen::VectorXd::Constant(n, m)),
        inv_all(Eigen::VectorXd::Constant(n, 1 / m)), jac{steplab::SparseMat(n, n), steplab::SparseMat(n, n)} {
    std::vector<Eigen::Triplet<double>> tx, tv;
    for (int i = 0; i < n; ++i) {
      tx.emplace_back(i, i, -2 * k), tv.emplace_back(i, i, -c);
      if (i + 1 < n) tx.emplace_back(i, i + 1, k), tx.emplace_back(i + 1, i, k);
    }
    jac.dx.setFromTriplets(tx.begin(), tx.end());
    jac.dv.setFromTriplets(tv.begin(), tv.end());
  }
  double phi(int j, int i) const { return std::sin(i * j * std::numbers::pi / (n + 1)); }  // bead i = 1 .. N
  double lambda(int j) const {
    const double s = std::sin(j * std::numbers::pi / (2 * (n + 1)));
    return 4 * s * s;
  }
  double omega(int j) const { return std::sqrt(k * lambda(j) / m); }
  std::vector<steplab::Mode> modes() const {
    std::vector<steplab::Mode> out;
    for (int j = 1; j <= n; ++j) out.push_back({omega(j), c / (m * omega(j))});
    return out;
  }
  const Eigen::VectorXd& mass() const { return m_all; }
  const Eigen::VectorXd& inverse_mass() const { return inv_all; }
  Eigen::VectorXd force(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    Eigen::VectorXd f(n);
    for (int i = 0; i < n; ++i) f[i] = k * ((i > 0 ? x[i - 1] : 0.0) - 2 * x[i] + (i + 1 < n ? x[i + 1] : 0.0)) - c * v[i];
    return f;
  }
  const steplab::Jacobians<Eigen::Dynamic>& jacobians(const Eigen::VectorXd&, const Eigen::VectorXd&) const { return jac; }
  bool velocity_dependent() const { return c != 0; }
  double energy(const Eigen::VectorXd& x, const Eigen::VectorXd& v) const {
    double e = 0.5 * m * v.squaredNorm();
    for (int i = 0; i <= n; ++i) {
      const double d = (i < n ? x[i] : 0.0) - (i > 0 ? x[i - 1] : 0.0);
      e += 0.5 * k * d * d;
    }
    return e;
  }
  // Plucked in its first two modes, at rest.
  steplab::State<Eigen::Dynamic> initial() const {
    Eigen::VectorXd x(n);
    for (int i = 1; i <= n; ++i) x[i - 1] = 0.1 * phi(1, i) + 0.05 * phi(2, i);
    return {x, Eigen::VectorXd::Zero(n)};
  }
  steplab::State<Eigen::Dynamic> flow(const steplab::State<Eigen::Dynamic>& y, double t) const {
    const double alpha = -c / (2 * m);
    steplab::State<Eigen::Dynamic> out{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
    for (int j = 1; j <= n; ++j) {
      double q = 0, p = 0;
      for (int i = 1; i <= n; ++i) q += y.x[i - 1] * phi(j, i), p += y.v[i - 1] * phi(j, i);
      const double w = omega(j);
      const auto [u, du] = steplab::damped_oscillation(2 * q / (n + 1), 2 * p / (n + 1), alpha, w * w - alpha * alpha, t);
      for (int i = 1; i <= n; ++i) out.x[i - 1] += u * phi(j, i), out.v[i - 1] += du * phi(j, i);
    }
    return out;
  }
};

STEPLAB_SCENE(Beads);
EOF

# docs/scenes.md's worked examples, as the page prints them: a scene without Jacobians (Duffing's)
# and a damped pendulum with its invariant, period and extent (named arm: steplab has a pendulum
# of its own).
python3 - "$docs" <<'EOF'
import re, sys
page = open(sys.argv[1]).read()
section = page[page.index("## A scene of your own"):]
duffing, arm = re.findall(r"```cpp\n(.*?)```", section, flags=re.S)[:2]
open("duffing.hpp", "w").write(duffing)
open("arm.hpp", "w").write(arm)
EOF

cat > CMakeLists.txt <<'EOF'
cmake_minimum_required(VERSION 3.22)
project(mine LANGUAGES CXX)
find_package(steplab 0.2 REQUIRED)
steplab_add_executable(mysteplab METHODS heun.hpp heun_claims_3.hpp heun_frozen_time.hpp SCENES arm.hpp beads.hpp duffing.hpp)
EOF

cmake -S . -B build -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j 2 >/dev/null
tool=build/mysteplab

"$tool" check --method heun
status=0
"$tool" check --method heun_claims_3 > claims3.txt || status=$?
[[ $status -eq 1 ]] || { echo "check --method heun_claims_3 exited $status, not 1"; exit 1; }
grep -q "^FAIL  order 3 on the spring: fitted" claims3.txt || { cat claims3.txt; exit 1; }
grep -q "^FAIL  symplectic: on Kepler's orbit over 10000 periods" claims3.txt || { cat claims3.txt; exit 1; }
# the corrector at the wrong time: every claim holds but the order on the driven target
status=0
"$tool" check --method heun_frozen_time > frozen.txt || status=$?
[[ $status -eq 1 ]] || { echo "check --method heun_frozen_time exited $status, not 1"; exit 1; }
grep -q "^FAIL  order 2 on the target: fitted" frozen.txt || { cat frozen.txt; exit 1; }
[[ $(grep -c "^FAIL" frozen.txt) -eq 1 ]] || { cat frozen.txt; exit 1; }

"$tool" study convergence --scene arm --methods heun,rk4 --json conv.json >/dev/null
python3 - conv.json <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["scene"] == "arm", d["scene"]
assert d["reference"] is not None, "no reference solution"
want = {"heun": 2, "rk4": 4}
for f in d["fits"]:
    print(f"{f['method']}: fitted order {f['order']:.3f} against the reference (declared {want[f['method']]})")
    assert abs(f["order"] - want[f["method"]]) <= 0.1, f
EOF
# the new method in packs on the spring: the same bytes one run at a time and two (SSE2) at a time
"$tool" study stability --methods heun,rk4 --lanes 1 --json stability_1.json >/dev/null
"$tool" study stability --methods heun,rk4 --lanes 2 --json stability_2.json >/dev/null
cmp stability_1.json stability_2.json
# docs/scenes.md's commands on the Duffing scene print what the page shows; an implicit method on
# it (no Jacobians) is refused in one line naming them
python3 - "$docs" "$tool" <<'EOF'
import re, shlex, subprocess, sys
page, tool = open(sys.argv[1]).read(), sys.argv[2]
section = page[page.index("## A scene of your own"):]
# the page's fenced blocks without a language (a fence opens and closes a block in turn; a
# pattern over the text alone took a closing fence for an opening one and checked nothing)
blocks, fence = [], None
for line in section.split("\n"):
    if line.startswith("```"):
        if fence is None:
            fence = (line[3:].strip(), [])
        else:
            if not fence[0]:
                blocks.append("\n".join(fence[1]))
            fence = None
    elif fence is not None:
        fence[1].append(line)
commands = [l for b in blocks for l in b.split("\n") if l.startswith("$ build/mysteplab ")]
assert len(commands) == section.count("\n$ build/mysteplab "), "a command outside a plain fenced block"
assert len(commands) >= 5, commands  # Duffing's two, the arm's three
for block in blocks:
    for cmd_block in re.split(r"^(?=\$ )", block, flags=re.M):
        lines = [l for l in cmd_block.rstrip("\n").split("\n") if l]
        if not lines or not lines[0].startswith("$ build/mysteplab "):
            continue
        out = subprocess.run([tool] + shlex.split(lines[0])[2:], capture_output=True, text=True, check=True).stdout.split("\n")
        at = 0
        for want in lines[1:]:
            if want.endswith("..."):
                want = want[:-3]
                while at < len(out) and not out[at].startswith(want):
                    at += 1
            else:
                while at < len(out) and out[at] != want:
                    at += 1
            assert at < len(out), f"{lines[0]}: docs/scenes.md shows a line it does not print:\n{want}\n" + "\n".join(out)
            at += 1
        print(f"docs/scenes.md: {lines[0][2:]}: as printed")
r = subprocess.run([tool, "run", "--scene", "duffing", "--method", "implicit_euler"], capture_output=True, text=True)
assert r.returncode == 2 and len(r.stderr.splitlines()) == 1 and "jacobians" in r.stderr and not r.stdout, r
# the arm's long-time study at its default friction: refused in the one line the page quotes
r = subprocess.run([tool, "study", "long-time", "--scene", "arm"], capture_output=True, text=True)
quoted = "--friction 0.05 makes the arm's energy decay: it is then no invariant; accepted: 0 for the long-time study"
assert r.returncode == 2 and r.stderr.splitlines() == ["steplab: " + quoted] and quoted in " ".join(page.split()), r
EOF
# the new method on a built-in scene, the built-in ones on the new scene
"$tool" run --scene chain --method heun --dt 0.001 --t-end 1 >/dev/null
"$tool" run --scene arm --method radau_iia5 --dt 0.01 --t-end 1 >/dev/null
# A scene of run-time size none of the studies has seen (beads.hpp: its file and its name in
# steplab_add_executable) joins run, study convergence, study stability and study scaling by
# what it declares: its exact flow, its size parameter, its modes, its banded Jacobians.
"$tool" run --scene beads --beads 12 --method rk4 --dt 0.001 --t-end 1 --json run_beads.json >/dev/null
"$tool" study convergence --scene beads --methods rk4,implicit_midpoint --dt-max 0.02 --dt-min 0.001 --points 6 \
  --json conv_beads.json >/dev/null
"$tool" study stability --scene beads --beads 16 --methods rk4,symplectic_euler --json stab_beads.json >/dev/null
"$tool" study scaling --scene beads --sizes 8,16,32 --methods rk4,implicit_midpoint,cvode_adams_band --no-timing \
  --error 1e-4 --json scal_beads.json >/dev/null
python3 - run_beads.json conv_beads.json stab_beads.json scal_beads.json <<'EOF'
import json, math, sys
run, conv, stab, scal = (json.load(open(f)) for f in sys.argv[1:])
# rk4 at h = 0.001 with omega_max ~ 2 sqrt(k/m) = 2 sqrt(13 * 12) = 25: error ~ (omega h)^4 of the
# amplitude 0.1, 4e-8 at the fastest mode; 1e-6 leaves room for the constants
assert run["status"] == "ok" and run["error"]["final"] < 1e-6, run["error"]
# against the exact flow: rk4 and implicit midpoint at their orders 4 and 2 (within 0.15: a few
# steps per period of the fastest mode, at the edge of the asymptotic range)
want = {"rk4": 4, "implicit_midpoint": 2}
for f in conv["fits"]:
    print(f"beads: {f['method']} fitted order {f['order']:.3f} (declared {want[f['method']]})")
    assert abs(f["order"] - want[f["method"]]) <= 0.15, f
# dt* from its modes against runs of the whole string: within 1 %; omega_max against the closed
# form 2 sqrt(k/m) sin(N pi / (2 (N + 1))) with N = 16, k = 17, m = 1/16
n = 16
w = 2 * math.sqrt(17 * 16) * math.sin(n * math.pi / (2 * (n + 1)))
for t in stab["thresholds"]:
    assert abs(t["omega_max"] - w) < 1e-9 * w, (t["omega_max"], w)
    assert abs(t["dt_measured"] / t["dt_theory"] - 1) < 0.01, t
    print(f"beads: {t['method']} dt* predicted {t['dt_theory']:.6g}, measured {t['dt_measured']:.6g}")
# scaling: every size reached, each row at or below the target error; rk4's dt* times omega_max is
# RK4's 2 sqrt 2 on the imaginary axis (the fastest mode's damping ratio is below 1e-3 here: the
# constant moves by less than 0.3 %)
assert [r["beads"] for r in scal["rows"] if r["solver"] == "rk4"] == [8, 16, 32]
for r in scal["rows"]:
    assert r["error"] is not None and r["error"] <= 1e-4, r
    if r["solver"] == "rk4":
        n = r["beads"]
        wn = 2 * math.sqrt((n + 1) * n) * math.sin(n * math.pi / (2 * (n + 1)))
        assert abs(r["dt_stable"] * wn / (2 * math.sqrt(2)) - 1) < 0.003, r
print("beads: run, convergence, stability and scaling ok")
EOF
# ... and the report's "As the system grows" (in the atlas), which refines every scene of run-time
# size with modes: its paragraph, its exponents from its own study (data/scaling/scaling_beads.json).
cat > small.json <<'EOF'
{"convergence": {"points": 4, "dt_min": 0.01}, "work_precision": {"points": 3, "stiffnesses": [5], "timing": false},
 "stability": {"map_dt_points": 4, "map_damping_points": 4}, "collision": {"t_end": 1, "dts": [0.004]},
 "figures": {"energy_t_end": 2, "cannonball_t_end": 2},
 "scaling": {"rope": [4, 8], "softbody": [2], "beads": [4, 8], "t_end": 0.5, "map_sizes": [4, 8], "stiffening": [1, 100]}}
EOF
"$tool" report --print-config | python3 -c 'import json, sys; assert "beads" in json.load(sys.stdin)["scaling"]'
"$tool" report --config small.json --out rep >/dev/null
python3 - rep/atlas.md rep/data/scaling/scaling_beads.json <<'EOF'
import sys, json
md, scal = open(sys.argv[1]).read(), json.load(open(sys.argv[2]))
scaling = md[md.index("## As the system grows"):]
beads = scaling[scaling.index("String of N beads**"):]
beads = beads[:beads.index("\n**")] if "\n**" in beads else beads
table = beads[beads.index("| solver | cost ~"):].split("\n\n")[0] if "| solver | cost ~" in beads else ""
assert [r["beads"] for r in scal["rows"] if r["solver"] == "rk4"] == [4, 8]
finding = lambda e: e["exponent"] is not None and e["ci95"][1] - e["ci95"][0] <= 1
for f in scal["exponents"]:
    rows = [l for l in table.splitlines() if l.startswith(f"| `{f['solver']}` |")]
    if not any(finding(f[k]) for k in ("step", "run", "stable_step")):
        assert not rows, rows  # two sizes: no exponent is a finding, no row
        continue
    e = f["run"]
    cell = f"{e['exponent']:.2f} [{e['ci95'][0]:.2f}, {e['ci95'][1]:.2f}]" + "*" * e["early"] if finding(e) else "-"
    assert f"| {cell} |" in rows[0], (rows, f)
assert "For every solver no exponent is a finding at these sizes" in beads, beads
print("beads: in the report, its exponents from its own study")
EOF
# ... and a report of the user's method beside the methods it should be compared with: those
# methods only, its numbers the full report's (the same studies, whatever runs beside them).
"$tool" report --config small.json --methods heun,explicit_euler,explicit_midpoint,rk4 --sections summary,families,convergence \
  --out mine >/dev/null
python3 - mine/report.md rep/report.md <<'EOF'
import sys
mine, full = open(sys.argv[1]).read(), open(sys.argv[2]).read()
heads = [l for l in mine.splitlines() if l.startswith("## ")]
assert heads == ["## Summary", "## Stability and order, family by family", "## Convergence"], heads
row = lambda md, m: next(l for l in md.splitlines() if f"| `{m}` |" in l)
for m in ["heun", "explicit_euler", "explicit_midpoint", "rk4"]:
    assert row(mine, m).split("|")[2:] == row(full, m).split("|")[2:], (row(mine, m), row(full, m))
for m in ["rk3", "symplectic_euler", "bdf2", "heun_claims_3"]:
    assert f"`{m}`" not in mine, m
print("heun: a report of its own, beside the methods chosen")
EOF
# ... and a report on the user's scene: the sections that need the spring left out with one line
# each, its convergence against the reference solution, the same fits as `study convergence`.
echo '{"convergence": {"t_end": 1}}' > arm.json
"$tool" report --config arm.json --scenes arm --methods heun,rk4 --sections summary,convergence,cost,reproduce \
  --out arm >/dev/null
python3 - arm/report.md arm/data/convergence/convergence_arm.json conv.json <<'EOF'
import sys, json
md, rep, study = open(sys.argv[1]).read(), json.load(open(sys.argv[2])), json.load(open(sys.argv[3]))
assert "*Left out: Summary (it needs `spring`, not among the chosen scenes).*" in md, md
assert "*Left out: What accuracy costs (it needs `spring`" in md, md
assert "arm has no exact solution" in md.replace("Arm", "arm"), md
orders = lambda d: {f["method"]: f["order"] for f in d["fits"]}
assert orders(rep) == orders(study), (orders(rep), orders(study))
print("arm: a report of its own, its orders those of study convergence")
EOF
echo "plugin ok"
