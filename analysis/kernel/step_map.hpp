// The step map of a method on a 1-D scene, flattened to one vector of doubles: x, v, then every
// memory entry's x and v (a multistep method's history, most recent first). A one-step method's
// map is (x, v) alone. The stability analyses difference it (stability.cpp, on the spring) or
// apply it to unit vectors (regions.cpp, on the linear test equation).
#pragma once

#include <Eigen/Core>

#include "core/stepper.hpp"

namespace steplab {

template <class M> constexpr int map_size() {
  if constexpr (Multistep<M>) return 2 * (1 + M::history);
  else return 2;
}

// A memory's entries into z after (x, v): entry k at 2k, 2k + 1.
template <int K> void put_memory(Eigen::VectorXd& z, const History<1, K>& mem) {
  for (int k = 1; k <= K; ++k) z.segment<2>(2 * k) << mem.past[k - 1].x[0], mem.past[k - 1].v[0];
}

// One step of M from the flattened state z (memory full), returned flattened.
template <class M, Scene S> Eigen::VectorXd step_flat(const S& s, const Eigen::VectorXd& z, double h) {
  static_assert(S::dim == 1, "the step map is flattened for 1-D scenes");
  State<1> y{Vec<1>::Constant(z[0]), Vec<1>::Constant(z[1])};
  Stepper<M, S> stepper;
  if constexpr (Multistep<M>)
    stepper.memory = history_of<1, M::history>([&](int k) {
      return State<1>{Vec<1>::Constant(z[2 * k]), Vec<1>::Constant(z[2 * k + 1])};
    });
  stepper.step(s, y, 0.0, h);
  Eigen::VectorXd out(z.size());
  out << y.x[0], y.v[0];
  if constexpr (Multistep<M>) put_memory(out, stepper.memory);
  return out;
}

// The flattened memory of a run that has sat at y forever.
template <class M, Scene S> Eigen::VectorXd at_rest_flat(const S& s, const State<1>& y) {
  Eigen::VectorXd z(map_size<M>());
  z << y.x[0], y.v[0];
  if constexpr (Multistep<M>) put_memory(z, M::remember(s, [&](int) { return y; }));
  return z;
}

}  // namespace steplab
