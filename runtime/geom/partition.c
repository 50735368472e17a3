/* partition.c — recursive coordinate bisection of a body's lattice into parts, global ids,
 * halos and the pair rules (partition.h; docs/mpi.md).
 *
 * Order of the points of a node along an axis c: by the key (k[c], id), lexicographic.  A cut
 * gives the left child the first `target` points in that order, so its threshold is the key
 * of the first point of the right child: (plane, cut_id).  Within a plane the ids run with
 * the plane's other lattice coordinates, the slowest first, so the counting builder finds
 * the threshold by visiting one plane in that order.
 *
 * The counting builder visits each node's box once (its points' histograms along every
 * axis give its extent and, along the cut axis, the plane of the cut), then the cut plane
 * once more: a level of the tree costs one pass over the body's lattice box, the whole tree
 * depth passes; a process that needs only its path and its neighbourhood pays about two.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "partition.h"
#include "region.h"
#include "core/defs.h"

/* Boxes of fewer lattice points are visited by one thread: the many small nodes deep in the
 * tree cost more to share out than to count (much more on a machine whose cores are busy). */
#define PARALLEL_POINTS 65536

/* ------------------------------------------------------------------ lattice */

void sph_lattice_coords(const sph_lattice *L, const double *x, long k[3])
{
    for (int c = 0; c < 3; c++)
        k[c] = c < L->dim ? (long)nearbyint((x[c] - L->lo[c]) / L->dx - 0.5) : 0;
}

int64_t sph_lattice_id_of(const sph_lattice *L, const long k[3])
{
    return (int64_t)k[0] + (int64_t)L->nk[0] * ((int64_t)k[1] + (int64_t)L->nk[1] * k[2]);
}

int64_t sph_lattice_id(const sph_lattice *L, const double *x)
{
    long k[3];
    sph_lattice_coords(L, x, k);
    return sph_lattice_id_of(L, k);
}

void sph_lattice_point(const sph_lattice *L, const long k[3], double *x)
{
    for (int c = 0; c < L->dim; c++)
        x[c] = L->lo[c] + ((double)k[c] + 0.5) * L->dx; /* fill.c's lattice_point */
}

/* Whether lattice point k is one sph_fill_region keeps (its membership test and tolerance). */
static int lattice_in(const sph_region *r, const sph_lattice *L, const long k[3])
{
    double x[3], p[3] = { 0.0, L->y_plane, 0.0 };
    sph_lattice_point(L, k, x);
    for (int c = 0; c < L->dim; c++)
        p[sph_axis(L->dim, c)] = x[c];
    return sph_region_contains_tol_dim(r, L->dim, p, 1e-9 * L->dx);
}

/* Box lo..hi clipped to the lattice into a..b; 0 when nothing is left. */
static int clip_box(const sph_lattice *L, const long lo[3], const long hi[3], long a[3],
                    long b[3])
{
    int any = 1;
    for (int c = 0; c < 3; c++) {
        a[c] = lo[c] > 0 ? lo[c] : 0;
        b[c] = hi[c] < L->nk[c] - 1 ? hi[c] : L->nk[c] - 1;
        any &= a[c] <= b[c];
    }
    return any;
}

long sph_lattice_count(const sph_region *r, const sph_lattice *L, const long lo[3],
                       const long hi[3])
{
    long a[3], b[3], k[3], n = 0;
    if (!clip_box(L, lo, hi, a, b))
        return 0;
    for (k[2] = a[2]; k[2] <= b[2]; k[2]++)
        for (k[1] = a[1]; k[1] <= b[1]; k[1]++)
            for (k[0] = a[0]; k[0] <= b[0]; k[0]++)
                n += lattice_in(r, L, k);
    return n;
}

long sph_lattice_margin(const sph_lattice *L, double radius, int range)
{
    double cut = radius * (1.0 + 1e-9); /* neighbours.c's criterion */
    if (range > 0)
        cut = fmin(cut, (range + 0.01) * L->dx);
    return cut > 0.0 ? (long)floor(cut / L->dx * (1.0 + 1e-9)) : 0;
}

int sph_lattice_offsets(const sph_lattice *L, double radius, int range, long **off)
{
    const long m = sph_lattice_margin(L, radius, range);
    const double rc = radius * (1.0 + 1e-9), rc2 = radius > 0.0 ? rc * rc : -1.0;
    const double lim = range > 0 ? (range + 0.01) * L->dx : HUGE_VAL;
    const long w = 2 * m + 1, total = L->dim == 2 ? w * w : w * w * w;
    *off = malloc((size_t)total * 3 * sizeof **off);
    if (!*off)
        return -1;
    int n = 0;
    for (long q = 0; q < total; q++) {
        long o[3] = { q % w - m, q / w % w - m, L->dim == 3 ? q / (w * w) - m : 0 };
        double d2 = 0.0;
        int ok = o[0] || o[1] || o[2];
        for (int c = 0; c < L->dim; c++) {
            const double d = (double)o[c] * L->dx;
            d2 += d * d;
            ok &= fabs(d) <= lim;
        }
        if (ok && d2 <= rc2)
            memcpy(*off + 3 * (size_t)n++, o, sizeof o);
    }
    return n;
}

/* ------------------------------------------------------------------ the tree */

/* The nodes of a tree of nparts parts, every parent before its children, none computed. */
static int rcb_init(sph_rcb *T, int nparts)
{
    T->nparts = nparts;
    T->nnodes = 1;
    T->node = nparts > 0 ? calloc((size_t)(2 * nparts - 1), sizeof *T->node) : NULL;
    if (!T->node)
        return -1;
    T->node[0] = (sph_rcb_node){ .first = 0, .nparts = nparts, .parent = -1, .left = -1,
                                 .right = -1 };
    for (int x = 0; x < T->nnodes; x++) {
        sph_rcb_node *n = &T->node[x];
        if (n->nparts < 2)
            continue;
        const int nl = n->nparts / 2;
        n->left = T->nnodes++;
        n->right = T->nnodes++;
        T->node[n->left] = (sph_rcb_node){ .first = n->first, .nparts = nl, .parent = x,
                                           .left = -1, .right = -1 };
        T->node[n->right] = (sph_rcb_node){ .first = n->first + nl, .nparts = n->nparts - nl,
                                            .parent = x, .left = -1, .right = -1 };
    }
    return 0;
}

void sph_rcb_free(sph_rcb *T)
{
    free(T->node);
    T->node = NULL;
    T->nnodes = T->nparts = 0;
}

/* Whether key (k[axis], id) comes before the cut (plane, cut_id). */
static int key_less(const long k[3], int64_t id, int axis, long plane, int64_t cut_id)
{
    return k[axis] < plane || (k[axis] == plane && id < cut_id);
}

/* Whether a lattice point lies in node x (its ancestors' cuts send it there). */
static int in_node(const sph_rcb *T, int x, const long k[3], int64_t id)
{
    for (int p = T->node[x].parent; p >= 0; x = p, p = T->node[p].parent) {
        const sph_rcb_node *q = &T->node[p];
        if (key_less(k, id, q->axis, q->plane, q->cut_id) != (q->left == x))
            return 0;
    }
    return 1;
}

/* A node without points: an empty box and a cut that sends nothing anywhere. */
static void set_empty(sph_rcb_node *n)
{
    n->count = 0;
    for (int c = 0; c < 3; c++)
        n->lo[c] = n->hi[c] = 0;
    n->hi[0] = -1;
    n->axis = 0;
    n->plane = 0;
    n->cut_id = 0;
}

/* The component of the box's longest lattice extent (ties: the lower one). */
static int longest_axis(const sph_rcb_node *n, int dim)
{
    int a = 0;
    for (int c = 1; c < dim; c++)
        if (n->hi[c] - n->lo[c] > n->hi[a] - n->lo[a])
            a = c;
    return a;
}

/* The left child's points: round(count (nparts / 2) / nparts), so n parts split n/2 : n - n/2
 * with the points in proportion. */
static long left_target(const sph_rcb_node *n)
{
    const int64_t nl = n->nparts / 2;
    return (long)((2 * (int64_t)n->count * nl + n->nparts) / (2 * (int64_t)n->nparts));
}

/* The boxes the cut of node x leaves its children (before they are computed). */
static void set_children(sph_rcb *T, int x)
{
    const sph_rcb_node *n = &T->node[x];
    if (n->left < 0)
        return;
    sph_rcb_node *a = &T->node[n->left], *b = &T->node[n->right];
    if (n->count == 0) {
        set_empty(a);
        set_empty(b);
        return;
    }
    memcpy(a->lo, n->lo, sizeof a->lo), memcpy(a->hi, n->hi, sizeof a->hi);
    memcpy(b->lo, n->lo, sizeof b->lo), memcpy(b->hi, n->hi, sizeof b->hi);
    if (a->hi[n->axis] > n->plane)
        a->hi[n->axis] = n->plane;
    b->lo[n->axis] = n->plane;
}

/* ------------------------------------------------------------------ by counting */

/* One row k[1], k[2] of node x's box a..b: its points counted into h[c] (entry k - a[c]). */
static long row_histograms(const sph_region *r, const sph_lattice *L, const sph_rcb *T, int x,
                           const long a[3], const long b[3], long k1, long k2, long *h[3])
{
    long k[3] = { 0, k1, k2 }, count = 0;
    for (k[0] = a[0]; k[0] <= b[0]; k[0]++) {
        if (!in_node(T, x, k, sph_lattice_id_of(L, k)) || !lattice_in(r, L, k))
            continue;
        count++;
        for (int c = 0; c < 3; c++)
            h[c][k[c] - a[c]]++;
    }
    return count;
}

/* One pass over node x's box a..b: its points counted along every axis into hist[c] (entry
 * k - a[c]), each thread into its own copy first.  Returns the count, -1 when memory runs
 * out. */
static long node_histograms(const sph_region *r, const sph_lattice *L, const sph_rcb *T, int x,
                            const long a[3], const long b[3], long *hist[3])
{
    long count = 0;
    int failed = 0;
    const long volume = (b[0] - a[0] + 1) * (b[1] - a[1] + 1) * (b[2] - a[2] + 1);
#pragma omp parallel reduction(+ : count) reduction(| : failed) if (volume >= PARALLEL_POINTS)
    {
        long *h[3];
        int ok = 1;
        for (int c = 0; c < 3; c++)
            ok &= (h[c] = calloc((size_t)(b[c] - a[c] + 1), sizeof **h)) != NULL;
        failed |= !ok;
#pragma omp for collapse(2) schedule(dynamic, 16)
        for (long k2 = a[2]; k2 <= b[2]; k2++)
            for (long k1 = a[1]; k1 <= b[1]; k1++)
                count += ok ? row_histograms(r, L, T, x, a, b, k1, k2, h) : 0;
#pragma omp critical(sph_rcb_histograms)
        for (int c = 0; c < 3 && ok; c++)
            for (long q = 0; q <= b[c] - a[c]; q++)
                hist[c][q] += h[c][q];
        for (int c = 0; c < 3; c++)
            free(h[c]);
    }
    return failed ? -1 : count;
}

/* The id of the m-th point (from 0) of node x in lattice plane k[axis] = kp, in id order. */
static int64_t nth_in_plane(const sph_region *r, const sph_lattice *L, const sph_rcb *T, int x,
                            int axis, long kp, long m)
{
    const sph_rcb_node *n = &T->node[x];
    long a[3], b[3], k[3];
    memcpy(a, n->lo, sizeof a), memcpy(b, n->hi, sizeof b);
    a[axis] = b[axis] = kp;
    for (k[2] = a[2]; k[2] <= b[2]; k[2]++)
        for (k[1] = a[1]; k[1] <= b[1]; k[1]++)
            for (k[0] = a[0]; k[0] <= b[0]; k[0]++) {
                const int64_t id = sph_lattice_id_of(L, k);
                if (in_node(T, x, k, id) && lattice_in(r, L, k) && m-- == 0)
                    return id;
            }
    return 0; /* not reached: the plane holds more than m points of the node */
}

/* The cut of a counted node from its histogram along the axis (entries from a0). */
static void cut_from_histogram(const sph_region *r, const sph_lattice *L, sph_rcb *T, int x,
                               const long *h, long a0)
{
    sph_rcb_node *n = &T->node[x];
    n->axis = longest_axis(n, L->dim);
    const long target = left_target(n);
    if (target == n->count) {
        n->plane = n->hi[n->axis] + 1;
        n->cut_id = 0;
        return;
    }
    long before = 0, kp = n->lo[n->axis];
    while (before + h[kp - a0] <= target)
        before += h[kp++ - a0];
    n->plane = kp;
    n->cut_id = nth_in_plane(r, L, T, x, n->axis, kp, target - before);
}

/* Computes node x (its parent computed): count, box of its points, cut. */
static int count_node(const sph_region *r, const sph_lattice *L, sph_rcb *T, int x)
{
    sph_rcb_node *n = &T->node[x];
    long a[3], b[3], *hist[3] = { NULL, NULL, NULL };
    n->done = 1;
    if (!clip_box(L, n->lo, n->hi, a, b)) {
        set_empty(n);
        set_children(T, x);
        return 0;
    }
    int ok = 1;
    for (int c = 0; c < 3; c++)
        ok &= (hist[c] = calloc((size_t)(b[c] - a[c] + 1), sizeof **hist)) != NULL;
    if (ok) {
        n->count = node_histograms(r, L, T, x, a, b, hist);
        ok = n->count >= 0;
    }
    if (ok) {
        if (n->count == 0)
            set_empty(n);
        for (int c = 0; c < 3 && n->count > 0; c++) { /* the box of its points */
            long lo = a[c], hi = b[c];
            while (hist[c][lo - a[c]] == 0)
                lo++;
            while (hist[c][hi - a[c]] == 0)
                hi--;
            n->lo[c] = lo, n->hi[c] = hi;
        }
        if (n->left >= 0 && n->count > 0)
            cut_from_histogram(r, L, T, x, hist[longest_axis(n, L->dim)],
                               a[longest_axis(n, L->dim)]);
        set_children(T, x);
    }
    for (int c = 0; c < 3; c++)
        free(hist[c]);
    return ok ? 0 : -1;
}

/* Whether boxes a (a0..a1) and b (b0..b1) share a lattice point. */
static int boxes_meet(const long a0[3], const long a1[3], const long b0[3], const long b1[3])
{
    for (int c = 0; c < 3; c++)
        if (a0[c] > a1[c] || b0[c] > b1[c] || a1[c] < b0[c] || b1[c] < a0[c])
            return 0;
    return 1;
}

/* The nodes process `part` needs beyond its path: those within margin of its leaf's box. */
static int count_neighbourhood(const sph_region *r, const sph_lattice *L, sph_rcb *T,
                               int leaf, long margin)
{
    long g0[3], g1[3];
    for (int c = 0; c < 3; c++) {
        g0[c] = T->node[leaf].lo[c] - (c < L->dim ? margin : 0);
        g1[c] = T->node[leaf].hi[c] + (c < L->dim ? margin : 0);
    }
    for (int x = 1; x < T->nnodes; x++) {
        const sph_rcb_node *n = &T->node[x];
        if (!n->done && T->node[n->parent].done && boxes_meet(n->lo, n->hi, g0, g1) &&
            count_node(r, L, T, x) < 0)
            return -1;
    }
    return 0;
}

/* The nodes of T that sph_rcb_count computes (T's root box set). */
static int count_nodes(const sph_region *r, const sph_lattice *L, sph_rcb *T, int part,
                       long margin)
{
    if (part < 0) {
        for (int x = 0; x < T->nnodes; x++)
            if (count_node(r, L, T, x) < 0)
                return -1;
        return 0;
    }
    int x = 0; /* the path to the leaf of `part` */
    for (;;) {
        if (count_node(r, L, T, x) < 0)
            return -1;
        const sph_rcb_node *n = &T->node[x];
        if (n->left < 0)
            break;
        x = part < T->node[n->right].first ? n->left : n->right;
    }
    return T->node[x].count > 0 ? count_neighbourhood(r, L, T, x, margin) : 0;
}

int sph_rcb_count(const sph_region *r, const sph_lattice *L, int nparts, int part, long margin,
                  sph_rcb *T)
{
    T->node = NULL;
    if (part >= nparts || rcb_init(T, nparts) < 0)
        return -1;
    for (int c = 0; c < 3; c++)
        T->node[0].lo[c] = 0, T->node[0].hi[c] = L->nk[c] - 1;
    if (count_nodes(r, L, T, part, margin) < 0) {
        sph_rcb_free(T);
        return -1;
    }
    return 0;
}

int sph_rcb_owner(const sph_rcb *T, const sph_lattice *L, const long k[3])
{
    const int64_t id = sph_lattice_id_of(L, k);
    for (int x = 0;;) {
        const sph_rcb_node *n = &T->node[x];
        if (!n->done)
            return -1;
        if (n->left < 0)
            return n->first;
        x = key_less(k, id, n->axis, n->plane, n->cut_id) ? n->left : n->right;
    }
}

/* ------------------------------------------------------------------ from filled points */

typedef struct {
    long k[3];
    int64_t id;
    int i;
} rcb_item;

static int item_less(const rcb_item *a, const rcb_item *b, int axis)
{
    return key_less(a->k, a->id, axis, b->k[axis], b->id);
}

static void item_swap(rcb_item *it, long p, long q)
{
    const rcb_item t = it[p];
    it[p] = it[q];
    it[q] = t;
}

/* Reorders it[0..n-1] so that it[m] is the m-th smallest in key order, the smaller ones
 * before it and the larger after (quickselect, median-of-three pivot; keys are distinct). */
static void select_item(rcb_item *it, long n, long m, int axis)
{
    long lo = 0, hi = n - 1;
    while (lo < hi) {
        const long mid = lo + (hi - lo) / 2;
        if (item_less(&it[mid], &it[lo], axis))
            item_swap(it, lo, mid);
        if (item_less(&it[hi], &it[lo], axis))
            item_swap(it, lo, hi);
        if (item_less(&it[mid], &it[hi], axis))
            item_swap(it, mid, hi); /* it[hi]: the median of the three */
        long s = lo;
        for (long q = lo; q < hi; q++)
            if (item_less(&it[q], &it[hi], axis))
                item_swap(it, s++, q);
        item_swap(it, s, hi);
        if (m == s)
            return;
        if (m < s)
            hi = s - 1;
        else
            lo = s + 1;
    }
}

/* Node x from its points it[0..count-1]: box and cut (moving the left child's points first). */
static void points_node(sph_rcb *T, int x, int dim, rcb_item *it, long count)
{
    sph_rcb_node *n = &T->node[x];
    n->done = 1;
    n->count = count;
    if (count == 0) {
        set_empty(n);
        return;
    }
    for (int c = 0; c < 3; c++) {
        n->lo[c] = it[0].k[c], n->hi[c] = it[0].k[c];
        for (long q = 1; q < count; q++) {
            n->lo[c] = it[q].k[c] < n->lo[c] ? it[q].k[c] : n->lo[c];
            n->hi[c] = it[q].k[c] > n->hi[c] ? it[q].k[c] : n->hi[c];
        }
    }
    if (n->left < 0)
        return;
    n->axis = longest_axis(n, dim);
    const long target = left_target(n);
    if (target == count) {
        n->plane = n->hi[n->axis] + 1;
        n->cut_id = 0;
        return;
    }
    select_item(it, count, target, n->axis);
    n->plane = it[target].k[n->axis];
    n->cut_id = it[target].id;
}

int sph_rcb_points(const sph_lattice *L, const double *X, int n, int nparts, sph_rcb *T,
                   int *part)
{
    T->node = NULL;
    rcb_item *it = malloc((size_t)(n > 0 ? n : 1) * sizeof *it);
    long *begin = nparts > 0 ? malloc((size_t)(2 * nparts) * sizeof *begin) : NULL;
    if (!it || !begin || rcb_init(T, nparts) < 0) {
        free(it), free(begin);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        sph_lattice_coords(L, X + (size_t)i * L->dim, it[i].k);
        it[i].id = sph_lattice_id_of(L, it[i].k);
        it[i].i = i;
    }
    long *count = malloc((size_t)(2 * nparts) * sizeof *count);
    if (!count) {
        free(it), free(begin), sph_rcb_free(T);
        return -1;
    }
    begin[0] = 0; /* node x holds it[begin[x] .. + count[x]], split by its cut */
    count[0] = n;
    for (int x = 0; x < T->nnodes; x++) {
        points_node(T, x, L->dim, it + begin[x], count[x]);
        const sph_rcb_node *nd = &T->node[x];
        if (nd->left >= 0) {
            const long nl = nd->count > 0 ? left_target(nd) : 0;
            begin[nd->left] = begin[x], count[nd->left] = nl;
            begin[nd->right] = begin[x] + nl, count[nd->right] = count[x] - nl;
        } else if (part) {
            for (long q = begin[x]; q < begin[x] + count[x]; q++)
                part[it[q].i] = nd->first;
        }
    }
    free(it), free(begin), free(count);
    return 0;
}

/* ------------------------------------------------------------------ halos */

void sph_rcb_local_free(sph_rcb_local_set *s)
{
    free(s->own_id), free(s->halo_id), free(s->own_X), free(s->halo_X), free(s->halo_part);
    memset(s, 0, sizeof *s);
}

/* The leaf of part p. */
static int leaf_of(const sph_rcb *T, int p)
{
    int x = 0;
    while (T->node[x].left >= 0)
        x = p < T->node[T->node[x].right].first ? T->node[x].left : T->node[x].right;
    return x;
}

/* The lattice points of box g0..g1 (within the lattice) as an array over the box: the owner
 * of each of the region's points, -1 elsewhere; *failed set when an owner is not known (a
 * node of T missing).  w receives the box's widths. */
static int *owner_map(const sph_region *r, const sph_lattice *L, const sph_rcb *T,
                      const long g0[3], const long g1[3], long w[3], int *failed)
{
    for (int c = 0; c < 3; c++)
        w[c] = g1[c] - g0[c] + 1;
    int *map = malloc((size_t)(w[0] * w[1] * w[2]) * sizeof *map);
    if (!map)
        return NULL;
    int unknown = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(| : unknown) \
    if (w[0] * w[1] * w[2] >= PARALLEL_POINTS)
    for (long k2 = g0[2]; k2 <= g1[2]; k2++) {
        long k[3] = { 0, 0, k2 };
        for (k[1] = g0[1]; k[1] <= g1[1]; k[1]++)
            for (k[0] = g0[0]; k[0] <= g1[0]; k[0]++) {
                const long q = (k[0] - g0[0]) + w[0] * ((k[1] - g0[1]) + w[1] * (k2 - g0[2]));
                const int in = lattice_in(r, L, k);
                map[q] = in ? sph_rcb_owner(T, L, k) : -1;
                unknown |= in && map[q] < 0;
            }
    }
    *failed = unknown;
    return map;
}

/* Marks (halo[q] = 1) the points of other parts that neighbour part p's points in the map. */
static void mark_halo(const int *map, const long w[3], int p, const long *off, int noff,
                      unsigned char *halo)
{
    for (long q = 0; q < w[0] * w[1] * w[2]; q++) {
        if (map[q] != p)
            continue;
        const long k[3] = { q % w[0], q / w[0] % w[1], q / (w[0] * w[1]) };
        for (int o = 0; o < noff; o++) {
            long j[3], in = 1;
            for (int c = 0; c < 3; c++) {
                j[c] = k[c] + off[3 * o + c];
                in &= j[c] >= 0 && j[c] < w[c];
            }
            const long s = in ? j[0] + w[0] * (j[1] + w[1] * j[2]) : -1;
            if (s >= 0 && map[s] >= 0 && map[s] != p)
                halo[s] = 1;
        }
    }
}

/* Copies the map's points of part p (halo == NULL) or its marked halo into the set's arrays. */
static int collect(const sph_lattice *L, const int *map, const long g0[3], const long w[3],
                   int p, const unsigned char *halo, int64_t **id, double **X, int **part)
{
    const long total = w[0] * w[1] * w[2];
    long n = 0;
    for (long q = 0; q < total; q++)
        n += halo ? halo[q] : map[q] == p;
    *id = malloc((size_t)(n ? n : 1) * sizeof **id);
    *X = malloc((size_t)(n ? n : 1) * L->dim * sizeof **X);
    if (part)
        *part = malloc((size_t)(n ? n : 1) * sizeof **part);
    if (!*id || !*X || (part && !*part))
        return -1;
    long m = 0;
    for (long q = 0; q < total; q++) {
        if (halo ? !halo[q] : map[q] != p)
            continue;
        const long k[3] = { g0[0] + q % w[0], g0[1] + q / w[0] % w[1],
                            g0[2] + q / (w[0] * w[1]) };
        (*id)[m] = sph_lattice_id_of(L, k);
        sph_lattice_point(L, k, *X + (size_t)m * L->dim);
        if (part)
            (*part)[m] = map[q];
        m++;
    }
    return (int)n;
}

int sph_rcb_local(const sph_region *r, const sph_lattice *L, const sph_rcb *T, int part,
                  double radius, int range, sph_rcb_local_set *out)
{
    memset(out, 0, sizeof *out);
    const sph_rcb_node *leaf = &T->node[leaf_of(T, part)];
    if (!leaf->done)
        return -1;
    if (leaf->count == 0)
        return 0;
    const long m = sph_lattice_margin(L, radius, range);
    long g0[3], g1[3], w[3];
    for (int c = 0; c < 3; c++) {
        g0[c] = leaf->lo[c] - (c < L->dim ? m : 0);
        g1[c] = leaf->hi[c] + (c < L->dim ? m : 0);
    }
    clip_box(L, g0, g1, g0, g1);
    long *off = NULL;
    int failed = 0, rc = -1;
    const int noff = sph_lattice_offsets(L, radius, range, &off);
    int *map = noff >= 0 ? owner_map(r, L, T, g0, g1, w, &failed) : NULL;
    unsigned char *halo = map ? calloc((size_t)(w[0] * w[1] * w[2]), 1) : NULL;
    if (halo && !failed) {
        mark_halo(map, w, part, off, noff, halo);
        out->nown = collect(L, map, g0, w, part, NULL, &out->own_id, &out->own_X, NULL);
        out->nhalo = collect(L, map, g0, w, part, halo, &out->halo_id, &out->halo_X,
                             &out->halo_part);
        rc = out->nown < 0 || out->nhalo < 0 ? -1 : 0;
    }
    if (rc < 0)
        sph_rcb_local_free(out);
    free(off), free(map), free(halo);
    return rc;
}

/* Counts part p's halo: particles j of other parts at an offset from one of its particles
 * (members[0..nm-1]), each once (stamp[j] == p once counted). */
static long part_halo(const sph_lattice *L, const long *kx, const int *index, const int *part,
                      const int *members, int nm, int p, const long *off, int noff, int *stamp)
{
    long h = 0;
    for (int q = 0; q < nm; q++) {
        const long *k = kx + 3 * (size_t)members[q];
        for (int o = 0; o < noff; o++) {
            long j[3], in = 1;
            for (int c = 0; c < 3; c++) {
                j[c] = k[c] + off[3 * o + c];
                in &= j[c] >= 0 && j[c] < L->nk[c];
            }
            const int s = in ? index[j[0] + L->nk[0] * (j[1] + L->nk[1] * j[2])] : -1;
            if (s >= 0 && part[s] != p && stamp[s] != p) {
                stamp[s] = p;
                h++;
            }
        }
    }
    return h;
}

int sph_rcb_halo_sizes(const sph_lattice *L, const double *X, int n, const int *part,
                       int nparts, double radius, int range, long *halo)
{
    const long cells = L->nk[0] * L->nk[1] * L->nk[2];
    long *off = NULL, *kx = malloc((size_t)(n ? n : 1) * 3 * sizeof *kx);
    int *index = malloc((size_t)cells * sizeof *index);
    int *first = calloc((size_t)nparts + 1, sizeof *first);
    int *members = malloc((size_t)(n ? n : 1) * sizeof *members);
    const int noff = sph_lattice_offsets(L, radius, range, &off);
    int rc = -1;
    if (!kx || !index || !first || !members || noff < 0)
        goto done;
    for (long q = 0; q < cells; q++)
        index[q] = -1;
    for (int i = 0; i < n; i++) { /* the lattice's particles, and the parts' members */
        long *k = kx + 3 * (size_t)i;
        sph_lattice_coords(L, X + (size_t)i * L->dim, k);
        index[k[0] + L->nk[0] * (k[1] + L->nk[1] * k[2])] = i;
        first[part[i] + 1]++;
    }
    for (int p = 0; p < nparts; p++)
        first[p + 1] += first[p];
    for (int i = 0; i < n; i++) /* first[p] runs through part p's members */
        members[first[part[i]]++] = i;
    for (int p = nparts; p > 0; p--) /* (and ends at part p + 1's start) */
        first[p] = first[p - 1];
    first[0] = 0;
    int failed = 0;
#pragma omp parallel reduction(| : failed)
    {
        int *stamp = malloc((size_t)(n ? n : 1) * sizeof *stamp);
        failed |= !stamp;
        for (int i = 0; stamp && i < n; i++)
            stamp[i] = -1;
#pragma omp for schedule(dynamic, 1)
        for (int p = 0; p < nparts; p++)
            halo[p] = stamp ? part_halo(L, kx, index, part, members + first[p],
                                        first[p + 1] - first[p], p, off, noff, stamp) : 0;
        free(stamp);
    }
    rc = failed ? -1 : 0;
done:
    free(off), free(kx), free(index), free(first), free(members);
    return rc;
}
