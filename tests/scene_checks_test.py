#!/usr/bin/env python3
"""A scene that declares an optional member with another signature than the studies read is
stopped by STEPLAB_SCENE (core/scene_checks.hpp), and the compiler's first error names that
member and the signature expected, not a template backtrace or nothing at all (without the
check each of these compiled, and the member was silently left out: no implicit methods, no
predicted dt*, no long-time study on the scene).

Usage: scene_checks_test.py CXX SOURCE_DIR INCLUDE_DIR...  (the compiler, the tree, Eigen's)"""
import subprocess, sys, tempfile, os

cxx, source, includes = sys.argv[1], sys.argv[2], sys.argv[3:]

SCENE = """#include <array>
#include <cmath>
#include <span>
#include <string_view>
#include <utility>
#include <vector>
#include "core/scene.hpp"
struct Toy {
  static constexpr int dim = 1;
  static constexpr std::string_view name = "toy";
  static constexpr std::array<steplab::ParamSpec, 1> params{{{"stiffness", 1.0, steplab::Bound::Positive, "k"}}};
  double k;
  explicit Toy(std::span<const double> p) : k(p[0]) {}
  steplab::Vec<1> mass() const { return steplab::Vec<1>::Constant(1); }
  steplab::Vec<1> inverse_mass() const { return steplab::Vec<1>::Constant(1); }
  steplab::Vec<1> force(const steplab::Vec<1>& x, const steplab::Vec<1>&) const { return -k * x; }
  bool velocity_dependent() const { return false; }
  double energy(const steplab::Vec<1>& x, const steplab::Vec<1>& v) const { return 0.5 * (v[0] * v[0] + k * x[0] * x[0]); }
  steplab::State<1> initial() const { return {steplab::Vec<1>::Constant(1), steplab::Vec<1>::Zero()}; }
%s
};
STEPLAB_SCENE(Toy);
"""
JACOBIANS = "steplab::Jacobians<1> jacobians(const steplab::Vec<1>&, const steplab::Vec<1>&) const { return {steplab::Mat<1>::Constant(-k), steplab::Mat<1>::Zero()}; }"
MODES = "std::vector<steplab::Mode> modes() const { return {{std::sqrt(k), 0.0}}; }"
NAMES = 'static constexpr std::array<std::string_view, 1> invariant_names{"energy"};'
INVARIANTS = "std::array<double, 1> invariants(const steplab::Vec<1>& x, const steplab::Vec<1>& v) const { return {energy(x, v)}; }"
PERIOD = "double period() const { return 6.283185307179586 / std::sqrt(k); }"
EXTENT = "double extent() const { return 1; }"
LONG_TIME = [NAMES, INVARIANTS, PERIOD, EXTENT]

def swap(members, old, new):
    return [new if m == old else m for m in members]

# (what is wrong, the members, the words the first error must hold; None: it compiles)
CASES = [
    ("every member as read", [JACOBIANS, MODES] + LONG_TIME, None),
    ("jacobians of x alone, a matrix",
     ["steplab::Mat<1> jacobians(const steplab::Vec<1>&) const { return steplab::Mat<1>::Constant(-k); }"],
     "`jacobians` is not `steplab::Jacobians<dim> jacobians(const steplab::Vec<dim>& x, const steplab::Vec<dim>& v) const`"),
    ("modes as pairs", ["std::vector<std::pair<double, double>> modes() const { return {{std::sqrt(k), 0.0}}; }"],
     "`modes` is not `std::vector<steplab::Mode> modes() const`"),
    ("invariant names as C strings", swap(LONG_TIME, NAMES, 'static constexpr std::array<const char*, 1> invariant_names{"energy"};'),
     None),  # a const char* converts to std::string_view: read as declared
    ("invariant names as numbers", swap(LONG_TIME, NAMES, "static constexpr std::array<int, 1> invariant_names{1};"),
     "`invariant_names` is not `static constexpr std::array<std::string_view, N> invariant_names`"),
    ("invariants as a vector",
     swap(LONG_TIME, INVARIANTS, "std::vector<double> invariants(const steplab::Vec<1>& x, const steplab::Vec<1>& v) const { return {energy(x, v)}; }"),
     "`invariants` is not `std::array<double, N> invariants(const steplab::Vec<dim>& x, const steplab::Vec<dim>& v) const`"),
    ("period of the amplitude", swap(LONG_TIME, PERIOD, "double period(double a) const { return 6.28 * a; }"),
     "`period` is not `double period() const`"),
    ("extent not const", swap(LONG_TIME, EXTENT, "double extent() { return 1; }"), "`extent` is not `double extent() const`"),
    ("invariants without period and extent", [NAMES, INVARIANTS],
     "reads invariant_names, invariants(x, v), period() and extent() together"),
]

failed = 0
with tempfile.TemporaryDirectory() as tmp:
    for what, members, want in CASES:
        path = os.path.join(tmp, "toy.cpp")
        open(path, "w").write(SCENE % "\n".join("  " + m for m in members))
        r = subprocess.run([cxx, "-std=c++20", "-fsyntax-only", "-I" + source] + ["-I" + i for i in includes] + [path],
                           capture_output=True, text=True)
        errors = [l for l in r.stderr.splitlines() if "error:" in l]
        if want is None:
            ok = r.returncode == 0
            said = "compiles" if ok else "fails: " + (errors[0] if errors else r.stderr[:300])
        else:
            ok = r.returncode != 0 and bool(errors) and want in errors[0] and "STEPLAB_SCENE" in errors[0]
            said = (errors[0].split("error: ", 1)[1] if errors else "compiles") + f" ({len(r.stderr.splitlines())} lines)"
        print(f"{'ok' if ok else 'FAIL'}  {what}: {said}")
        failed += not ok
sys.exit(1 if failed else 0)
