// The vectors a step works in on a scene of run-time size, without allocating (MuJoCo's mjData
// stack in spirit): a run owns a pool of vectors (its Stepper, core/stepper.hpp, installs it while
// it steps) and a step's temporaries borrow from it and give back when they go out of scope. The
// pool grows in a run's first step, to as many vectors as a step holds at once; every later step
// finds them there, sized: no heap allocation after the first step.
//
// Temp<D, T> is the type a method names its temporaries with (`using V = Temp<S::dim, T>;`):
//   fixed D (and every pack of runs):  Vec<D, T> itself, on the stack, as before;
//   D = Eigen::Dynamic:                ScratchVec, a borrowed vector of the pool, usable in any
//                                      Eigen expression (it is an Eigen::Map).
// So one method file serves both, and a fixed-size step compiles to what it did.
#pragma once

#include <cstddef>
#include <deque>
#include <type_traits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "core/state.hpp"

namespace steplab {

class ScratchPool {
 public:
  // A free vector of size n: one of that size if there is one (a step's temporaries all have the
  // scene's size, the rope's transforms 2N + 1), else a new one. Never a free one of another size
  // resized: a step that borrows both sizes would then resize them back and forth, allocating in
  // every step; so the pool keeps vectors of each size a step asks for.
  int take(Eigen::Index n) {
    for (std::size_t k = free_.size(); k-- > 0;) {
      const int slot = free_[k];
      if (vectors_[static_cast<std::size_t>(slot)].size() == n) {
        free_.erase(free_.begin() + static_cast<std::ptrdiff_t>(k));
        return slot;
      }
    }
    const int slot = static_cast<int>(vectors_.size());
    vectors_.emplace_back(n);  // a deque: the vectors lent out stay where they are
    free_.reserve(vectors_.size());
    return slot;
  }
  void give_back(int slot) { free_.push_back(slot); }  // within capacity: reserved for every slot
  double* data(int slot) { return vectors_[static_cast<std::size_t>(slot)].data(); }
  std::size_t size() const { return vectors_.size(); }

 private:
  std::deque<Eigen::VectorXd> vectors_;
  std::vector<int> free_;
};

// The pool of the run this thread is stepping; outside a run, the thread's own (kept, so that a
// step called on its own also stops allocating after its first call).
inline thread_local ScratchPool* t_scratch_pool = nullptr;
inline ScratchPool& scratch_pool() {
  thread_local ScratchPool own;
  return t_scratch_pool ? *t_scratch_pool : own;
}

// Installs a run's pool for as long as it lives (the run's Stepper, while it steps).
class UseScratch {
 public:
  explicit UseScratch(ScratchPool& p) : previous_(t_scratch_pool) { t_scratch_pool = &p; }
  ~UseScratch() { t_scratch_pool = previous_; }
  UseScratch(const UseScratch&) = delete;
  UseScratch& operator=(const UseScratch&) = delete;

 private:
  ScratchPool* previous_;
};

// A vector of the pool for as long as it lives. Made from an expression it holds its value;
// copying makes another; moving hands the borrowed vector on.
class ScratchVec : public Eigen::Map<Eigen::VectorXd> {
  using Base = Eigen::Map<Eigen::VectorXd>;

 public:
  explicit ScratchVec(Eigen::Index n) : ScratchVec(scratch_pool(), n) {}
  template <class E> ScratchVec(const Eigen::MatrixBase<E>& e) : ScratchVec(e.size()) { Base::operator=(e); }
  ScratchVec(const ScratchVec& o) : ScratchVec(o.size()) { Base::operator=(o); }
  ScratchVec(ScratchVec&& o) noexcept : Base(o.data(), o.size()), pool_(o.pool_), slot_(std::exchange(o.slot_, -1)) {}
  ~ScratchVec() {
    if (slot_ >= 0) pool_->give_back(slot_);
  }
  ScratchVec& operator=(const ScratchVec& o) {
    Base::operator=(o);
    return *this;
  }
  template <class E> ScratchVec& operator=(const Eigen::MatrixBase<E>& e) {
    Base::operator=(e);
    return *this;
  }

 private:
  ScratchVec(ScratchPool& p, Eigen::Index n) : ScratchVec(p, p.take(n), n) {}
  ScratchVec(ScratchPool& p, int slot, Eigen::Index n) : Base(p.data(slot), n), pool_(&p), slot_(slot) {}
  ScratchPool* pool_;
  int slot_;
};

template <int D, class T = double> using Temp = std::conditional_t<D == Eigen::Dynamic, ScratchVec, Vec<D, T>>;

// A temporary of the size of `like` (a vector of the state): uninitialised.
template <int D, class T, class Like> Temp<D, T> temp_like(const Like& like) {
  if constexpr (D == Eigen::Dynamic) return ScratchVec(like.size());
  else return Vec<D, T>();
}

// A state of temporaries: what a multistep method's sums and derivatives are held in.
template <int D, class T = double> struct TempState {
  Temp<D, T> x, v;
  operator State<D, T>() const { return {x, v}; }  // a copy of its own (allocates on a run-time size)
};

}  // namespace steplab
