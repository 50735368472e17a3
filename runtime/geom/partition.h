/* partition.h — the domain decomposition of a body in its reference configuration, for runs
 * on many processes (docs/mpi.md).
 *
 * Total Lagrangian: neighbours never change, so a part's halo (the particles of other parts
 * within the kernel support of its own) is fixed for the whole run.  The pieces:
 *
 *  - the body's lattice (sph_lattice, the one sph_fill_region fills) and a global particle
 *    id from a particle's lattice coordinates, k0 + nk0 (k1 + nk1 k2): the same for a
 *    particle whichever process fills it and however many parts there are;
 *  - recursive coordinate bisection (RCB) into any number of parts: a node of n parts is
 *    cut along its points' longest lattice extent into n/2 and n - n/2 parts, the first
 *    getting round(count (n/2) / n) points exactly: points are ordered by their lattice plane
 *    along the axis, ties within a plane by id, so parts differ by at most a point per level;
 *  - two ways to compute the same tree: by counting lattice points in boxes with the
 *    membership test of sph_fill_region, without storing them (sph_rcb_count: a process
 *    computes only the nodes it needs, its own part's and those near it), or from filled
 *    positions (sph_rcb_points, for tests and reports);
 *  - a part's own particles and halo filled by that part alone (sph_rcb_local), the halo
 *    sizes of all parts from filled positions (sph_rcb_halo_sizes), and the rule that gives
 *    each pair to one part (sph_pair_owner).
 */
#ifndef SPH_PARTITION_H
#define SPH_PARTITION_H

#include <stdint.h>

#include "region.h"

/* The fill lattice of a region: point k along compact component c (x, z in 2D) at
 * lo[c] + (k + 1/2) dx, k = 0 .. nk[c] - 1; beyond dim nk is 1. */
typedef struct {
    int dim;
    double lo[3], dx, y_plane;
    long nk[3];
} sph_lattice;

/* fill.c: the lattice sph_fill_region(r, dim, dx, y_plane) fills; 1 for a lattice (which may
 * still hold none of the region's points), 0 when the region has no bounding box or dx is
 * invalid, -1 when the lattice holds too many points. */
int sph_fill_lattice(const sph_region *r, int dim, double dx, double y_plane, sph_lattice *L);

/* Lattice coordinates of a filled position x (dim components) into k[3] (0 beyond dim). */
void sph_lattice_coords(const sph_lattice *L, const double *x, long k[3]);
/* The global id of lattice point k, and of a filled position. */
int64_t sph_lattice_id_of(const sph_lattice *L, const long k[3]);
int64_t sph_lattice_id(const sph_lattice *L, const double *x);
/* The position of lattice point k (dim components), as sph_fill_region computes it. */
void sph_lattice_point(const sph_lattice *L, const long k[3], double *x);
/* The number of the region's lattice points in the box lo..hi (inclusive lattice
 * coordinates), with sph_fill_region's membership test; nothing is stored. */
long sph_lattice_count(const sph_region *r, const sph_lattice *L, const long lo[3],
                       const long hi[3]);

/* A node of the bisection tree: parts first .. first + nparts - 1.  A point of the node goes
 * to the left child when (k[axis], id) < (plane, cut_id), else to the right. */
typedef struct {
    int first, nparts;
    int parent, left, right;   /* -1: none (the root; a leaf, which is part `first`) */
    int done;                  /* 1: computed (sph_rcb_count may leave nodes out) */
    long count;                /* its points */
    long lo[3], hi[3];         /* the lattice box of its points (lo > hi: none); before the
                                  node is computed, the box its parent's cut leaves it */
    int axis;
    long plane;
    int64_t cut_id;
} sph_rcb_node;

typedef struct {
    int nparts, nnodes;
    sph_rcb_node *node;        /* 2 nparts - 1 nodes, every parent before its children */
} sph_rcb;

/* The tree of nparts >= 1 parts by counting the region's lattice points.  part < 0: every
 * node; otherwise only the nodes a process that holds `part` (< nparts) needs: the path to its
 * leaf, and every node whose box comes within `margin` lattice steps of that leaf's box (so
 * that the owner of every lattice point there is known).  0 on success, -1 when memory runs
 * out or the numbers are wrong (T then holds nothing to free). */
int sph_rcb_count(const sph_region *r, const sph_lattice *L, int nparts, int part, long margin,
                  sph_rcb *T);
/* The same tree from n filled positions X (n dim values, on lattice L); part[i] receives
 * particle i's part unless part is NULL.  0 on success, -1 when memory runs out or nparts < 1
 * (T then holds nothing to free). */
int sph_rcb_points(const sph_lattice *L, const double *X, int n, int nparts, sph_rcb *T,
                   int *part);
void sph_rcb_free(sph_rcb *T);
/* The part of lattice point k; -1 when a node on its way was not computed. */
int sph_rcb_owner(const sph_rcb *T, const sph_lattice *L, const long k[3]);

/* The neighbour criterion of sph_neighbours on the lattice: the offsets o != 0 (3 values
 * each, 0 beyond dim) with |o dx| <= radius (1 + 1e-9) and, when range > 0, |o_c| dx <=
 * (range + 0.01) dx.  Returns their number and a malloc'ed array in *off (NULL: none). */
int sph_lattice_offsets(const sph_lattice *L, double radius, int range, long **off);
/* The lattice steps a neighbour may be away along one axis (the halo's margin). */
long sph_lattice_margin(const sph_lattice *L, double radius, int range);

/* What the process of one part fills: its own points and its halo (points of other parts
 * that are neighbours of its own), each in id order, with global ids, positions (dim
 * values) and, for the halo, their parts. */
typedef struct {
    int nown, nhalo;
    int64_t *own_id, *halo_id;
    double *own_X, *halo_X;
    int *halo_part;
} sph_rcb_local_set;

/* Fills part `part` of tree T (computed for that part with sph_lattice_margin's margin, or
 * whole) and its halo for the neighbour criterion (radius, range); 0 on success, -1 when a
 * needed node of T is missing or memory runs out. */
int sph_rcb_local(const sph_region *r, const sph_lattice *L, const sph_rcb *T, int part,
                  double radius, int range, sph_rcb_local_set *out);
void sph_rcb_local_free(sph_rcb_local_set *s);

/* Halo sizes of every part from n filled positions X with their parts (part[i]): halo[p]
 * receives the number of particles of other parts that are neighbours (the criterion
 * above) of part p's particles.  0 on success, -1 when memory runs out. */
int sph_rcb_halo_sizes(const sph_lattice *L, const double *X, int n, const int *part,
                       int nparts, double radius, int range, long *halo);

/* Particles by global id: n ids (any order) with their indices, sorted by id (malloc'd; NULL
 * when memory runs out), and the index of a particle of id in them (-1: none). */
typedef struct {
    int64_t id;
    int index;
} sph_id_index;
sph_id_index *sph_id_sort(const int64_t *id, int n);
int sph_id_find(const sph_id_index *sorted, int n, int64_t id);

/* The half-pair scheme: every pair belongs to one part, which computes it (both particles'
 * shares) and sends the other particle's share to that particle's part.  Two rules:
 * sph_pair_owner gives it to the part of its particle of smaller id, so both parts of an
 * interface compute about half of its pairs and each needs the other's particles near it;
 * sph_pair_owner_lower gives a pair between two parts to the lower part number, so one side
 * of an interface computes all of its pairs and needs the other's particles, and the other
 * side needs none: about half the halo data, for a little more imbalance in the pairs each
 * part computes (docs/mpi.md measures both). */
static inline int sph_pair_owner(int64_t id_i, int part_i, int64_t id_j, int part_j)
{
    return id_i < id_j ? part_i : part_j;
}

static inline int sph_pair_owner_lower(int part_i, int part_j)
{
    return part_i < part_j ? part_i : part_j;
}

#endif
