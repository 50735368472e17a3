/* partition_report.c — the decomposition of one body into parts (runtime/geom/partition.h)
 * for a list of part counts: particles per part, balance, halo per part and the halo
 * fraction, the time each step takes, and what one process computes alone.  Built and run by
 * bench/partition; not part of the test suite.
 *
 *   partition_report [--parts 8,64,512,4096] [--coefh C] [--range R] [--no-count]
 *                    box DIM DX X0 Y0 Z0 X1 Y1 Z1
 *   partition_report [options] surface FILE DX
 *
 * The kernel support is 2h, h = coefh sqrt(dim) dx (runtime/run/setup.c); --range is nbsrange.
 * --no-count leaves out the whole tree by counting (the points' tree and one process's
 * share by counting are still computed). */
#include <math.h>
#include <omp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "geom/fill.h"
#include "geom/partition.h"
#include "geom/region.h"

typedef struct {
    sph_shape shape;
    sph_region r;
    int dim, range, no_count;
    double dx, coefh, radius;
    int parts[16], nparts;
} report;

static int usage(void)
{
    fprintf(stderr, "usage: partition_report [--parts N,N,..] [--coefh C] [--range R] "
                    "[--no-count]\n"
                    "           box DIM DX X0 Y0 Z0 X1 Y1 Z1 | surface FILE DX\n");
    return 2;
}

/* The options and the body; 0 when they are incomplete. */
static int parse(report *R, int argc, char **argv)
{
    static const int dflt[] = { 8, 64, 512, 4096 };
    memset(R, 0, sizeof *R);
    R->coefh = 1.0;
    R->nparts = 4;
    memcpy(R->parts, dflt, sizeof dflt);
    int a = 1;
    for (; a < argc && !strncmp(argv[a], "--", 2); a++) {
        if (!strcmp(argv[a], "--no-count")) {
            R->no_count = 1;
        } else if (a + 1 < argc && !strcmp(argv[a], "--coefh")) {
            R->coefh = atof(argv[++a]);
        } else if (a + 1 < argc && !strcmp(argv[a], "--range")) {
            R->range = atoi(argv[++a]);
        } else if (a + 1 < argc && !strcmp(argv[a], "--parts")) {
            R->nparts = 0;
            for (char *s = strtok(argv[++a], ","); s && R->nparts < 16; s = strtok(NULL, ","))
                R->parts[R->nparts++] = atoi(s);
        } else {
            return 0;
        }
    }
    if (a + 9 == argc && !strcmp(argv[a], "box")) {
        R->dim = atoi(argv[a + 1]);
        R->dx = atof(argv[a + 2]);
        R->shape = (sph_shape){ .kind = SPH_BOX };
        for (int c = 0; c < 3; c++)
            R->shape.a[c] = atof(argv[a + 3 + c]), R->shape.b[c] = atof(argv[a + 6 + c]);
    } else if (a + 3 == argc && !strcmp(argv[a], "surface")) {
        R->dim = 3;
        R->shape = (sph_shape){ .kind = SPH_MESH, .file = argv[a + 1] };
        R->dx = atof(argv[a + 2]);
    } else {
        return 0;
    }
    R->r = (sph_region){ .prims = &R->shape, .n = 1 };
    R->radius = 2.0 * R->coefh * sqrt((double)R->dim) * R->dx;
    return (R->dim == 2 || R->dim == 3) && R->dx > 0 && R->nparts > 0;
}

/* 1 when two trees agree node by node. */
static int same_tree(const sph_rcb *a, const sph_rcb *b)
{
    for (int x = 0; x < a->nnodes; x++) {
        const sph_rcb_node *p = &a->node[x], *q = &b->node[x];
        if (p->count != q->count || p->plane != q->plane || p->cut_id != q->cut_id ||
            p->axis != q->axis || memcmp(p->lo, q->lo, sizeof p->lo) ||
            memcmp(p->hi, q->hi, sizeof p->hi))
            return 0;
    }
    return 1;
}

/* The surface of each part's box against a cube of its volume: the mean of
 * 2 (ab + bc + ca) / (6 V^(2/3)) over the parts (2D: perimeter against a square's). */
static double box_shape_quotient(const sph_rcb *T, int dim)
{
    double sum = 0.0;
    int m = 0;
    for (int x = 0; x < T->nnodes; x++) {
        const sph_rcb_node *n = &T->node[x];
        if (n->left >= 0 || n->count == 0)
            continue;
        double e[3], v = 1.0, s;
        for (int c = 0; c < 3; c++)
            e[c] = c < dim ? (double)(n->hi[c] - n->lo[c] + 1) : 1.0, v *= e[c];
        s = dim == 3 ? 2.0 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]) / (6.0 * pow(v, 2.0 / 3.0))
                     : 2.0 * (e[0] + e[1]) / (4.0 * sqrt(v));
        sum += s;
        m++;
    }
    return m ? sum / m : 0.0;
}

/* Under both pair rules (partition.h: the smaller id, the lower part): the halo each part
 * needs for the pairs it owns, all parts together as a fraction of the particles, into
 * need[rule], and the most pairs a part owns against the mean into imbalance[rule].  Each
 * pair is seen from its owner's particle; particles are visited part by part, so stamp[j] ==
 * p marks j as counted for part p. */
static void rule_stats(const sph_lattice *L, const double *X, int n, const int *part, int N,
                       double radius, int range, double need[2], double imbalance[2])
{
    long *off, *k = malloc((size_t)n * 3 * sizeof *k);
    const int noff = sph_lattice_offsets(L, radius, range, &off);
    const long cells = L->nk[0] * L->nk[1] * L->nk[2];
    int *index = malloc((size_t)cells * sizeof *index), *order = malloc((size_t)n * sizeof *order);
    int *first = calloc((size_t)N + 1, sizeof *first), *stamp[2];
    long *pairs[2], halo[2] = { 0, 0 };
    for (int rule = 0; rule < 2; rule++) {
        stamp[rule] = malloc((size_t)n * sizeof **stamp);
        pairs[rule] = calloc((size_t)N, sizeof **pairs);
        for (int i = 0; i < n; i++)
            stamp[rule][i] = -1;
    }
    for (long q = 0; q < cells; q++)
        index[q] = -1;
    for (int i = 0; i < n; i++) {
        sph_lattice_coords(L, X + (size_t)i * L->dim, k + 3 * (size_t)i);
        index[sph_lattice_id_of(L, k + 3 * (size_t)i)] = i;
        first[part[i] + 1]++;
    }
    for (int p = 0; p < N; p++)
        first[p + 1] += first[p];
    for (int i = 0; i < n; i++)
        order[first[part[i]]++] = i;
    for (int q = 0; q < n; q++) {
        const int i = order[q], p = part[i];
        const long *ki = k + 3 * (size_t)i;
        const int64_t idi = sph_lattice_id_of(L, ki);
        for (int o = 0; o < noff; o++) {
            long kj[3], in = 1;
            for (int c = 0; c < 3; c++) {
                kj[c] = ki[c] + off[3 * o + c];
                in &= kj[c] >= 0 && kj[c] < L->nk[c];
            }
            const int64_t idj = in ? sph_lattice_id_of(L, kj) : 0;
            const int j = in ? index[idj] : -1;
            if (j < 0)
                continue;
            const int owner[2] = { sph_pair_owner(idi, p, idj, part[j]),
                                   sph_pair_owner_lower(p, part[j]) };
            for (int rule = 0; rule < 2; rule++) {
                if (owner[rule] != p)
                    continue;
                pairs[rule][p] += part[j] != p || idi < idj;
                if (part[j] != p && stamp[rule][j] != p)
                    stamp[rule][j] = p, halo[rule]++;
            }
        }
    }
    for (int rule = 0; rule < 2; rule++) {
        long most = 0, all = 0;
        for (int p = 0; p < N; p++)
            most = pairs[rule][p] > most ? pairs[rule][p] : most, all += pairs[rule][p];
        need[rule] = (double)halo[rule] / n;
        imbalance[rule] = all ? most / ((double)all / N) : 0.0;
        free(stamp[rule]), free(pairs[rule]);
    }
    free(off), free(k), free(index), free(order), free(first);
}

/* What the process of part p computes alone: its tree nodes by counting, then its own
 * particles and halo.  Returns the seconds; sets the nodes, own and halo counts. */
static double one_process(const report *R, const sph_lattice *L, int N, int p, int *nodes,
                          int *own, int *halo)
{
    sph_rcb T;
    sph_rcb_local_set s;
    const double t0 = omp_get_wtime();
    if (sph_rcb_count(&R->r, L, N, p, sph_lattice_margin(L, R->radius, R->range), &T) < 0 ||
        sph_rcb_local(&R->r, L, &T, p, R->radius, R->range, &s) < 0) {
        fprintf(stderr, "partition_report: part %d failed\n", p);
        exit(1);
    }
    const double t = omp_get_wtime() - t0;
    *nodes = 0;
    for (int x = 0; x < T.nnodes; x++)
        *nodes += T.node[x].done;
    *own = s.nown;
    *halo = s.nhalo;
    sph_rcb_local_free(&s);
    sph_rcb_free(&T);
    return t;
}

/* One line of the table for N parts. */
static void report_parts(const report *R, const sph_lattice *L, const double *X, int n, int N)
{
    sph_rcb P, C;
    int *part = malloc((size_t)n * sizeof *part);
    long *halo = malloc((size_t)N * sizeof *halo), *own = calloc((size_t)N, sizeof *own);
    double t0 = omp_get_wtime();
    if (!part || !halo || !own || sph_rcb_points(L, X, n, N, &P, part) < 0) {
        fprintf(stderr, "partition_report: out of memory\n");
        exit(1);
    }
    const double t_points = omp_get_wtime() - t0;
    double t_count = -1.0;
    int same = -1;
    if (!R->no_count) {
        t0 = omp_get_wtime();
        sph_rcb_count(&R->r, L, N, -1, 0, &C);
        t_count = omp_get_wtime() - t0;
        same = same_tree(&P, &C);
        sph_rcb_free(&C);
    }
    t0 = omp_get_wtime();
    sph_rcb_halo_sizes(L, X, n, part, N, R->radius, R->range, halo);
    const double t_halo = omp_get_wtime() - t0;
    long omin = n, omax = 0, hmax = 0, hsum = 0;
    double rmax = 0.0;
    for (int i = 0; i < n; i++)
        own[part[i]]++;
    for (int p = 0; p < N; p++) {
        omin = own[p] < omin ? own[p] : omin;
        omax = own[p] > omax ? own[p] : omax;
        hmax = halo[p] > hmax ? halo[p] : hmax;
        hsum += halo[p];
        rmax = own[p] ? fmax(rmax, (double)halo[p] / own[p]) : rmax;
    }
    const double mean = (double)n / N;
    int nodes, pown, phalo;
    const int p = N / 2;
    const double t_one = one_process(R, L, N, p, &nodes, &pown, &phalo);
    const int agree = pown == own[p] && phalo == halo[p];
    double need[2], imbalance[2];
    rule_stats(L, X, n, part, N, R->radius, R->range, need, imbalance);
    printf("| %5d | %8ld | %8ld | %10.1f | %6.2f %% | %8.1f | %8ld | %6.1f %% | %6.1f %% | "
           "%5.3f | %6.1f %% %5.3f | %6.1f %% %5.3f | %5.2f | %5.2f | %5.2f | %5.3f (%d)%s |%s\n",
           N, omin, omax, mean, 100.0 * (omax / mean - 1.0), (double)hsum / N, hmax,
           100.0 * hsum / n, 100.0 * rmax, box_shape_quotient(&P, L->dim), 100.0 * need[0],
           imbalance[0], 100.0 * need[1], imbalance[1], t_points, t_count, t_halo, t_one,
           nodes, agree ? "" : " DIFFERS", same == 0 ? " (counted tree DIFFERS)" : "");
    fflush(stdout);
    free(part), free(halo), free(own);
    sph_rcb_free(&P);
}

int main(int argc, char **argv)
{
    report R;
    if (!parse(&R, argc, argv))
        return usage();
    sph_lattice L;
    double *X, t0 = omp_get_wtime();
    const int n = sph_fill_region(&R.r, R.dim, R.dx, 0.0, &X);
    const double t_fill = omp_get_wtime() - t0;
    if (n <= 0 || sph_fill_lattice(&R.r, R.dim, R.dx, 0.0, &L) <= 0) {
        fprintf(stderr, "partition_report: the body has no particles\n");
        return 1;
    }
    printf("%dD body, dx %g: %d particles (lattice %ld x %ld x %ld, filled in %.2f s), "
           "support radius %.4g dx, %d threads\n\n", R.dim, R.dx, n, L.nk[0], L.nk[1], L.nk[2],
           t_fill, R.radius / R.dx, omp_get_max_threads());
    printf("| parts | min/part | max/part | mean/part | balance | halo mean | halo max | "
           "halo/own | worst part | shape | id rule: need, pairs | lower rule: need, pairs | "
           "points s | count s | halo s | one process s (nodes) |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (int q = 0; q < R.nparts; q++)
        report_parts(&R, &L, X, n, R.parts[q]);
    free(X);
    return 0;
}
