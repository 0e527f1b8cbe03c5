// A pack of W doubles, one per run, used as Eigen's scalar: the same method and scene code steps
// one run (T = double) or W runs at once (T = Pack<W>), lane by lane the same IEEE operations,
// so a lane's numbers are the bits a run of its own gives (with -ffp-contract=off, see
// CMakeLists.txt: no fused multiply-add in one and not the other). Drake's SIMD scalar
// (multibody/mpm/simd_scalar.h) is the model.
//
// The lanes are one GCC vector (`vector_size`) of the register width of the instruction set the
// batched run loop is compiled for (core/batch.hpp, analysis/kernel/kernel_impl.hpp): 2 on SSE2, 4 on
// AVX2, 8 on AVX-512. A vector wider than the target's registers is lowered through memory
// (3-4x slower). One pack is stepped at a time, not two interleaved: the loop is bound by its
// instruction count, not by its latency, so a second chain of a step in flight gained nothing
// (docs/design.md, Why a step is fast). Comparisons give a Mask; a branch on the state becomes a
// select.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include <Eigen/Core>

namespace steplab {

// GCC takes vector_size on a type whose size is known where it is declared, not on a template's.
template <int W> struct GccVector;
template <> struct GccVector<2> { typedef double lanes __attribute__((vector_size(16))); typedef std::int64_t bits __attribute__((vector_size(16))); };
template <> struct GccVector<4> { typedef double lanes __attribute__((vector_size(32))); typedef std::int64_t bits __attribute__((vector_size(32))); };
template <> struct GccVector<8> { typedef double lanes __attribute__((vector_size(64))); typedef std::int64_t bits __attribute__((vector_size(64))); };

template <int W> struct Mask;

template <int W> struct Pack {
  static_assert(W == 2 || W == 4 || W == 8, "a pack holds 2, 4 or 8 lanes");
  static constexpr int width = W;
  using Lanes = typename GccVector<W>::lanes;
  using Bits = typename GccVector<W>::bits;
  Lanes v;

  Pack() = default;
  // Copied by hand, so not trivially copyable: the ABI then passes a pack by reference to a
  // function that was not inlined, never in vector registers, whose width differs between code
  // compiled for SSE2 and for AVX2 or AVX-512 (a call across them would read the wrong lanes).
  Pack(const Pack& o) : v(o.v) {}
  Pack& operator=(const Pack& o) { return v = o.v, *this; }
  Pack(double d) : v(Lanes{} + d) {}  // every lane d (implicit: 0.5 * h, h / 6 read as written)
  static Pack of(const Lanes& l) {
    Pack p;
    p.v = l;
    return p;
  }
  double operator[](int l) const { return v[l]; }
  void set(int l, double d) { v[l] = d; }

  friend Pack operator+(const Pack& a, const Pack& b) { return of(a.v + b.v); }
  friend Pack operator-(const Pack& a, const Pack& b) { return of(a.v - b.v); }
  friend Pack operator*(const Pack& a, const Pack& b) { return of(a.v * b.v); }
  friend Pack operator/(const Pack& a, const Pack& b) { return of(a.v / b.v); }
  friend Pack operator-(const Pack& a) { return of(-a.v); }
  Pack& operator+=(const Pack& b) { return v += b.v, *this; }
  Pack& operator-=(const Pack& b) { return v -= b.v, *this; }
  Pack& operator*=(const Pack& b) { return v *= b.v, *this; }
  Pack& operator/=(const Pack& b) { return v /= b.v, *this; }

  friend Mask<W> operator<(const Pack& a, const Pack& b) { return Mask<W>::of(a.v < b.v); }
  friend Mask<W> operator>(const Pack& a, const Pack& b) { return Mask<W>::of(a.v > b.v); }
  friend Mask<W> operator<=(const Pack& a, const Pack& b) { return Mask<W>::of(a.v <= b.v); }
  friend Mask<W> operator>=(const Pack& a, const Pack& b) { return Mask<W>::of(a.v >= b.v); }
  friend Mask<W> operator==(const Pack& a, const Pack& b) { return Mask<W>::of(a.v == b.v); }
  friend Mask<W> operator!=(const Pack& a, const Pack& b) { return Mask<W>::of(a.v != b.v); }
};

// Lane-wise truth: all bits set where it holds.
template <int W> struct Mask {
  using Bits = typename Pack<W>::Bits;
  Bits b;
  Mask() = default;
  // Every lane on, or none (bool(on) for one run). A select of two constants, which GCC folds
  // where `on` is known; Bits{} + (on ? -1 : 0) was built lane by lane from a register of 0 in
  // the stepping loop of an explicit method (core/batch.hpp: the lanes whose step failed).
  explicit Mask(bool on) : b(on ? Bits{} - 1 : Bits{}) {}
  Mask(const Mask& o) : b(o.b) {}  // not trivially copyable: see Pack
  Mask& operator=(const Mask& o) { return b = o.b, *this; }
  static Mask of(const Bits& bits) {
    Mask m;
    m.b = bits;
    return m;
  }
  friend Mask operator&&(const Mask& x, const Mask& y) { return of(x.b & y.b); }
  friend Mask operator||(const Mask& x, const Mask& y) { return of(x.b | y.b); }
  friend Mask operator!(const Mask& x) { return of(~x.b); }
  bool operator[](int l) const { return b[l] != 0; }
  void set(int l, bool on) { b[l] = on ? -1 : 0; }
};

// --- The same names for one run (double, bool) and for a pack --------------------------------

// What comparing two T gives: bool for one run, Mask<W> for a pack. MaskOf<T>(b) is b in every lane.
template <class T> using MaskOf = decltype(std::declval<const T&>() < std::declval<const T&>());

inline double select(bool c, double a, double b) { return c ? a : b; }
// Per width, as GCC 12 compiles it best (docs/design.md, Why a step is fast). A mask's lanes are all
// ones or all zeros, so on AVX2 its sign bit is the lane: c < 0 is one vblendvpd, where c != 0
// compares the mask with zero twice first. SSE2 has no blend and GCC makes either form a branch
// per lane: the bits are and-ed and or-ed. On AVX-512, c < 0 is a comparison typed for plain
// x86-64, which GCC 12 does lane by lane: c != 0.
template <int W> Pack<W> select(const Mask<W>& c, const Pack<W>& a, const Pack<W>& b) {
  using P = Pack<W>;
  if constexpr (W == 2) return P::of(typename P::Lanes((typename P::Bits(a.v) & c.b) | (typename P::Bits(b.v) & ~c.b)));
  else if constexpr (W == 4) return P::of(c.b < 0 ? a.v : b.v);
  else return P::of(c.b ? a.v : b.v);
}

inline bool any(bool c) { return c; }
inline bool all(bool c) { return c; }
// Any lane on: the two halves OR-ed together until two lanes are left, in log2(W) operations
// rather than a test per lane (fewer instructions per step: docs/design.md, Why a step is fast).
template <int W> bool any(const Mask<W>& c) {
  const typename Mask<W>::Bits& b = c.b;
  if constexpr (W == 8) return any(Mask<4>::of(__builtin_shufflevector(b, b, 0, 1, 2, 3) | __builtin_shufflevector(b, b, 4, 5, 6, 7)));
  else if constexpr (W == 4) return any(Mask<2>::of(__builtin_shufflevector(b, b, 0, 1) | __builtin_shufflevector(b, b, 2, 3)));
  else return (b[0] | b[1]) != 0;
}
template <int W> bool all(const Mask<W>& c) { return !any(!c); }

// Lane-wise |a| (the sign bit cleared, as std::abs does), max and min as std::max and std::min pick.
template <int W> Pack<W> abs(const Pack<W>& a) {
  using P = Pack<W>;
  return P::of(typename P::Lanes(typename P::Bits(a.v) & std::numeric_limits<std::int64_t>::max()));
}
template <int W> Pack<W> max(const Pack<W>& a, const Pack<W>& b) { return select(a < b, b, a); }
template <int W> Pack<W> min(const Pack<W>& a, const Pack<W>& b) { return select(b < a, b, a); }
// f(a) lane by lane, for the functions of <cmath> below: each lane the bits of one run.
template <int W, class F> [[gnu::always_inline]] inline Pack<W> lanewise(const Pack<W>& a, F f) {
  Pack<W> p;
  for (int l = 0; l < W; ++l) p.v[l] = f(a.v[l]);
  return p;
}
// Correctly rounded in every lane, like std::sqrt (GCC emits one sqrtpd for the loop: with
// -fno-math-errno, CMakeLists.txt).
template <int W> Pack<W> sqrt(const Pack<W>& a) { return lanewise(a, [](double x) { return std::sqrt(x); }); }
// libm's log in every lane (the ln E fit).
template <int W> Pack<W> log(const Pack<W>& a) { return lanewise(a, [](double x) { return std::log(x); }); }
// cos and sin: a scene's set-up from its parameters (the cannon ball's launch), not a step.
template <int W> Pack<W> cos(const Pack<W>& a) { return lanewise(a, [](double x) { return std::cos(x); }); }
template <int W> Pack<W> sin(const Pack<W>& a) { return lanewise(a, [](double x) { return std::sin(x); }); }
// Finite in every coordinate: x - x is 0 for a finite x, NaN for inf and NaN (std::isfinite).
inline bool finite(double x) { return std::isfinite(x); }
template <int W> Mask<W> finite(const Pack<W>& x) { return (x - x) == Pack<W>(0.0); }

}  // namespace steplab

// Eigen's view of a pack: a real scalar that is not vectorised further (the lanes are).
template <int W> struct Eigen::NumTraits<steplab::Pack<W>> : Eigen::GenericNumTraits<double> {
  using Real = steplab::Pack<W>;
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
