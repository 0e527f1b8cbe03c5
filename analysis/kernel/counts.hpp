// What a run asked for, counted the same way for steplab's methods and for the peers (analysis/
// peers.hpp), so that a cost is given in counts beside its time.
//
//   steps           accepted steps (a fixed-step run: all of them)
//   rejected        steps tried and thrown away: a failed error test or a failed Newton solve
//                   (0 for a fixed step)
//   forces          evaluations of the force, the right side z' = f(t, z) (CVODE's and odeint's
//                   right-side calls; a difference-quotient Jacobian's calls included)
//   jacobians       evaluations of the Jacobians dF/dx, dF/dv (CVODE: of df/dz)
//   factorisations  iteration matrices factorised (steplab: on a fixed size each Newton update's
//                   dense LU; on a run-time size each kept matrix made anew, core/sparse.hpp;
//                   CVODE: its linear solver's setups, M = I - gamma J formed and factorised)
//   solves          linear solves with a factorisation
//   newton          Newton iterations (each one a linear solve)
#pragma once

namespace steplab {

struct Counts {
  long long steps = 0, rejected = 0, forces = 0, jacobians = 0, factorisations = 0, solves = 0, newton = 0;
};

}  // namespace steplab
