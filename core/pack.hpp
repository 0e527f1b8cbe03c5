// A pack of W doubles, one per run, used as Eigen's scalar: the same method and scene code steps
// one run (T = double) or W runs at once (T = Pack<W>), lane by lane the same IEEE operations,
// so a lane's numbers are the bits a run of its own gives (with -ffp-contract=off, see
// CMakeLists.txt: no fused multiply-add in one and not the other). Drake's SIMD scalar
// (multibody/mpm/simd_scalar.h) is the model.
//
// The lanes are a GCC vector (`vector_size`): GCC lowers it to the widest registers of the
// target it compiles for, four SSE2 registers, two AVX2 or one AVX-512 register for W = 8, so the
// batched run loop (core/batch.hpp), compiled once per instruction set by target_clones, uses
// the CPU's widest unit. Comparisons give a Mask; a branch on the state becomes a select.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Core>

namespace steplab {

// GCC takes vector_size on a type whose size is known where it is declared, not on a template's.
template <int N> struct GccVector;
template <> struct GccVector<2> { typedef double lanes __attribute__((vector_size(16))); typedef std::int64_t bits __attribute__((vector_size(16))); };
template <> struct GccVector<4> { typedef double lanes __attribute__((vector_size(32))); typedef std::int64_t bits __attribute__((vector_size(32))); };
template <> struct GccVector<8> { typedef double lanes __attribute__((vector_size(64))); typedef std::int64_t bits __attribute__((vector_size(64))); };

template <int W, int R> struct Mask;

// W lanes held in R registers of W / R doubles each: 2 registers of an instruction set's width
// (W = 4 on SSE2, 8 on AVX2, 16 on AVX-512) keep two independent chains of a step in flight,
// where one waits on the latency of the last operation (a GCC vector wider than the target's
// registers is lowered through memory instead: 3-4x slower, measured).
template <int W, int R = 1> struct Pack {
  static constexpr int width = W, N = W / R;  // N: lanes a register
  static_assert(R >= 1 && W % R == 0 && (N == 2 || N == 4 || N == 8), "a register holds 2, 4 or 8 lanes");
  using Reg = typename GccVector<N>::lanes;
  using Bits = typename GccVector<N>::bits;
  Reg r[R];

  Pack() = default;
  // Copied by hand, so not trivially copyable: the ABI then passes a pack by reference to a
  // function that was not inlined, never in vector registers, whose width differs between code
  // compiled for SSE2 and for AVX2 or AVX-512 (a call across them would read the wrong lanes).
  Pack(const Pack& o) { for (int i = 0; i < R; ++i) r[i] = o.r[i]; }
  Pack& operator=(const Pack& o) { for (int i = 0; i < R; ++i) r[i] = o.r[i]; return *this; }
  Pack(double d) { for (int i = 0; i < R; ++i) r[i] = Reg{} + d; }  // every lane d (implicit: 0.5 * h, h / 6 read as written)
  double operator[](int l) const { return r[l / N][l % N]; }
  void set(int l, double d) { r[l / N][l % N] = d; }

  // Register by register; the lambdas take references (a vector by value would change the ABI
  // with the instruction set, GCC's -Wpsabi).
  template <class F> static Pack map(const Pack& a, const Pack& b, F f) {
    Pack p;
    for (int i = 0; i < R; ++i) f(p.r[i], a.r[i], b.r[i]);
    return p;
  }
  friend Pack operator+(const Pack& a, const Pack& b) { return map(a, b, [](Reg& o, const Reg& x, const Reg& y) { o = x + y; }); }
  friend Pack operator-(const Pack& a, const Pack& b) { return map(a, b, [](Reg& o, const Reg& x, const Reg& y) { o = x - y; }); }
  friend Pack operator*(const Pack& a, const Pack& b) { return map(a, b, [](Reg& o, const Reg& x, const Reg& y) { o = x * y; }); }
  friend Pack operator/(const Pack& a, const Pack& b) { return map(a, b, [](Reg& o, const Reg& x, const Reg& y) { o = x / y; }); }
  friend Pack operator-(const Pack& a) { return map(a, a, [](Reg& o, const Reg& x, const Reg&) { o = -x; }); }
  Pack& operator+=(const Pack& b) { return *this = *this + b; }
  Pack& operator-=(const Pack& b) { return *this = *this - b; }
  Pack& operator*=(const Pack& b) { return *this = *this * b; }
  Pack& operator/=(const Pack& b) { return *this = *this / b; }

  template <class F> static Mask<W, R> test(const Pack& a, const Pack& b, F f) {
    Mask<W, R> m;
    for (int i = 0; i < R; ++i) f(m.r[i], a.r[i], b.r[i]);
    return m;
  }
  friend Mask<W, R> operator<(const Pack& a, const Pack& b) { return test(a, b, [](Bits& o, const Reg& x, const Reg& y) { o = x < y; }); }
  friend Mask<W, R> operator>(const Pack& a, const Pack& b) { return test(a, b, [](Bits& o, const Reg& x, const Reg& y) { o = x > y; }); }
  friend Mask<W, R> operator<=(const Pack& a, const Pack& b) { return test(a, b, [](Bits& o, const Reg& x, const Reg& y) { o = x <= y; }); }
  friend Mask<W, R> operator>=(const Pack& a, const Pack& b) { return test(a, b, [](Bits& o, const Reg& x, const Reg& y) { o = x >= y; }); }
  friend Mask<W, R> operator==(const Pack& a, const Pack& b) { return test(a, b, [](Bits& o, const Reg& x, const Reg& y) { o = x == y; }); }
  friend Mask<W, R> operator!=(const Pack& a, const Pack& b) { return test(a, b, [](Bits& o, const Reg& x, const Reg& y) { o = x != y; }); }
};

// Lane-wise truth: all bits set where it holds.
template <int W, int R = 1> struct Mask {
  using Bits = typename Pack<W, R>::Bits;
  static constexpr int N = Pack<W, R>::N;
  Bits r[R];
  Mask() = default;
  Mask(const Mask& o) { for (int i = 0; i < R; ++i) r[i] = o.r[i]; }  // not trivially copyable: see Pack
  Mask& operator=(const Mask& o) { for (int i = 0; i < R; ++i) r[i] = o.r[i]; return *this; }
  template <class F> static Mask map(const Mask& a, const Mask& b, F f) {
    Mask m;
    for (int i = 0; i < R; ++i) f(m.r[i], a.r[i], b.r[i]);
    return m;
  }
  friend Mask operator&&(const Mask& x, const Mask& y) { return map(x, y, [](Bits& o, const Bits& a, const Bits& b) { o = a & b; }); }
  friend Mask operator||(const Mask& x, const Mask& y) { return map(x, y, [](Bits& o, const Bits& a, const Bits& b) { o = a | b; }); }
  friend Mask operator!(const Mask& x) { return map(x, x, [](Bits& o, const Bits& a, const Bits&) { o = ~a; }); }
  bool operator[](int l) const { return r[l / N][l % N] != 0; }
  void set(int l, bool on) { r[l / N][l % N] = on ? -1 : 0; }
};

// --- The same names for one run (double, bool) and for a pack --------------------------------

inline double select(bool c, double a, double b) { return c ? a : b; }
template <int W, int R> Pack<W, R> select(const Mask<W, R>& c, const Pack<W, R>& a, const Pack<W, R>& b) {
  Pack<W, R> p;
  for (int i = 0; i < R; ++i) p.r[i] = c.r[i] ? a.r[i] : b.r[i];
  return p;
}

inline bool any(bool c) { return c; }
inline bool all(bool c) { return c; }
template <int W, int R> bool any(const Mask<W, R>& c) {
  typename Mask<W, R>::Bits m = c.r[0];
  for (int i = 1; i < R; ++i) m |= c.r[i];
  for (int l = 0; l < Mask<W, R>::N; ++l)
    if (m[l]) return true;
  return false;
}
template <int W, int R> bool all(const Mask<W, R>& c) { return !any(!c); }

// Lane-wise |a| (the sign bit cleared, as std::abs does), max and min as std::max and std::min pick.
template <int W, int R> Pack<W, R> abs(const Pack<W, R>& a) {
  using P = Pack<W, R>;
  P p;
  for (int i = 0; i < R; ++i)
    p.r[i] = typename P::Reg(typename P::Bits(a.r[i]) & std::numeric_limits<std::int64_t>::max());
  return p;
}
template <int W, int R> Pack<W, R> max(const Pack<W, R>& a, const Pack<W, R>& b) { return select(a < b, b, a); }
template <int W, int R> Pack<W, R> min(const Pack<W, R>& a, const Pack<W, R>& b) { return select(b < a, b, a); }
// Correctly rounded in every lane, like std::sqrt (GCC emits one sqrtpd for the loop: with
// -fno-math-errno, CMakeLists.txt).
template <int W, int R> Pack<W, R> sqrt(const Pack<W, R>& a) {
  Pack<W, R> p;
  for (int l = 0; l < W; ++l) p.set(l, std::sqrt(a[l]));
  return p;
}
// Lane by lane std::log: the bits of a run of its own.
template <int W, int R> Pack<W, R> log(const Pack<W, R>& a) {
  Pack<W, R> p;
  for (int l = 0; l < W; ++l) p.set(l, std::log(a[l]));
  return p;
}
// Finite in every coordinate: x - x is 0 for a finite x, NaN for inf and NaN (std::isfinite).
inline bool finite(double x) { return std::isfinite(x); }
template <int W, int R> Mask<W, R> finite(const Pack<W, R>& x) { return (x - x) == Pack<W, R>(0.0); }

template <class T> constexpr int width_of = 1;
template <int W, int R> constexpr int width_of<Pack<W, R>> = W;

}  // namespace steplab

// Eigen's view of a pack: a real scalar that is not vectorised further (the lanes are).
template <int W, int R> struct Eigen::NumTraits<steplab::Pack<W, R>> : Eigen::GenericNumTraits<double> {
  using Real = steplab::Pack<W, R>;
  using NonInteger = Real;
  using Literal = Real;
  using Nested = Real;
  enum { IsComplex = 0, IsInteger = 0, IsSigned = 1, RequireInitialization = 0, ReadCost = 1, AddCost = W, MulCost = W };
  static Real epsilon() { return std::numeric_limits<double>::epsilon(); }
  static Real dummy_precision() { return 1e-12; }
  static Real highest() { return std::numeric_limits<double>::max(); }
  static Real lowest() { return std::numeric_limits<double>::lowest(); }
  static int digits10() { return std::numeric_limits<double>::digits10; }
};
