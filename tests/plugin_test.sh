#!/usr/bin/env bash
# The README's walk-through "check your own integrator", from an empty folder: install steplab
# into a temporary prefix, write a method (Heun's), the same method declared one order too high,
# and a scene without an exact solution (a damped pendulum) into a new project, build it with
# steplab_add_executable(), and ask the tool about them:
#   mysteplab check --method heun            exit 0 (every claim holds)
#   mysteplab check --method heun_claims_3   exit 1 (the order claim fails)
#   mysteplab study convergence --scene pendulum --methods heun,rk4
#                                            against the reference solution (no exact one):
#                                            fitted orders 2 and 4 within 0.1
#   mysteplab study stability --methods heun,rk4 --lanes 1 and --lanes 2
#                                            the same JSON (Heun is written over the scalar,
#                                            so the spring's runs step two at a time)
# Usage: plugin_test.sh BUILD_DIR [extra cmake arguments for the project]
set -euo pipefail
build=$1
shift
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
  static steplab::StepStatus step(const S& s, steplab::State<S::dim, T>& y, steplab::Time<T>, steplab::Time<T> h) {
    using V = steplab::Vec<S::dim, T>;
    const V kx1 = y.v, kv1 = steplab::acceleration(s, y.x, y.v);
    const V xp = y.x + h * kx1, vp = y.v + h * kv1;
    const V kx2 = vp, kv2 = steplab::acceleration(s, xp, vp);
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

// The same step, declared third order: `check` must say no.
struct HeunClaims3 : Heun {
  static constexpr steplab::MethodInfo info{.name = "heun_claims_3", .order = 3, .family = steplab::Family::ExplicitRungeKutta,
                                            .summary = "Heun's method declared one order too high"};
};

STEPLAB_METHOD(HeunClaims3);
EOF

cat > pendulum.hpp <<'EOF'
#pragma once
#include <array>
#include <cmath>
#include <span>
#include <string_view>

#include <steplab/core/scene.hpp>

// A damped pendulum, angle x from the vertical: m l^2 x'' = -m g l sin x - c x'. No closed form:
// studies converge against the reference solution.
struct Pendulum {
  static constexpr int dim = 1;
  static constexpr std::string_view name = "pendulum";
  static constexpr std::array<steplab::ParamSpec, 4> params{{
      {"bob-mass", 1.0, steplab::Bound::Positive, "mass of the bob"},
      {"arm", 1.0, steplab::Bound::Positive, "length of the arm"},
      {"friction", 0.05, steplab::Bound::NonNegative, "damping torque per angular velocity"},
      {"angle", 2.0, steplab::Bound::Any, "start angle (at rest), radians"},
  }};
  double m, l, c, a0, g = 9.81;
  explicit Pendulum(std::span<const double> p) : m(p[0]), l(p[1]), c(p[2]), a0(p[3]) {}
  steplab::Vec<1> mass() const { return steplab::Vec<1>::Constant(m * l * l); }
  steplab::Vec<1> inverse_mass() const { return steplab::Vec<1>::Constant(1 / (m * l * l)); }
  steplab::Vec<1> force(const steplab::Vec<1>& x, const steplab::Vec<1>& v) const {
    return steplab::Vec<1>::Constant(-m * g * l * std::sin(x[0]) - c * v[0]);
  }
  steplab::Jacobians<1> jacobians(const steplab::Vec<1>& x, const steplab::Vec<1>&) const {
    return {steplab::Mat<1>::Constant(-m * g * l * std::cos(x[0])), steplab::Mat<1>::Constant(-c)};
  }
  bool velocity_dependent() const { return c != 0; }
  double energy(const steplab::Vec<1>& x, const steplab::Vec<1>& v) const {
    return 0.5 * m * l * l * v[0] * v[0] + m * g * l * (1 - std::cos(x[0]));
  }
  steplab::State<1> initial() const { return {steplab::Vec<1>::Constant(a0), steplab::Vec<1>::Zero()}; }
};

STEPLAB_SCENE(Pendulum);
EOF

cat > CMakeLists.txt <<'EOF'
cmake_minimum_required(VERSION 3.22)
project(mine LANGUAGES CXX)
find_package(steplab 0.2 REQUIRED)
steplab_add_executable(mysteplab METHODS heun.hpp heun_claims_3.hpp SCENES pendulum.hpp)
EOF

cmake -S . -B build -DCMAKE_PREFIX_PATH="$tmp/prefix" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build build -j 2 >/dev/null
tool=build/mysteplab

"$tool" check --method heun
status=0
"$tool" check --method heun_claims_3 || status=$?
[[ $status -eq 1 ]] || { echo "check --method heun_claims_3 exited $status, not 1"; exit 1; }

"$tool" study convergence --scene pendulum --methods heun,rk4 --json conv.json >/dev/null
python3 - conv.json <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["scene"] == "pendulum", d["scene"]
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
# the new method on a built-in scene, the built-in ones on the new scene
"$tool" run --scene chain --method heun --dt 0.001 --t-end 1 >/dev/null
"$tool" run --scene pendulum --method radau_iia5 --dt 0.01 --t-end 1 >/dev/null
echo "plugin ok"
