/* contact.c — contact between the particles of different bodies (contact.h).
 *
 * Particles are spheres of diameter dx (3D) or cylinders of diameter dx and unit length
 * (2D, plane strain).  Particles i of body A and j of body B, at distance r = |x_i - x_j|
 * in the current configuration, overlap by delta = d_c - r, d_c = (dx_A + dx_B)/2, and
 * then push each other apart along n = (x_i - x_j)/r with
 *
 *   F_n = max(0, F_e(delta) - c v_n),  v_n = (v_i - v_j) . n   (v_n < 0: approaching)
 *   F_e = k delta^{3/2},  k = coef 4/3 E* sqrt(R*)            (3D: Hertz, touching spheres)
 *   F_e = k delta,        k = coef pi/4 E* (1 m)              (2D: cylinders, linear)
 *   1/E* = (1 - nu_A^2)/E_A + (1 - nu_B^2)/E_B,  R* = R_A R_B/(R_A + R_B),  R = dx/2
 *   c = 2 zeta sqrt(m* k_t),  k_t = dF_e/d delta,  m* = m_i m_j/(m_i + m_j)
 *   zeta = -ln e / sqrt(pi^2 + ln^2 e),  e = (e_A + e_B)/2 (the restitutions)
 *
 * c makes a linear contact (2D) bounce back with exactly the speed ratio e, and a Hertz
 * contact (3D, c following k_t) approximately so.  Friction opposes the tangential slip
 * v_t = (v_i - v_j) - v_n n with F_t = min(mu F_n, m* |v_t| / dt), mu = (mu_A + mu_B)/2:
 * Coulomb's law, except that it stops a slip within one step rather than reversing it.
 * The pair force is computed from both sides with the same arithmetic, so it is exactly
 * equal and opposite: contact conserves linear momentum to round-off.
 *
 * The energy stored in a contact is the potential of F_e (2/5 k delta^{5/2}; 1/2 k delta^2);
 * the work of the damping and friction forces is summed as dissipated energy.  The contact's
 * time-step bound is 1/omega = sqrt(m* / k_t) of the stiffest contact, and never above its
 * value at an overlap of 0.1 d_c (so a first impact finds the step already small). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "contact_law.h"
#include "contact_search.h"
#include "device.h"
#include "core/exit_codes.h"
#include "core/message.h"
#include "scene/body.h"
#include "scene/body_desc.h"
#include "scene/model.h"
#include "scene/sim.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

struct sph_contact {
    int dim, n, nbodies;
    int *base;         /* nbodies + 1: first global index of each body (its own particles) */
    int nown;          /* base[nbodies]: the particles of this process */
    int *body;         /* n: body of each global particle */
    double *dc;        /* nbodies^2 contact distances (for the search) */
    sph_pair_law *law;     /* nbodies^2 */
    double *x, *v;     /* n*dim current positions and velocities */
    int cap;           /* particles the arrays hold (own and, on many processes, partners) */
    sph_csearch search;
    double stored, dissipated, w2max;
    double level, close; /* sph_contact_closeness's level, and the closest pair's (contact_law.h) */
    double w2ref;      /* the largest reference omega^2 of two bodies' law */
    double *part;      /* 2 per block of active particles: its stored energy and power */
    int nblocks;       /* (the blocks' sums added in order: the same bits on any threads) */
};

static sph_pair_law make_law(const sph_model *m, const sph_body *A, const sph_body *B)
{
    const sph_body_desc *a = A->desc, *b = B->desc;
    const double estar = 1.0 / ((1 - a->poisson * a->poisson) / a->young +
                                (1 - b->poisson * b->poisson) / b->young);
    const double ra = 0.5 * A->dx, rb = 0.5 * B->dx, e = 0.5 * (a->restitution + b->restitution);
    sph_pair_law L;
    L.dc = ra + rb;
    L.k = m->contact->coef * (m->dim == 3 ? 4.0 / 3.0 * estar * sqrt(ra * rb / (ra + rb))
                                          : 0.25 * M_PI * estar);
    L.zeta = e >= 1 ? 0 : -log(e) / sqrt(M_PI * M_PI + log(e) * log(e));
    L.mu = 0.5 * (a->friction + b->friction);
    L.mstar = A->mass * B->mass / (A->mass + B->mass);
    const double kt = m->dim == 3 ? 1.5 * L.k * sqrt(0.1 * L.dc) : L.k;
    L.w2ref = kt / L.mstar;
    return L;
}

/* The contact state of scene s (pair laws, search), not built yet. */
static sph_contact *contact_new(const sph_sim *s)
{
    sph_contact *c = calloc(1, sizeof *c);
    const int nb = s->nbodies;
    c->dim = s->m->dim;
    c->nbodies = nb;
    c->base = calloc((size_t)nb + 1, sizeof *c->base);
    for (int i = 0; i < nb; i++)
        c->base[i + 1] = c->base[i] + s->bodies[i].nown;
    c->n = c->nown = c->cap = c->base[nb];
    c->body = malloc(((size_t)c->n + 1) * sizeof *c->body);
    for (int i = 0; i < nb; i++)
        for (int p = c->base[i]; p < c->base[i + 1]; p++)
            c->body[p] = i;
    c->dc = malloc((size_t)nb * nb * sizeof *c->dc);
    c->law = malloc((size_t)nb * nb * sizeof *c->law);
    double dxmax = 0;
    for (int i = 0; i < nb; i++) {
        dxmax = fmax(dxmax, s->bodies[i].dx);
        for (int j = 0; j < nb; j++) {
            c->law[i * nb + j] = make_law(s->m, &s->bodies[i], &s->bodies[j]);
            c->dc[i * nb + j] = c->law[i * nb + j].dc;
            if (i != j)
                c->w2ref = fmax(c->w2ref, c->law[i * nb + j].w2ref);
        }
    }
    c->x = malloc(((size_t)c->n * c->dim + 1) * sizeof *c->x);
    c->v = malloc(((size_t)c->n * c->dim + 1) * sizeof *c->v);
    const double skin = 0.5 * dxmax; /* (as the device's, sph_cuda_contact.h) */
    c->search = (sph_csearch){.n = c->n, .dim = c->dim, .nbodies = nb, .body = c->body,
                              .dc = c->dc, .skin = skin};
    c->level = 0.5 * skin;
    c->close = c->level; /* before the first step's pairs: as if touching */
    return c;
}

void sph_contact_init(sph_sim *s)
{
    if (s->m->contact && !s->contact)
        s->contact = contact_new(s);
}

/* Current positions and velocities of every own particle into c->x, c->v. */
static void gather(sph_contact *c, const sph_sim *s)
{
    for (int i = 0; i < s->nbodies; i++) {
        const sph_body *b = &s->bodies[i];
        double *x = c->x + (size_t)c->base[i] * c->dim, *v = c->v + (size_t)c->base[i] * c->dim;
        const size_t nd = (size_t)b->nown * c->dim;
#pragma omp parallel for schedule(static)
        for (size_t p = 0; p < nd; p++)
            x[p] = b->X[p] + b->u[p], v[p] = b->v[p];
    }
}

/* The current positions and velocities of the particles with candidates alone (their
 * candidates have candidates too: the pairs are symmetric), while no rebuild is due: the
 * pair forces read nothing else. */
static void gather_active(sph_contact *c, const sph_sim *s)
{
    const sph_csearch *q = &c->search;
    const int D = c->dim;
#pragma omp parallel for schedule(static) if (q->nactive > 4096)
    for (int a = 0; a < q->nactive; a++) {
        const int gi = q->active[a];
        const sph_body *b = &s->bodies[c->body[gi]];
        const size_t at = (size_t)gi * D, i = (size_t)(gi - c->base[c->body[gi]]) * D;
        for (int k = 0; k < D; k++)
            c->x[at + k] = b->X[i + k] + b->u[i + k], c->v[at + k] = b->v[i + k];
    }
}

/* The largest squared distance of n particles at X + u from x0 (D values each), D a constant
 * where it is inlined: the loop vectorises. */
static inline double moved2_of(const double *X, const double *u, const double *x0, int n,
                               const int D)
{
    double moved2 = 0;
#pragma omp parallel for simd schedule(static) reduction(max : moved2)
    for (int i = 0; i < n; i++) {
        double d2 = 0;
        for (int k = 0; k < D; k++) {
            const double d = (X[i * D + k] + u[i * D + k]) - x0[i * D + k];
            d2 += d * d;
        }
        moved2 = d2 > moved2 ? d2 : moved2;
    }
    return moved2;
}

/* Whether a particle has moved more than a quarter of the skin since the candidates were
 * built (sph_csearch_stale, on X + u as gather() would make them): one pass
 * over the bodies' arrays, where gathering every particle's position and velocity first
 * took 3 % of the flyer plates' step (7 % on two threads) while they were far apart. */
static int rebuild_due(const sph_contact *c, const sph_sim *s)
{
    const sph_csearch *q = &c->search;
    if (!q->built)
        return 1;
    double moved2 = 0;
    for (int bi = 0; bi < s->nbodies; bi++) {
        const sph_body *b = &s->bodies[bi];
        const double *x0 = q->x0 + (size_t)c->base[bi] * c->dim;
        const double m2 = c->dim == 2 ? moved2_of(b->X, b->u, x0, b->nown, 2)
                                      : moved2_of(b->X, b->u, x0, b->nown, 3);
        moved2 = m2 > moved2 ? m2 : moved2;
    }
    return sph_csearch_stale(q, moved2);
}

/* Room for n particles in the arrays of the contact set; 0, or -1 when memory runs out. */
static int reserve(sph_contact *c, int n)
{
    if (n <= c->cap)
        return 0;
    const size_t nd = (size_t)n * c->dim + 1;
    int *body = realloc(c->body, ((size_t)n + 1) * sizeof *body);
    if (body)
        c->body = body;
    double *x = realloc(c->x, nd * sizeof *x);
    if (x)
        c->x = x;
    double *v = realloc(c->v, nd * sizeof *v);
    if (v)
        c->v = v;
    if (!body || !x || !v)
        return -1;
    c->cap = n;
    return 0;
}

/* On many processes: the particles of other processes that may touch this one's
 * (sph_contact_partners), appended to the contact set after the own ones, as partners whose
 * forces their own processes compute.  The set changes from step to step, so the candidates
 * are built anew. */
static void add_partners(sph_contact *c, const sph_sim *s)
{
    const int D = c->dim, nb = c->nbodies, rec = 1 + 2 * D;
    double dcmax = 0;
    for (int k = 0; k < nb * nb; k++)
        dcmax = fmax(dcmax, c->dc[k]);
    double *in;
    const int total = sph_contact_partners(s->par, D, nb, c->nown, c->body, c->x, c->v,
                                           dcmax + c->search.skin, &in);
    if (reserve(c, c->nown + total)) {
        sph_error("out of memory for contact between processes");
        exit(SPH_EXIT_SETUP);
    }
    const double *r = in;
    for (int g = 0; g < total; g++, r += rec) {
        const size_t at = (size_t)c->nown + (size_t)g;
        c->body[at] = (int)r[0];
        memcpy(c->x + at * D, r + 1, (size_t)D * sizeof *r);
        memcpy(c->v + at * D, r + 1 + D, (size_t)D * sizeof *r);
    }
    c->n = c->nown + total;
    sph_csearch_reset(&c->search, c->n, c->body);
    free(in);
}

/* Contact force on particle i (global gi) from j (global gj), contact_law.h. */
static void pair_force(const sph_contact *c, int gi, int gj, double dt, double f[3],
                       double *stored, double *power, double *w2, double *close)
{
    const int D = c->dim, bi = c->body[gi], bj = c->body[gj];
    sph_contact_pair(&c->law[bi * c->nbodies + bj], D, c->x + (size_t)gi * D,
                     c->x + (size_t)gj * D, c->v + (size_t)gi * D, c->v + (size_t)gj * D, dt,
                     c->level, f, stored, power, w2, close);
}

void sph_contact_forces(sph_sim *s, double dt)
{
    if (!s->m->contact)
        return;
    sph_contact_init(s);
    sph_contact *c = s->contact;
    if (s->par->size > 1 || rebuild_due(c, s)) { /* (partners change from step to step) */
        gather(c, s);
        if (s->par->size > 1)
            add_partners(c, s);
        sph_csearch_build_at(&c->search, c->x); /* (due: rebuild_due has tested it) */
    } else
        gather_active(c, s);
    const sph_csearch *q = &c->search;
    enum { BLOCK = 32 };
    const int nblocks = (q->nactive + BLOCK - 1) / BLOCK;
    if (nblocks > c->nblocks) {
        free(c->part);
        c->part = malloc(2 * (size_t)nblocks * sizeof *c->part);
        c->nblocks = nblocks;
    }
    double w2 = 0, close = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(max : w2, close)
    for (int blk = 0; blk < nblocks; blk++) {
        const int end = q->nactive - blk * BLOCK < BLOCK ? q->nactive : (blk + 1) * BLOCK;
        double stored = 0, power = 0;
        for (int a = blk * BLOCK; a < end; a++) {
            const int gi = q->active[a], bi = c->body[gi];
            if (gi >= c->nown)
                continue; /* (a partner of another process: its forces are that one's) */
            double fi[3] = {0, 0, 0}, f[3];
            for (int p = q->start[gi]; p < q->start[gi + 1]; p++) {
                pair_force(c, gi, q->nb[p], dt, f, &stored, &power, &w2, &close);
                for (int k = 0; k < c->dim; k++)
                    fi[k] += f[k];
            }
            sph_body *b = &s->bodies[bi];
            double *acc = b->a + (size_t)(gi - c->base[bi]) * c->dim;
            for (int k = 0; k < c->dim; k++)
                acc[k] += fi[k] / b->mass;
        }
        c->part[2 * blk] = stored, c->part[2 * blk + 1] = power;
    }
    double stored = 0, power = 0;
    for (int blk = 0; blk < nblocks; blk++)
        stored += c->part[2 * blk], power += c->part[2 * blk + 1];
    c->stored = stored; /* (on many processes: this process's share, summed at outputs) */
    c->dissipated += power * dt;
    double most[2] = {w2, close}; /* (the time step's: over all processes) */
    s->par->max(most, 2);
    c->w2max = most[0];
    c->close = most[1];
}

const sph_pair_law *sph_contact_laws(sph_sim *s)
{
    sph_contact_init(s);
    return s->contact->law;
}

void sph_contact_set(sph_sim *s, double stored, double dissipated, double w2max, double close)
{
    sph_contact_init(s);
    s->contact->stored = stored;
    s->contact->dissipated = dissipated;
    s->contact->w2max = w2max;
    s->contact->close = close;
}

double sph_contact_level(const sph_sim *s)
{
    return s->contact ? s->contact->level : 0;
}

double sph_contact_close(const sph_sim *s)
{
    return s->contact ? s->contact->close : 0;
}

int sph_contact_checkpoint(const sph_sim *s, double sums[4], const double **x0, size_t *nx0)
{
    const sph_contact *c = s->contact;
    if (!s->m->contact)
        return 0;
    sums[0] = c ? c->stored : 0, sums[1] = c ? c->dissipated : 0, sums[2] = c ? c->w2max : 0;
    sums[3] = c ? c->close : 0;
    /* (a device target builds no lists; on many processes they are built at every step) */
    const int built = c && c->search.built && s->par->size == 1;
    *x0 = built ? c->search.x0 : NULL;
    *nx0 = built ? (size_t)c->n * (size_t)c->dim : 0;
    return 1;
}

int sph_contact_restore(sph_sim *s, const double sums[4], const double *x0, size_t nx0)
{
    sph_contact_set(s, sums[0], sums[1], sums[2], sums[3]);
    sph_contact *c = s->contact;
    if (!nx0 || s->par->size > 1)
        return 0; /* (on many processes the lists are built at every step) */
    if (nx0 != (size_t)c->n * (size_t)c->dim) {
        sph_error("cannot restart: the checkpoint's contact holds %zu coordinates, the scene %zu",
                  nx0, (size_t)c->n * (size_t)c->dim);
        return -1;
    }
    sph_csearch_build_at(&c->search, x0); /* the lists the run had, in their order */
    return 0;
}

double sph_contact_dt(const sph_sim *s, double step)
{
    const sph_contact *c = s->contact;
    if (!c)
        return INFINITY;
    double vmax2 = 0, amax2 = 0;
    for (int i = 0; i < s->nbodies; i++)
        vmax2 = fmax(vmax2, s->bodies[i].vmax2), amax2 = fmax(amax2, s->bodies[i].amax2);
    const int near = sph_contact_near(c->close, c->level, vmax2, amax2, s->dt, step);
    return sph_contact_bound(c->w2max, c->w2ref, near);
}

void sph_contact_energies(const sph_sim *s, double *stored, double *dissipated)
{
    *stored = s->contact ? s->contact->stored : 0;
    *dissipated = s->contact ? s->contact->dissipated : 0;
}

double sph_contact_w2max(const sph_sim *s)
{
    return s->contact ? s->contact->w2max : 0;
}

static void contact_free(sph_contact *c)
{
    sph_csearch_free(&c->search);
    free(c->base);
    free(c->body);
    free(c->dc);
    free(c->law);
    free(c->x);
    free(c->v);
    free(c->part);
    free(c);
}

void sph_contact_free(sph_sim *s)
{
    if (s->contact)
        contact_free(s->contact);
    s->contact = NULL;
}

/* What the pairs of two bodies closer than their contact distance hold: pairs (each counted
 * from both sides), of them coincident, the deepest overlap over d_c, their stored energy. */
typedef struct {
    double pairs, coincident, deepest, stored;
} overlap;

/* Body pair (A, B)'s overlaps among the candidates of contact c, A's own particles' side. */
static void overlaps_of(const sph_contact *c, overlap *o)
{
    const sph_csearch *q = &c->search;
    const int D = c->dim, nb = c->nbodies;
    for (int a = 0; a < q->nactive; a++) {
        const int gi = q->active[a];
        if (gi >= c->nown)
            continue; /* (a partner of another process: that one counts its side) */
        for (int p = q->start[gi]; p < q->start[gi + 1]; p++) {
            const int gj = q->nb[p], k = c->body[gi] * nb + c->body[gj];
            double r2 = 0, f[3], power = 0, w2 = 0, close = 0;
            for (int d = 0; d < D; d++) {
                const double x = c->x[(size_t)gi * D + d] - c->x[(size_t)gj * D + d];
                r2 += x * x;
            }
            const double dc = c->law[k].dc, r = sqrt(r2);
            if (!(r < dc * (1 - 1e-9)))
                continue; /* (apart, or touching up to the round-off of their positions) */
            o[k].pairs += 1;
            o[k].coincident += r <= 1e-9 * dc;
            o[k].deepest = fmax(o[k].deepest, (dc - r) / dc);
            sph_contact_pair(&c->law[k], D, c->x + (size_t)gi * D, c->x + (size_t)gj * D,
                             c->v + (size_t)gi * D, c->v + (size_t)gj * D, 1.0, c->level, f,
                             &o[k].stored, &power, &w2, &close);
        }
    }
}

/* Particles of two bodies that overlap in the configuration the run starts from (a
 * collective call on many processes, before the first step of a run not resumed): a warning
 * for each pair of bodies, and the energy their contacts store from the start, where
 * energies.csv's first row counts it.  The candidates are found by a contact state of their
 * own, so that the run's are built at its first contact pass as before. */
void sph_contact_overlaps(sph_sim *s)
{
    if (!s->m->contact || s->nbodies < 2)
        return;
    sph_contact_init(s);
    sph_contact *c = contact_new(s);
    gather(c, s);
    if (s->par->size > 1)
        add_partners(c, s);
    sph_csearch_build_at(&c->search, c->x);
    const int nb = c->nbodies;
    overlap *o = calloc((size_t)nb * nb, sizeof *o);
    overlaps_of(c, o);
    double total = 0, stored = 0; /* (this process's share of the stored energy) */
    for (int k = 0; k < nb * nb; k++) {
        double all[4] = {o[k].pairs, o[k].coincident, o[k].stored, 0};
        stored += o[k].stored;
        s->par->sum(all, 3);
        double deepest = o[k].deepest;
        s->par->max(&deepest, 1);
        o[k].pairs = all[0], o[k].coincident = all[1], o[k].deepest = deepest;
        o[k].stored = all[2];
        total += all[0];
    }
    for (int a = 0; a < nb && s->par->rank == 0; a++)
        for (int b = a + 1; b < nb; b++) {
            const overlap *x = &o[a * nb + b], *y = &o[b * nb + a];
            if (x->pairs + y->pairs == 0)
                continue;
            char coincident[160] = "";
            if (x->coincident + y->coincident > 0)
                snprintf(coincident, sizeof coincident, ", %.0f of them coincident (no force "
                         "acts between them: they pass through each other)",
                         0.5 * (x->coincident + y->coincident));
            sph_warning("bodies '%s' and '%s' overlap at the start: %.0f pairs of their "
                        "particles are closer than the contact distance %g m, the deepest by "
                        "%.3g of it%s; the contact pushes them apart from the first step, and "
                        "energies.csv's contact column holds the %g J it stores at the start",
                        s->bodies[a].desc->name, s->bodies[b].desc->name,
                        0.5 * (x->pairs + y->pairs), c->law[a * nb + b].dc,
                        fmax(x->deepest, y->deepest), coincident, x->stored + y->stored);
        }
    free(o);
    contact_free(c);
    if (total > 0)
        s->contact->stored = stored; /* (this process's share, as a contact pass leaves it) */
}
