/* Time windows and `near` of velocity boundary conditions (window2d.sph).  The steps land
 * on the window's ends (1 ms, 2 ms); a window holds for a step that starts in [t0, t1).
 *  - `near`: the particles within dx of the box are the 12 of the top row with
 *    9.5 mm <= x0 <= 20.5 mm (closed form from the geometry);
 *  - before 1 ms nothing acts on the bodies: every velocity is exactly 0 and no particle
 *    is fixed;
 *  - from 1 ms to 2 ms the selected particles move at exactly the prescribed velocity, with
 *    their fix bit set, and no other particle is fixed;
 *  - after 2 ms they move freely: no particle is fixed, their velocity departs from the
 *    prescribed value, and the bodies' momentum stays constant (free bodies). */
#define main generated_main
#include "window2d.c"
#undef main

#include "check.h"

enum { D = 2 };

static double momentum(const sph_body *b, int k)
{
    double s = 0;
    for (int i = 0; i < b->n; i++)
        s += b->v[(size_t)i * D + k];
    return b->mass * s;
}

typedef struct {
    const char *name;
    int comp;          /* compact component: 0 = x, 1 = z */
    double value;      /* prescribed velocity */
    unsigned char *sel;
    long bad_before, bad_during, bad_after; /* violations counted per particle and step */
    double p_after, p_drift, departed;
} watch;

static void observe(const sph_body *b, watch *w, double t_start)
{
    const int before = t_start < 1e-3 - 1e-12, during = !before && t_start < 2e-3 - 1e-12;
    for (int i = 0; i < b->n; i++) {
        const double vk = b->v[(size_t)i * D + w->comp];
        const int fixed = b->fix[i] != 0;
        if (before)
            w->bad_before += fixed || b->v[(size_t)i * D] != 0 || b->v[(size_t)i * D + 1] != 0;
        else if (during)
            w->bad_during += w->sel[i] ? !(fixed && b->fix[i] == 1 << w->comp && vk == w->value)
                                       : fixed;
        else {
            w->bad_after += fixed;
            if (w->sel[i])
                w->departed = fmax(w->departed, fabs(vk - w->value));
        }
    }
    if (!before && !during) {
        const double p = momentum(b, w->comp);
        if (isnan(w->p_after))
            w->p_after = p;
        w->p_drift = fmax(w->p_drift, fabs(p - w->p_after));
    }
}

int main(void)
{
    sph_sim sim;
    if (sph_sim_init(&sim, &MODEL, 0))
        return 1;
    const sph_body *plate = &sim.bodies[0], *slab = &sim.bodies[1];
    watch w[2] = {{"plate (near)", 1, 0.3, NULL, 0, 0, 0, NAN, 0, 0},
                  {"slab (x0 < 2 mm)", 0, -0.1, NULL, 0, 0, 0, NAN, 0, 0}};
    w[0].sel = calloc((size_t)plate->n, 1);
    w[1].sel = calloc((size_t)slab->n, 1);
    int nsel[2] = {0, 0}, nclosed = 0;
    for (int q = 0; q < plate->bc_count[0]; q++)
        w[0].sel[plate->bc_list[0][q]] = 1;
    for (int i = 0; i < plate->n; i++) {
        const double x = plate->X[(size_t)i * D], z = plate->X[(size_t)i * D + 1];
        nsel[0] += w[0].sel[i];
        nclosed += w[0].sel[i] && fabs(z - 9.5e-3) < 1e-9 && x > 9e-3 && x < 21e-3;
    }
    for (int i = 0; i < slab->n; i++)
        nsel[1] += w[1].sel[i] = slab->X[(size_t)i * D] < 2e-3;
    check_close("near: particles selected", plate->bc_count[0], 12, 0);
    check_close("near: of them in the top row, 9.5 <= x0 <= 20.5 mm", nclosed, 12, 0);

    const double marks[] = {1e-3, 2e-3, MODEL.t_end};
    int mark = 0;
    while (mark < 3) {
        double dt = sph_sim_stable_dt(&sim);
        if (sim.t + dt >= marks[mark] - 1e-12)
            dt = marks[mark++] - sim.t;
        const double t_start = sim.t;
        sph_sim_step(&sim, dt);
        observe(plate, &w[0], t_start);
        observe(slab, &w[1], t_start);
    }
    printf("%ld steps to t = %.6g s\n", sim.step, sim.t);
    for (int k = 0; k < 2; k++) {
        const sph_body *b = &sim.bodies[k];
        char what[120];
        printf("%s: %d particles prescribed; after the window: momentum %.6g N s/m, largest "
               "|v - v_bc| %.4g m/s\n", w[k].name, nsel[k], w[k].p_after, w[k].departed);
        snprintf(what, sizeof what, "%s: before 1 ms, particle-steps moving or fixed", w[k].name);
        check_close(what, w[k].bad_before, 0, 0);
        snprintf(what, sizeof what, "%s: 1-2 ms, particle-steps not as prescribed", w[k].name);
        check_close(what, w[k].bad_during, 0, 0);
        snprintf(what, sizeof what, "%s: after 2 ms, particle-steps fixed", w[k].name);
        check_close(what, w[k].bad_after, 0, 0);
        /* released, the driven particles are pulled back by the body within a few steps */
        snprintf(what, sizeof what, "%s: after 2 ms, driven particles left v_bc (> 1 %%)", w[k].name);
        check_close(what, w[k].departed > 0.01 * fabs(w[k].value), 1, 0);
        /* free body: momentum constant to round-off (viscosity and stress cancel in pairs) */
        snprintf(what, sizeof what, "%s: after 2 ms, momentum drift / |momentum|", w[k].name);
        check_close(what, w[k].p_drift / fabs(w[k].p_after), 0, 1e-10);
        (void)b;
    }
    free(w[0].sel), free(w[1].sel);
    sph_sim_free(&sim);
    return check_result();
}
