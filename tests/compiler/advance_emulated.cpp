/* sph_sim_advance on the CUDA target's device clock, built with SPH_CUDA_EMULATE around the
 * model.cu named by MODEL_CU (run_cuda_emulated_advance.cmake):
 *  - a batch of 7 steps with its stop time far away takes 7 steps;
 *  - a batch that may take as many steps as it likes (INT_MAX) stops at its stop time, on
 *    it to within eps, without queueing its INT_MAX steps (the host looks whether the clock
 *    stopped after every chunk; queueing them all would take minutes: the test's timeout);
 *  - a batch that starts at its stop time takes none;
 *  - the host's t, step and time step follow the device's clock. */
#include <climits>

#define main generated_main
#include MODEL_CU
#undef main

static int failures;

static void check(int ok, const char *what)
{
    printf("%s: %s\n", ok ? "ok" : "FAIL", what);
    failures += !ok;
}

int main()
{
    sph_sim s;
    if (sph_sim_init(&s, &MODEL, 0))
        return 2;
    const double eps = 1e-15;
    sph_advance a = {7, 1.0, eps, 0.0, 0, 0, 0};
    int taken = sph_sim_advance(&s, &a);
    check(taken == 7 && s.step == 7 && !a.collapsed, "7 steps asked, 7 taken");
    check(s.t > 0 && s.dt > 0 && fabs(s.t - 7 * s.dt) < 0.1 * s.t, "t and dt from the clock");

    const double t_stop = 1e-3;
    const long step0 = s.step;
    a = sph_advance{INT_MAX, t_stop, eps, 0.0, 0, 0, 0};
    taken = sph_sim_advance(&s, &a);
    printf("%d steps to t = %.17g (stop %g)\n", taken, s.t, t_stop);
    check(taken > 20 && s.step == step0 + taken && !a.collapsed, "as many steps as it takes");
    check(fabs(s.t - t_stop) <= eps, "on the stop time");

    a = sph_advance{INT_MAX, t_stop, eps, 0.0, 0, 0, 0};
    taken = sph_sim_advance(&s, &a);
    check(taken == 0 && fabs(s.t - t_stop) <= eps, "none from the stop time");
    sph_sim_free(&s);
    return failures ? 1 : 0;
}
