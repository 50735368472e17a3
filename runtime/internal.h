/* internal.h — runtime pieces that generated code does not see. */
#ifndef SPHRT_INTERNAL_H
#define SPHRT_INTERNAL_H

#include "output.h"
#include "sphrt.h"

/* region.c: regions tested in the body's dimension (2D: in the x-z plane, y ignored). */
int sph_region_contains_dim(const sph_region *r, int dim, const double p[3]);
/* The same, counting points within tol of a primitive as on it (fill.c: tol = 1e-9 dx). */
int sph_region_contains_tol_dim(const sph_region *r, int dim, const double p[3], double tol);
double sph_region_distance_dim(const sph_region *r, int dim, const double p[3]);
int sph_region_bbox_dim(const sph_region *r, int dim, double lo[3], double hi[3]);

/* alloc.c: bytes for a large array of the set-up (on huge pages from 4 MiB; zeroed when
 * zero is set), freed with free(); NULL when memory runs out. */
void *sph_alloc_large(size_t bytes, int zero);

/* part_fill.c: a process's particles of a body on many processes: its own (nown, first)
 * and its halo (n - nown after them, with the process each belongs to), positions X (dim
 * values each) and global ids.  0 (out->n = 0 when the region has no lattice), or -1 when
 * the lattice is too large or memory runs out. */
typedef struct {
    int n, nown;
    double *X;
    int64_t *gid;
    int *halo_part;
} sph_part_fill;
int sph_fill_part(const sph_region *r, int dim, double dx, double y_plane, double radius,
                  int range, int part, int nparts, sph_part_fill *out);

/* setup.c: particles, neighbours, gradients, selections and arrays of one body, on the
 * processes par (collective). */
int sph_body_setup(sph_body *b, const sph_body_desc *d, const sph_model *m, const sph_par *par);
void sph_body_free(sph_body *b);

/* contact.c: the contact state of a scene with contact (pair laws, search); idempotent. */
void sph_contact_init(sph_sim *s);

/* contact.c, for checkpoints: 1 with the contact's sums (stored, dissipated, the largest
 * omega^2, the closest pair's closeness) and the positions its candidates were last built
 * at (*nx0 values, 0 before the first build); 0 in a scene without contact. */
int sph_contact_checkpoint(const sph_sim *s, double sums[4], const double **x0, size_t *nx0);
/* The contact as a checkpoint left it: its sums, and its candidates built again at x0 (nx0
 * values; 0: not built yet).  -1 after reporting when nx0 is not the scene's size. */
int sph_contact_restore(sph_sim *s, const double sums[4], const double *x0, size_t nx0);

/* A growable time series of one measured quantity set. */
typedef struct {
    double *t;
    double *val;   /* n rows of `width` values */
    int n, cap, width;
} sph_series;
void sph_series_push(sph_series *s, double t, const double *row);

/* Mean displacement (3) and total force (3, sum m a) over measurement k of body b. */
void sph_measure(const sph_body *b, int k, double out[6]);

/* monitor.c: stability checks; returns 0 when the state is sane, otherwise fills msg. */
typedef struct {
    double e_ref;     /* largest total energy seen (for runaway detection) */
} sph_monitor;
int sph_monitor_check(sph_monitor *mon, const sph_sim *s, char *msg, size_t len);
/* 0 when every displacement, velocity and acceleration is finite, otherwise 1 with msg as
 * sph_monitor_check's (step, time, body, particle, what; the initial state, a collapsed step). */
int sph_monitor_finite(const sph_sim *s, char *msg, size_t len);
/* "step S, t = T s, body 'B', particle P (reference position ...)" at the start of msg (P: on
 * many processes the global id); what snprintf returns. */
int sph_monitor_where(char *msg, size_t len, const sph_sim *s, const sph_body *b, int particle);
/* On many processes: the lowest process where `found`, whose msg every process then gets;
 * 1 when there is one.  On one process: found.  Collective. */
int sph_monitor_share(const sph_sim *s, int found, char *msg, size_t len);
/* The same checks from a device target's per-body sums (sph_model.monitor): 0 when they show
 * a sane state (*stretch then gets the smallest principal stretch), 1 when the state must be
 * copied to the host and looked at with sph_monitor_check.  Collective: on many processes
 * the sums of all. */
int sph_monitor_glance(sph_monitor *mon, const sph_sim *s, const sph_monitor_sums *sums,
                       double *stretch);

/* expect.c: evaluate the model's expectations; writes them into the summary and prints a
 * line each.  Returns the number of failed expectations. */
typedef struct {
    sph_series *measures;   /* per (body, measure): rows ux uy uz fx fy fz */
    int *measure_base;      /* index of body b's first measure in `measures` */
    sph_series energy;      /* rows: total strain, total kinetic */
} sph_record;
/* errors (if not NULL, len bytes) receives "period 1.91 %, energy 0.0059 %", one entry per
 * expectation, for the program's final line. */
int sph_expect_evaluate(const sph_model *m, const sph_record *r, sph_json *j, int quiet,
                        char *errors, size_t len);

/* partition_report.c: --partition N, each body's decomposition for N processes printed
 * (particles and halo per part); 0, or -1 after a message. */
int sph_partition_report(const sph_model *m, int nparts);

#endif
