# THE method and scene tables, in the order every study, the CLI and the report list them.
#
# Adding an integrator: write core/methods/<name>.hpp (a struct with `info` and `step`, see
# core/method.hpp; a multistep method also keeps a memory, see core/stepper.hpp) ending with the
# line STEPLAB_METHOD(steplab::<Type>), and add <name> below. A scene likewise: core/scenes/<name>.hpp
# (see core/scene.hpp) ending with STEPLAB_SCENE(steplab::<Type>), and <name> below. CMake then
# generates the method's translation unit (tools/kernels.cmake) and the table; nothing else
# changes. `steplab check --method <name>` measures what a method's `info` claims.
set(STEPLAB_METHODS
    explicit_euler symplectic_euler explicit_midpoint implicit_euler  # the sheet's four
    velocity_verlet rk4 implicit_midpoint                             # order vs stability
    rk3 yoshida4 gauss_legendre4                                      # families: one-step
    adams_bashforth2 adams_bashforth3 bdf2 bdf3                       # families: multistep
    radau_iia5                                                        # stiff systems
    xpbd pbd baraff_witkin                                            # the course's next: on springs
    analytic)
set(STEPLAB_SCENES cannonball spring falling bounce chain rope softbody cloth target kepler swing pendulum)
