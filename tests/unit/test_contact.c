/* test_contact.c — contact between bodies (runtime/contact/contact.c, contact_search.c):
 *  - the candidate search against brute force (2D and 3D, three bodies, different sizes);
 *  - a 3D head-on collision of two particles against Hertz's solution: largest overlap
 *    (5 m* v^2 / (4 k))^{2/5} and contact time 2.9432 delta_max / v, speed kept (e = 1),
 *    momentum kept to round-off;
 *  - 2D collisions with restitution e: the rebound speed ratio is e, and the kinetic energy
 *    lost equals the dissipated energy the contact reports;
 *  - friction: the tangential impulse is mu times the normal one while sliding, the slip
 *    never reverses, and a large mu stops it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact/contact_search.h"
#include "sphrt.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static int failures = 0;

static void check(int ok, const char *what, double got, double want)
{
    printf("%-4s %-62s got %-13.7g want %.7g\n", ok ? "ok" : "FAIL", what, got, want);
    failures += !ok;
}

static double rnd(unsigned long long *s)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

/* ------------------------------------------------------------------ search */

static double dist2(const double *x, int dim, int i, int j)
{
    double r2 = 0;
    for (int k = 0; k < dim; k++)
        r2 += (x[i * dim + k] - x[j * dim + k]) * (x[i * dim + k] - x[j * dim + k]);
    return r2;
}

/* How often j is among i's candidates. */
static int listed(const sph_csearch *c, int i, int j)
{
    int have = 0;
    for (int p = c->start[i]; p < c->start[i + 1]; p++)
        have += c->nb[p] == j;
    return have;
}

static int search_case(int dim, unsigned long long seed)
{
    enum { NB = 3 };
    const int n = 600;
    const double dx[NB] = {0.1, 0.05, 0.2};
    int *body = malloc(n * sizeof *body);
    double *x = malloc((size_t)n * dim * sizeof *x), dc[NB * NB];
    for (int a = 0; a < NB; a++)
        for (int b = 0; b < NB; b++)
            dc[a * NB + b] = 0.5 * (dx[a] + dx[b]);
    for (int i = 0; i < n; i++) {
        body[i] = i % NB;
        for (int k = 0; k < dim; k++)
            x[i * dim + k] = (dim == 2 ? 2.0 : 1.0) * rnd(&seed) - 0.3; /* also < 0 */
    }
    sph_csearch c = {.n = n, .dim = dim, .nbodies = NB, .body = body, .dc = dc, .skin = 0.1};
    sph_csearch_update(&c, x);
    int bad = 0, found = 0, expected = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            if (body[i] == body[j])
                continue;
            const double reach = dc[body[i] * NB + body[j]] + c.skin;
            const int want = dist2(x, dim, i, j) <= reach * reach, have = listed(&c, i, j);
            bad += have != want;
            found += have, expected += want;
        }
    /* moved less than skin/4: no rebuild, and every pair within half a skin of contact (the
     * closeness's level, contact_law.h) is still a candidate */
    for (int p = 0; p < n * dim; p++)
        x[p] += 0.0249 * (2 * rnd(&seed) - 1) / sqrt(dim);
    int rebuilt = sph_csearch_update(&c, x), missed = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            if (body[i] == body[j])
                continue;
            const double d = dc[body[i] * NB + body[j]] + 0.5 * c.skin;
            if (dist2(x, dim, i, j) < d * d)
                missed += listed(&c, i, j) != 1;
        }
    char what[120];
    snprintf(what, sizeof what, "%dD search: candidates equal brute force (%d pairs)", dim,
             expected);
    check(bad == 0 && found == expected, what, bad, 0);
    snprintf(what, sizeof what, "%dD search: moved < skin/4, no rebuild, none within skin/2 missed", dim);
    check(!rebuilt && !missed, what, missed + rebuilt, 0);
    sph_csearch_free(&c);
    free(body);
    free(x);
    return 0;
}

/* ------------------------------------------------------------------ two particles */

typedef struct {
    sph_model m;
    sph_contact_desc cd;
    sph_body_desc desc[2];
    sph_body b[2];
    double X[2][3], u[2][3], v[2][3], a[2][3];
    double jn, jt; /* impulse on particle 0 along and across the current normal */
    sph_sim s;
} pair_scene;

static void pair_init(pair_scene *p, int dim, double dx, const double mass[2], double e,
                      double mu)
{
    memset(p, 0, sizeof *p);
    p->cd.coef = 1;
    p->m.dim = dim;
    p->m.contact = &p->cd;
    for (int k = 0; k < 2; k++) {
        p->desc[k] = (sph_body_desc){.young = 200e9, .poisson = 0.3, .restitution = e,
                                     .friction = mu};
        p->b[k] = (sph_body){.desc = &p->desc[k], .n = 1, .nown = 1, .dim = dim, .dx = dx,
                             .mass = mass[k], .X = p->X[k], .u = p->u[k], .v = p->v[k],
                             .a = p->a[k]};
    }
    p->s = (sph_sim){.m = &p->m, .bodies = p->b, .nbodies = 2, .par = &sph_par_one};
}

/* One step of Alg. 1 (Verlet) with contact as the only force. */
/* The unit normal from particle 1 to particle 0, and the relative velocity v0 - v1. */
static void normal(const pair_scene *p, double n[3], double dv[3])
{
    double r = 0;
    for (int c = 0; c < 3; c++) {
        n[c] = p->X[0][c] + p->u[0][c] - p->X[1][c] - p->u[1][c];
        dv[c] = p->v[0][c] - p->v[1][c];
        r += n[c] * n[c];
    }
    for (int c = 0; c < 3; c++)
        n[c] /= sqrt(r);
}

static void pair_step(pair_scene *p, double dt)
{
    memset(p->a, 0, sizeof p->a);
    sph_contact_forces(&p->s, dt);
    double n[3], dv[3], an = 0, at2 = 0;
    normal(p, n, dv);
    for (int c = 0; c < 3; c++)
        an += p->a[0][c] * n[c];
    for (int c = 0; c < 3; c++)
        at2 += (p->a[0][c] - an * n[c]) * (p->a[0][c] - an * n[c]);
    p->jn += p->b[0].mass * an * dt;
    p->jt += p->b[0].mass * sqrt(at2) * dt;
    for (int k = 0; k < 2; k++)
        for (int c = 0; c < p->m.dim; c++) {
            p->v[k][c] += dt * p->a[k][c];
            p->u[k][c] += dt * p->v[k][c];
        }
}

static double gap(const pair_scene *p)
{
    double r2 = 0;
    for (int c = 0; c < p->m.dim; c++) {
        const double d = p->X[0][c] + p->u[0][c] - p->X[1][c] - p->u[1][c];
        r2 += d * d;
    }
    return sqrt(r2);
}

static void hertz_3d(void)
{
    const double dx = 0.01, mass[2] = {1.0, 3.0}, v0 = 20;
    pair_scene p;
    pair_init(&p, 3, dx, mass, 1.0, 0);
    p.X[1][0] = dx * 1.2; /* apart by 0.2 dx, approaching along x */
    p.v[0][0] = 0.75 * v0, p.v[1][0] = -0.25 * v0; /* momentum 0.75 - 0.75 = 0 */
    const double ms = mass[0] * mass[1] / (mass[0] + mass[1]);
    const double estar = 200e9 / (2 * (1 - 0.09)); /* 1/E* = 2 (1 - nu^2)/E */
    const double k = 4.0 / 3.0 * estar * sqrt(0.25 * dx); /* R* = (dx/2)(dx/2)/dx */
    const double dmax = pow(5 * ms * v0 * v0 / (4 * k), 0.4), tc = 2.9432 * dmax / v0;
    const double dt = tc / 4000;
    double t = 0, t_in = -1, t_out = -1, most = 0;
    for (int step = 0; step < 200000 && t_out < 0; step++) {
        pair_step(&p, dt);
        t += dt;
        const double overlap = dx - gap(&p);
        if (overlap > 0 && t_in < 0)
            t_in = t;
        if (overlap <= 0 && t_in >= 0)
            t_out = t;
        most = fmax(most, overlap);
    }
    const double vrel = p.v[1][0] - p.v[0][0];
    const double mom = mass[0] * p.v[0][0] + mass[1] * p.v[1][0];
    check(fabs(most / dmax - 1) < 2e-3, "3D Hertz: largest overlap / (5 m* v^2/(4k))^(2/5)",
          most / dmax, 1);
    check(fabs((t_out - t_in) / tc - 1) < 2e-3, "3D Hertz: contact time / 2.9432 dmax/v",
          (t_out - t_in) / tc, 1);
    check(fabs(vrel / v0 - 1) < 1e-3, "3D Hertz, e = 1: rebound speed / impact speed", vrel / v0,
          1);
    check(fabs(mom) < 1e-12 * mass[0] * v0, "3D Hertz: momentum (kg m/s), to round-off", mom, 0);
    sph_contact_free(&p.s);
}

/* 2D head-on collision with restitution e: returns the rebound speed ratio; *loss and *diss
 * get the kinetic energy lost and the dissipated energy reported. */
static double bounce_2d(double e, double *loss, double *diss)
{
    const double dx = 0.01, mass[2] = {2.0, 2.0}, v0 = 10;
    pair_scene p;
    pair_init(&p, 2, dx, mass, e, 0);
    p.X[1][1] = dx * 1.0001; /* 1 um apart */
    p.v[0][1] = 0.5 * v0, p.v[1][1] = -0.5 * v0;
    const double ms = 1.0, k = 0.25 * M_PI * 200e9 / (2 * (1 - 0.09));
    const double dt = M_PI * sqrt(ms / k) / 4000;
    for (int step = 0; step < 40000; step++)
        pair_step(&p, dt);
    double stored, dissipated;
    sph_contact_energies(&p.s, &stored, &dissipated);
    const double vrel = p.v[1][1] - p.v[0][1];
    *loss = 0.5 * ms * v0 * v0 - 0.5 * ms * vrel * vrel - stored;
    *diss = dissipated;
    sph_contact_free(&p.s);
    return vrel / v0;
}

/* The rebound ratio of a linear spring-dashpot contact that pulls no tension: the free
 * damped oscillation delta = v0/wd e^{-zeta w0 t} sin(wd t), left where the force
 * k delta + c delta' falls to zero (then the particles fly apart at |delta'|). */
static double clamped_restitution(double e)
{
    if (e >= 1)
        return 1;
    const double zeta = -log(e) / sqrt(M_PI * M_PI + log(e) * log(e)), wd = sqrt(1 - zeta * zeta);
    double lo = 0.5 * M_PI / wd, hi = M_PI / wd; /* w0 = 1, v0 = 1 */
    for (int it = 0; it < 200; it++) {
        const double t = 0.5 * (lo + hi), d = exp(-zeta * t) * sin(wd * t) / wd;
        const double dd = exp(-zeta * t) * (cos(wd * t) - zeta * sin(wd * t) / wd);
        *(d + 2 * zeta * dd > 0 ? &lo : &hi) = t;
    }
    const double t = lo;
    return fabs(exp(-zeta * t) * (cos(wd * t) - zeta * sin(wd * t) / wd));
}

static void restitution_2d(void)
{
    const double es[3] = {1.0, 0.95, 0.8};
    for (int k = 0; k < 3; k++) {
        double loss, diss;
        const double r = bounce_2d(es[k], &loss, &diss);
        char what[120];
        const double want = clamped_restitution(es[k]);
        snprintf(what, sizeof what, "2D linear, e = %.2f: rebound / impact speed (no tension)",
                 es[k]);
        check(fabs(r - want) < 1e-3, what, r, want);
        snprintf(what, sizeof what, "2D linear, e = %.2f: rebound / impact speed, nominal", es[k]);
        check(fabs(r - es[k]) < 0.01, what, r, es[k]);
        snprintf(what, sizeof what, "2D, e = %.2f: kinetic energy lost = dissipated (J)", es[k]);
        check(fabs(loss - diss) < 1e-3 * 50, what, loss, diss);
    }
}

/* Oblique 2D impact: normal speed 10 m/s, slip speed vt. */
static void friction_2d(double mu, double vt, double *ratio, double *vt_end, int *reversed)
{
    const double dx = 0.01, mass[2] = {2.0, 2.0};
    pair_scene p;
    pair_init(&p, 2, dx, mass, 1.0, mu);
    p.X[1][1] = dx * 1.0001; /* 1 um apart */
    p.v[0][1] = 5, p.v[1][1] = -5;
    p.v[0][0] = 0.5 * vt, p.v[1][0] = -0.5 * vt;
    const double k = 0.25 * M_PI * 200e9 / (2 * (1 - 0.09)), dt = M_PI * sqrt(1.0 / k) / 4000;
    *reversed = 0;
    for (int step = 0; step < 40000; step++) {
        pair_step(&p, dt);
        double n[3], dv[3]; /* slip along the tangent (-n_z, n_x), initially +x */
        normal(&p, n, dv);
        *reversed |= -n[1] * dv[0] + n[0] * dv[1] < -1e-12 * vt;
    }
    double n[3], dv[3], vn = 0, t2 = 0;
    normal(&p, n, dv);
    for (int c = 0; c < 3; c++)
        vn += dv[c] * n[c];
    for (int c = 0; c < 3; c++)
        t2 += (dv[c] - vn * n[c]) * (dv[c] - vn * n[c]);
    *ratio = p.jt / p.jn;
    *vt_end = sqrt(t2);
    sph_contact_free(&p.s);
}

static void friction(void)
{
    double ratio, vt_end;
    int reversed;
    friction_2d(0.3, 20, &ratio, &vt_end, &reversed);
    check(fabs(ratio - 0.3) < 1e-3, "friction mu = 0.3, sliding: tangential / normal impulse",
          ratio, 0.3);
    check(!reversed, "friction: the slip never reverses", reversed, 0);
    friction_2d(5, 1, &ratio, &vt_end, &reversed);
    check(fabs(vt_end) < 1e-9 && !reversed, "friction mu = 5: the slip stops (m/s)", vt_end, 0);
}

int main(void)
{
    search_case(2, 7);
    search_case(3, 11);
    hertz_3d();
    restitution_2d();
    friction();
    printf(failures ? "%d check(s) FAILED\n" : "all checks passed\n", failures);
    return failures ? 1 : 0;
}
