/* test_partition.c — the decomposition of a body for runs on many processes (partition.h):
 * global ids from the lattice, recursive coordinate bisection by counting equal to the one
 * from filled points, every particle in one part, the balance, each part's own particles and
 * halo filled by that part alone against the serial neighbour lists, and every serial pair
 * owned by exactly one part under both pair rules.  Bodies: blocks in 2D and 3D, a block with a hole off its centre
 * (2D), a cylinder (3D) and a block with nbsrange 1 (2D); 1, 2, 3, 4 and 7 parts. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom/fill.h"
#include "geom/partition.h"
#include "geom/region.h"
#include "pairs/neighbours.h"
#include "unit_check.h"

/* A body of the test: its region, dimension, spacing, kernel support and nbsrange. */
typedef struct {
    const char *name;
    sph_shape prims[2];
    int nprims, dim, range;
    double dx;
} body_case;

/* A filled body with everything the checks compare against. */
typedef struct {
    const body_case *bc;
    sph_region r;
    sph_lattice L;
    int n;
    double *X, radius;
    int64_t *id;
    int *sorted;          /* particle indices in id order */
    int *start, *nb;      /* serial neighbour lists */
} body;

static double worst_balance = 0.0;

static int64_t *cmp_ids;
static int by_id(const void *a, const void *b)
{
    const int64_t x = cmp_ids[*(const int *)a], y = cmp_ids[*(const int *)b];
    return (x > y) - (x < y);
}

static int cmp_i64(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

/* The particle of id v (-1: none), by bisection in the id order. */
static int index_of(const body *B, int64_t v)
{
    int lo = 0, hi = B->n - 1;
    while (lo <= hi) {
        const int m = (lo + hi) / 2;
        const int64_t w = B->id[B->sorted[m]];
        if (w == v)
            return B->sorted[m];
        if (w < v)
            lo = m + 1;
        else
            hi = m - 1;
    }
    return -1;
}

/* Fills the body, its ids and its serial neighbour lists (coefh 1: radius 2 sqrt(dim) dx). */
static void body_fill(body *B, const body_case *bc)
{
    memset(B, 0, sizeof *B);
    B->bc = bc;
    B->r = (sph_region){ .prims = bc->prims, .n = bc->nprims };
    B->n = sph_fill_region(&B->r, bc->dim, bc->dx, 0.0, &B->X);
    sph_fill_lattice(&B->r, bc->dim, bc->dx, 0.0, &B->L);
    B->radius = 2.0 * sqrt((double)bc->dim) * bc->dx;
    B->id = malloc((size_t)B->n * sizeof *B->id);
    B->sorted = malloc((size_t)B->n * sizeof *B->sorted);
    for (int i = 0; i < B->n; i++) {
        B->id[i] = sph_lattice_id(&B->L, B->X + (size_t)i * bc->dim);
        B->sorted[i] = i;
    }
    cmp_ids = B->id;
    qsort(B->sorted, (size_t)B->n, sizeof *B->sorted, by_id);
    sph_neighbours(B->X, B->n, bc->dim, B->radius, bc->range, bc->dx, &B->start, &B->nb);
}

static void body_free(body *B)
{
    free(B->X), free(B->id), free(B->sorted), free(B->start), free(B->nb);
}

/* Ids unique, and each id's lattice point is the filled position bit for bit. */
static void check_ids(const body *B)
{
    char what[160];
    int dup = 0, moved = 0;
    for (int m = 1; m < B->n; m++)
        dup += B->id[B->sorted[m]] == B->id[B->sorted[m - 1]];
    for (int i = 0; i < B->n; i++) {
        long k[3];
        double x[3];
        sph_lattice_coords(&B->L, B->X + (size_t)i * B->L.dim, k);
        sph_lattice_point(&B->L, k, x);
        moved += memcmp(x, B->X + (size_t)i * B->L.dim, (size_t)B->L.dim * sizeof *x) != 0 ||
                 sph_lattice_id_of(&B->L, k) != B->id[i];
    }
    snprintf(what, sizeof what, "%s: %d ids unique, lattice points = positions", B->bc->name,
             B->n);
    check(dup == 0 && moved == 0, what, dup + moved, 0);
}

/* Counting in boxes without filling: the whole lattice and a box of a third of it. */
static void check_counts(const body *B)
{
    char what[160];
    long lo[3] = { 0, 0, 0 }, hi[3], sub_lo[3], sub_hi[3];
    for (int c = 0; c < 3; c++) {
        hi[c] = B->L.nk[c] - 1;
        sub_lo[c] = B->L.nk[c] / 3;
        sub_hi[c] = c < B->L.dim ? 2 * B->L.nk[c] / 3 : 0;
    }
    long inside = 0;
    for (int i = 0; i < B->n; i++) {
        long k[3], in = 1;
        sph_lattice_coords(&B->L, B->X + (size_t)i * B->L.dim, k);
        for (int c = 0; c < 3; c++)
            in &= k[c] >= sub_lo[c] && k[c] <= sub_hi[c];
        inside += in;
    }
    const long all = sph_lattice_count(&B->r, &B->L, lo, hi);
    const long sub = sph_lattice_count(&B->r, &B->L, sub_lo, sub_hi);
    snprintf(what, sizeof what, "%s: counted %ld and %ld in a sub-box (filled %d, %ld)",
             B->bc->name, all, sub, B->n, inside);
    check(all == B->n && sub == inside, what, (double)labs(all - B->n) + labs(sub - inside), 0);
}

/* The tree by counting equals the tree from the filled points, node by node, and assigns
 * every particle the part the points' tree gave it. */
static void check_same_tree(const body *B, const sph_rcb *P, const sph_rcb *C, const int *part)
{
    char what[160];
    int diff = 0;
    for (int x = 0; x < P->nnodes; x++) {
        const sph_rcb_node *a = &P->node[x], *b = &C->node[x];
        diff += !a->done || !b->done || a->count != b->count || a->axis != b->axis ||
                a->plane != b->plane || a->cut_id != b->cut_id ||
                memcmp(a->lo, b->lo, sizeof a->lo) || memcmp(a->hi, b->hi, sizeof a->hi);
    }
    for (int i = 0; i < B->n; i++) {
        long k[3];
        sph_lattice_coords(&B->L, B->X + (size_t)i * B->L.dim, k);
        diff += sph_rcb_owner(C, &B->L, k) != part[i];
    }
    snprintf(what, sizeof what, "%s, %d parts: counted tree = points' tree (%d nodes)",
             B->bc->name, P->nparts, P->nnodes);
    check(diff == 0, what, diff, 0);
}

/* Every particle in one part, leaf counts right, balance max / mean - 1 within 5 %. */
static void check_parts(const body *B, const sph_rcb *P, const int *part)
{
    char what[160];
    const int N = P->nparts;
    long *cnt = calloc((size_t)N, sizeof *cnt), bad = 0, mx = 0;
    for (int i = 0; i < B->n; i++) {
        if (part[i] < 0 || part[i] >= N)
            bad++;
        else
            cnt[part[i]]++;
    }
    for (int x = 0; x < P->nnodes; x++)
        if (P->node[x].left < 0)
            bad += P->node[x].count != cnt[P->node[x].first];
    for (int p = 0; p < N; p++)
        mx = cnt[p] > mx ? cnt[p] : mx;
    const double mean = (double)B->n / N, balance = mx / mean - 1.0;
    worst_balance = fmax(worst_balance, balance);
    snprintf(what, sizeof what, "%s, %d parts: one part each, balance (max %ld, mean %.1f)",
             B->bc->name, N, mx, mean);
    check(bad == 0 && balance <= 0.05, what, balance, 0.05);
    if (N == 3) { /* n parts split n/2 : n - n/2, the points in proportion */
        const sph_rcb_node *l = &P->node[P->node[0].left];
        snprintf(what, sizeof what, "%s, 3 parts: the first cut 1 : 2 (left %ld of %d)",
                 B->bc->name, l->count, B->n);
        check(l->nparts == 1 && labs(3 * l->count - B->n) <= 2, what, l->count, B->n / 3.0);
    }
    free(cnt);
}

/* The serial halo of part p: stamp[j] = p for every j of another part next to part p. */
static long serial_halo(const body *B, const int *part, int p, int *stamp)
{
    long h = 0;
    for (int i = 0; i < B->n; i++)
        for (int q = B->start[i]; part[i] == p && q < B->start[i + 1]; q++) {
            const int j = B->nb[q];
            if (part[j] != p && stamp[j] != p)
                stamp[j] = p, h++;
        }
    return h;
}

/* One pair seen by a part: its ids, smaller first. */
typedef struct {
    int64_t a, b;
} id_pair;

static int cmp_pair(const void *x, const void *y)
{
    const id_pair *p = x, *q = y;
    return p->a != q->a ? (p->a > q->a) - (p->a < q->a) : (p->b > q->b) - (p->b < q->b);
}

/* What part p computes alone: its tree nodes, its own particles and halo (against the serial
 * ones), its particles' neighbour lists from its own points (against the serial lists), and
 * the pairs each rule gives it (appended to g[rule]). */
typedef struct {
    long bad_own, bad_halo, bad_lists, bad_reach, nodes, halo;
} local_result;

/* What the parts together gave: the pairs they own and their own ids. */
typedef struct {
    id_pair *pairs;
    long npairs;
    int64_t *own_ids;
    long nown;
} gathered;

static void local_part(const body *B, const int *part, int N, int p, int *stamp, gathered g[2],
                       local_result *res)
{
    const int D = B->L.dim;
    const long margin = sph_lattice_margin(&B->L, B->radius, B->bc->range);
    sph_rcb T;
    sph_rcb_local_set s;
    sph_rcb_count(&B->r, &B->L, N, p, margin, &T);
    for (int x = 0; x < T.nnodes; x++)
        res->nodes += T.node[x].done;
    if (sph_rcb_local(&B->r, &B->L, &T, p, B->radius, B->bc->range, &s) < 0) {
        res->bad_own++;
        sph_rcb_free(&T);
        return;
    }
    /* own: exactly the particles of part p, in id order */
    long mine = 0;
    for (int i = 0; i < B->n; i++)
        mine += part[i] == p;
    res->bad_own += mine != s.nown;
    for (int q = 0; q < s.nown; q++) {
        const int i = index_of(B, s.own_id[q]);
        res->bad_own += i < 0 || part[i] != p || (q > 0 && s.own_id[q] <= s.own_id[q - 1]) ||
                        memcmp(s.own_X + (size_t)q * D, B->X + (size_t)i * D, D * sizeof(double));
        g[0].own_ids[g[0].nown++] = s.own_id[q];
    }
    /* halo: exactly the serial halo, with its parts */
    const long h = serial_halo(B, part, p, stamp);
    res->halo += s.nhalo;
    res->bad_halo += h != s.nhalo;
    for (int q = 0; q < s.nhalo; q++) {
        const int j = index_of(B, s.halo_id[q]);
        res->bad_halo += j < 0 || stamp[j] != p || part[j] != s.halo_part[q] ||
                         memcmp(s.halo_X + (size_t)q * D, B->X + (size_t)j * D,
                                D * sizeof(double));
    }
    /* the neighbour lists of its own particles from its own points and halo */
    const int nl = s.nown + s.nhalo;
    double *X = malloc((size_t)(nl ? nl : 1) * D * sizeof *X);
    int64_t *lid = malloc((size_t)(nl ? nl : 1) * sizeof *lid);
    int *lpart = malloc((size_t)(nl ? nl : 1) * sizeof *lpart), *st, *nb;
    for (int q = 0; q < nl; q++) {
        const int own = q < s.nown;
        memcpy(X + (size_t)q * D, own ? s.own_X + (size_t)q * D : s.halo_X + (size_t)(q - s.nown) * D,
               D * sizeof *X);
        lid[q] = own ? s.own_id[q] : s.halo_id[q - s.nown];
        lpart[q] = own ? p : s.halo_part[q - s.nown];
    }
    sph_neighbours(X, nl, D, B->radius, B->bc->range, B->bc->dx, &st, &nb);
    for (int q = 0; q < s.nown; q++) {
        const int i = index_of(B, lid[q]);
        const int deg = B->start[i + 1] - B->start[i], ldeg = st[q + 1] - st[q];
        int64_t *mine_ids = malloc((size_t)(ldeg + 1) * sizeof *mine_ids);
        int64_t *ser_ids = malloc((size_t)(deg + 1) * sizeof *ser_ids);
        for (int t = 0; t < deg; t++)
            ser_ids[t] = B->id[B->nb[B->start[i] + t]];
        for (int t = 0; t < ldeg; t++) {
            const int b = nb[st[q] + t];
            mine_ids[t] = lid[b];
            /* the rules: each unordered pair once, kept where the rule gives it to part p */
            if (b < s.nown && lid[b] < lid[q])
                continue;
            const int owner[2] = { sph_pair_owner(lid[q], p, lid[b], lpart[b]),
                                   sph_pair_owner_lower(p, lpart[b]) };
            for (int rule = 0; rule < 2; rule++) {
                if (owner[rule] != p)
                    continue;
                g[rule].pairs[g[rule].npairs++] =
                    (id_pair){ lid[q] < lid[b] ? lid[q] : lid[b], lid[q] < lid[b] ? lid[b] : lid[q] };
                res->bad_reach += !(b < s.nown || stamp[index_of(B, lid[b])] == p);
            }
        }
        qsort(ser_ids, (size_t)deg, sizeof *ser_ids, cmp_i64);
        qsort(mine_ids, (size_t)ldeg, sizeof *mine_ids, cmp_i64);
        res->bad_lists += ldeg != deg || memcmp(ser_ids, mine_ids, (size_t)deg * sizeof *ser_ids);
        free(mine_ids), free(ser_ids);
    }
    free(X), free(lid), free(lpart), free(st), free(nb);
    sph_rcb_local_free(&s);
    sph_rcb_free(&T);
}

/* Every unordered serial pair once among the pairs all parts own. */
static long check_pairs_once(const body *B, id_pair *pairs, long npairs)
{
    long serial = 0, bad = 0;
    for (int i = 0; i < B->n; i++)
        for (int q = B->start[i]; q < B->start[i + 1]; q++)
            serial += B->id[B->nb[q]] > B->id[i];
    qsort(pairs, (size_t)npairs, sizeof *pairs, cmp_pair);
    for (long t = 1; t < npairs; t++)
        bad += !cmp_pair(&pairs[t], &pairs[t - 1]);
    for (long t = 0; t < npairs; t++) { /* each one a serial pair */
        const int i = index_of(B, pairs[t].a), j = index_of(B, pairs[t].b);
        int found = 0;
        for (int q = i >= 0 ? B->start[i] : 0; i >= 0 && q < B->start[i + 1]; q++)
            found |= B->nb[q] == j;
        bad += !found;
    }
    return bad + labs(serial - npairs);
}

/* All checks of one body for N parts; own_ids receives every part's own ids (sorted). */
static void check_body_parts(const body *B, int N, int64_t *own_ids)
{
    char what[200];
    int *part = malloc((size_t)B->n * sizeof *part);
    sph_rcb P, C;
    sph_rcb_points(&B->L, B->X, B->n, N, &P, part);
    sph_rcb_count(&B->r, &B->L, N, -1, 0, &C);
    check_same_tree(B, &P, &C, part);
    check_parts(B, &P, part);

    long *halo = calloc((size_t)N, sizeof *halo), hdiff = 0;
    int *stamp = malloc((size_t)B->n * sizeof *stamp);
    sph_rcb_halo_sizes(&B->L, B->X, B->n, part, N, B->radius, B->bc->range, halo);
    for (int i = 0; i < B->n; i++)
        stamp[i] = -1;
    for (int p = 0; p < N; p++)
        hdiff += labs(serial_halo(B, part, p, stamp) - halo[p]);
    snprintf(what, sizeof what, "%s, %d parts: halo sizes from the lattice = serial lists",
             B->bc->name, N);
    check(hdiff == 0, what, hdiff, 0);

    local_result res = { 0 };
    gathered g[2] = { { malloc((size_t)(B->start[B->n] + 1) * sizeof(id_pair)), 0, own_ids, 0 },
                      { malloc((size_t)(B->start[B->n] + 1) * sizeof(id_pair)), 0, NULL, 0 } };
    for (int p = 0; p < N; p++) {
        for (int i = 0; i < B->n; i++)
            stamp[i] = -1;
        local_part(B, part, N, p, stamp, g, &res);
    }
    const long nown = g[0].nown;
    qsort(own_ids, (size_t)nown, sizeof *own_ids, cmp_i64);
    snprintf(what, sizeof what, "%s, %d parts: each part fills its own particles alone",
             B->bc->name, N);
    check(res.bad_own == 0 && nown == B->n, what, res.bad_own + labs(nown - B->n), 0);
    snprintf(what, sizeof what, "%s, %d parts: its halo = the serial halo (%ld in all)",
             B->bc->name, N, res.halo);
    check(res.bad_halo == 0, what, res.bad_halo, 0);
    snprintf(what, sizeof what, "%s, %d parts: own neighbour lists = serial lists",
             B->bc->name, N);
    check(res.bad_lists == 0, what, res.bad_lists, 0);
    for (int rule = 0; rule < 2; rule++) {
        snprintf(what, sizeof what, "%s, %d parts: %ld serial pairs owned once (%s rule)",
                 B->bc->name, N, g[rule].npairs, rule ? "lower part" : "smaller id");
        const long bad_pairs = check_pairs_once(B, g[rule].pairs, g[rule].npairs);
        check(bad_pairs == 0, what, bad_pairs, 0);
    }
    snprintf(what, sizeof what, "%s, %d parts: owned pairs reach own particles and halo only",
             B->bc->name, N);
    check(res.bad_reach == 0, what, res.bad_reach, 0);
    printf("     %s, %d parts: a part computes %.1f of the tree's %d nodes\n", B->bc->name, N,
           (double)res.nodes / N, P.nnodes);
    free(g[0].pairs), free(g[1].pairs), free(halo), free(stamp), free(part);
    sph_rcb_free(&P), sph_rcb_free(&C);
}

static void test_body(const body_case *bc)
{
    static const int parts[] = { 1, 2, 3, 4, 7 };
    char what[160];
    body B;
    body_fill(&B, bc);
    check_ids(&B);
    check_counts(&B);
    int64_t *ids1 = malloc((size_t)B.n * sizeof *ids1), *ids = malloc((size_t)B.n * sizeof *ids);
    for (size_t q = 0; q < sizeof parts / sizeof *parts; q++) {
        check_body_parts(&B, parts[q], q == 0 ? ids1 : ids);
        if (parts[q] == 4) {
            snprintf(what, sizeof what, "%s: the ids of 4 parts = those of 1", bc->name);
            check(!memcmp(ids1, ids, (size_t)B.n * sizeof *ids), what, 0, 0);
        }
    }
    free(ids1), free(ids);
    body_free(&B);
}

/* An empty part: more parts than particles. */
static void test_more_parts_than_particles(void)
{
    char what[160];
    sph_shape box = { SPH_BOX, { 0, 0, 0 }, { 3e-3, 0, 2e-3 }, 0, 0, NULL, NULL, 0 };
    sph_region r = { .prims = &box, .n = 1 };
    sph_lattice L;
    double *X;
    const int n = sph_fill_region(&r, 2, 1e-3, 0.0, &X);
    sph_fill_lattice(&r, 2, 1e-3, 0.0, &L);
    int part[6], cnt[8] = { 0 }, diff = 0;
    sph_rcb P, C;
    sph_rcb_points(&L, X, n, 8, &P, part);
    sph_rcb_count(&r, &L, 8, -1, 0, &C);
    for (int i = 0; i < n; i++)
        cnt[part[i]]++;
    for (int x = 0; x < P.nnodes; x++)
        diff += P.node[x].count != C.node[x].count || P.node[x].cut_id != C.node[x].cut_id;
    int empty = 0, most = 0;
    for (int p = 0; p < 8; p++)
        empty += cnt[p] == 0, most = cnt[p] > most ? cnt[p] : most;
    snprintf(what, sizeof what, "6 particles in 8 parts: 2 empty, none with 2, trees equal");
    check(n == 6 && empty == 2 && most == 1 && diff == 0, what, empty, 2);
    sph_rcb_free(&P), sph_rcb_free(&C);
    free(X);
}

/* A body large enough that the counting passes share their boxes among threads: a block
 * with a cylindrical hole along y, off its centre (about 94 000 particles), in 7 and 64 parts:
 * the counted tree equals the points' tree, and the balance. */
static void test_large_tree(void)
{
    char what[160];
    const sph_shape prims[2] = {
        { SPH_BOX, { 0, 0, 0 }, { 80e-3, 40e-3, 32e-3 }, 0, 0, NULL, NULL, 0 },
        { SPH_CYLINDER, { 30e-3, -1e-3, 14e-3 }, { 30e-3, 41e-3, 14e-3 }, 9e-3, 1, NULL, NULL, 0 },
    };
    sph_region r = { .prims = prims, .n = 2 };
    sph_lattice L;
    double *X;
    const int n = sph_fill_region(&r, 3, 1e-3, 0.0, &X);
    sph_fill_lattice(&r, 3, 1e-3, 0.0, &L);
    int *part = malloc((size_t)n * sizeof *part);
    for (int N = 7; N <= 64; N += 57) {
        sph_rcb P, C;
        sph_rcb_points(&L, X, n, N, &P, part);
        sph_rcb_count(&r, &L, N, -1, 0, &C);
        int diff = 0;
        long mx = 0;
        for (int x = 0; x < P.nnodes; x++) {
            const sph_rcb_node *a = &P.node[x], *b = &C.node[x];
            diff += a->count != b->count || a->axis != b->axis || a->plane != b->plane ||
                    a->cut_id != b->cut_id || memcmp(a->lo, b->lo, sizeof a->lo) ||
                    memcmp(a->hi, b->hi, sizeof a->hi);
            mx = a->left < 0 && a->count > mx ? a->count : mx;
        }
        const double balance = mx / ((double)n / N) - 1.0;
        worst_balance = fmax(worst_balance, balance);
        snprintf(what, sizeof what, "block with a hole, %d particles, %d parts: counted tree = "
                 "points' tree (%d differ), balance", n, N, diff);
        check(diff == 0 && balance <= 0.05, what, balance, 0.05);
        sph_rcb_free(&P), sph_rcb_free(&C);
    }
    free(part), free(X);
}

int main(void)
{
    static const body_case cases[] = {
        { "2D block 40x20", { { SPH_BOX, { 0, 0, 0 }, { 40e-3, 0, 20e-3 }, 0, 0, NULL, NULL, 0 } },
          1, 2, 0, 1e-3 },
        { "3D block 12x8x6", { { SPH_BOX, { 0, 0, 0 }, { 12e-3, 8e-3, 6e-3 }, 0, 0, NULL, NULL,
                                 0 } }, 1, 3, 0, 1e-3 },
        { "2D block minus a block", { { SPH_BOX, { 0, 0, 0 }, { 30e-3, 0, 24e-3 }, 0, 0, NULL,
                                        NULL, 0 },
                                      { SPH_BOX, { 8e-3, 0, 6e-3 }, { 20e-3, 0, 16e-3 }, 0, 1,
                                        NULL, NULL, 0 } }, 2, 2, 0, 1e-3 },
        { "3D cylinder r 5 l 14", { { SPH_CYLINDER, { 0, 0, 0 }, { 14e-3, 0, 0 }, 5e-3, 0, NULL,
                                      NULL, 0 } }, 1, 3, 0, 1e-3 },
        { "2D block 30x17, nbsrange 1", { { SPH_BOX, { 0, 0, 0 }, { 30e-3, 0, 17e-3 }, 0, 0,
                                            NULL, NULL, 0 } }, 1, 2, 1, 1e-3 },
    };
    for (size_t q = 0; q < sizeof cases / sizeof *cases; q++)
        test_body(&cases[q]);
    test_more_parts_than_particles();
    test_large_tree();
    printf("worst balance (largest part / mean - 1): %.4f\n", worst_balance);
    printf("%s: %d failure(s)\n", failures ? "FAILED" : "PASSED", failures);
    return failures != 0;
}
