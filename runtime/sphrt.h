/* sphrt.h — the contract between generated model code and the sphc runtime (libsphrt).
 *
 * Generated code (model.c) fills an sph_model with the scene description and the
 * scene-specific passes (forces, boundary conditions, integrator), then calls sph_main().
 * The runtime builds particles, neighbour lists and kernel gradients, runs the time loop,
 * controls dt, monitors stability and writes the output.
 *
 * Conventions
 *  - Vectors of a body are stored compactly with `dim` components: in 2D (plane strain in
 *    the x–z plane) component 0 is x and component 1 is z; y is the constant out-of-plane
 *    coordinate `body->y_plane`.  sph_axis(dim, k) gives the 3D axis of component k.
 *  - Tensors of a body are stored per particle, row-major, dim×dim (`T[i*dim*dim + r*dim + c]`),
 *    except F, which is stored 3×3 (`F[i*9 + r*3 + c]`) so that 2D plane-strain values
 *    (F_yy = 1) and 3D values share one layout for output, and the pair passes' working
 *    tensors A, Q and Cv, whose rows or columns are padded for short vectors (SPH_TENSOR).
 *  - Pairs are stored per particle (CSR, both directions): nb_start[i] .. nb_start[i+1]-1,
 *    neighbour nb[p].  Everything that depends only on the reference offset X_i - X_j is
 *    looked up through nb_k[p] in small tables: wtab[k*SPH_ROW(dim) + c] = V_j dW/dX_i^c (the
 *    uncorrected kernel gradient times the neighbour volume; the corrected gradient is
 *    L_i · that) and gtab[k] (eq. 60, see setup.c).  On a particle lattice there are a few
 *    dozen distinct offsets, so a pair costs 8 bytes; otherwise the tables have one entry
 *    per pair.
 */
#ifndef SPHRT_H
#define SPHRT_H

#include <math.h>
#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Per-particle functions run on the host and, in the CUDA target, on the device: SPH_FN marks
 * the generated ones (material laws, boundary-condition values, user functions), SPH_HD the
 * helpers below. */
#ifdef __CUDACC__
#define SPH_HD __host__ __device__
#else
#define SPH_HD
#endif
#define SPH_FN SPH_HD static inline
/* SPH_FLAT marks the generated functions of a particle's stress (the material law, its
 * caller): the CPU's stress pass inlines them into its loop over a block of particles,
 * whatever their size, so that the loop can be vectorised (templates/body_forces.c). */
#ifdef __CUDACC__
#define SPH_FLAT SPH_FN
#else
#define SPH_FLAT static inline __attribute__((always_inline))
#endif
/* SPH_IVDEP, before a loop: no iteration depends on another (GCC's ivdep, Clang's
 * assume_safety), so the compiler need not prove that the arrays it touches never overlap. */
#if defined(__clang__)
#define SPH_IVDEP _Pragma("clang loop vectorize(assume_safety)")
/* (Clang says where such a loop stays scalar anyway: a law with a branch, 3D strides) */
#pragma clang diagnostic ignored "-Wpass-failed"
#elif defined(__GNUC__)
#define SPH_IVDEP _Pragma("GCC ivdep")
#else
#define SPH_IVDEP
#endif
/* glibc's vector math library (libmvec, which -lm links where it is used) has 2-, 4- and
 * 8-wide forms of these on x86-64; declared so, they let GCC vectorise the stress pass's
 * loop over a law that calls them (glibc's own headers declare them only under
 * -ffast-math).  Within 4 ulp, where the scalar ones are within 1. */
#if defined(__GNUC__) && !defined(__clang__) && !defined(__CUDACC__) && defined(__x86_64__) &&  \
    defined(__GLIBC__) && !defined(__FAST_MATH__)
__attribute__((__simd__("notinbranch"))) double exp(double);
__attribute__((__simd__("notinbranch"))) double log(double);
__attribute__((__simd__("notinbranch"))) double pow(double, double);
__attribute__((__simd__("notinbranch"))) double sin(double);
__attribute__((__simd__("notinbranch"))) double cos(double);
#endif

/* The exit codes of a generated program (README): a declared expectation failed, bad
 * options, the run went unstable, set-up or output failed, a CUDA call or kernel failed, a
 * signal stopped a run with checkpoints (after writing one), or one without. */
enum {
    SPH_EXIT_EXPECT = 1, SPH_EXIT_OPTIONS = 2, SPH_EXIT_UNSTABLE = 3, SPH_EXIT_SETUP = 4,
    SPH_EXIT_CUDA = 5, SPH_EXIT_STOPPED = 6, SPH_EXIT_SIGNALLED = 7
};

/* ------------------------------------------------------------------ geometry */

typedef enum { SPH_BOX, SPH_CYLINDER, SPH_SPHERE, SPH_MESH, SPH_PRISM, SPH_PYRAMID } sph_shape_kind;

typedef struct {
    sph_shape_kind kind;
    double a[3]; /* box: min corner   cylinder: axis start   sphere: centre */
    double b[3]; /* box: max corner   cylinder: axis end                    */
    double r;    /* cylinder, sphere: radius                                */
    int subtract;/* 1: this primitive is removed from the union of the previous ones */
    const char *file; /* mesh: a closed surface, VTK or STL (mesh.h); loaded at first use */
    const double *pts;/* prism: the base's corners, then the top's; pyramid: the apex, then */
    int npts;         /* the base's corners (npts points, mesh.h); its surface built at first use;
                       * mesh: NULL, or the map that moves the file's surface (4 points:
                       * sph_mesh_load_moved) */
} sph_shape;

typedef struct {
    const sph_shape *prims;
    int n;
    int has_corner;   /* 1: the fill lattice has a cell corner at `corner` */
    double corner[3];
} sph_region;

/* 1 when point p (3D) lies in the region (union/difference of its primitives). */
int sph_region_contains(const sph_region *r, const double p[3]);
/* Distance from p to the region (0 inside). */
double sph_region_distance(const sph_region *r, const double p[3]);

/* Fill a region with particles on the lattice of spacing dx.  Lattice points are cell
 * centres: lo + (k + 1/2) dx along each axis, where lo is the region's bounding-box
 * minimum when the box spans whole cells along that axis, else the cells are centred on the
 * box; when r->has_corner, the cells have a corner at r->corner instead.  A point is kept
 * when it lies inside the region or within 1e-9 dx of it (on its surface).  In 2D only x
 * and z vary and every particle gets y = y_plane.  Returns the number of particles and sets
 * *X to a malloc'ed array of n*dim coordinates (x,z in 2D; x,y,z in 3D); 0 for an empty
 * region, -1 (with a message) when the lattice is too large or memory runs out. */
int sph_fill_region(const sph_region *r, int dim, double dx, double y_plane, double **X);

/* ------------------------------------------------------------------ kernels */

typedef enum { SPH_WENDLAND = 0, SPH_CUBIC = 1 } sph_kernel_kind;

/* Kernel value and dW/dr / r (so that grad W = (X_i - X_j) * dwdr_over_r).  h is the
 * smoothing length; the support is 2h for both kernels (formulas in kernel.c).  The
 * normalisation constant aD and dW/dr / r are inline (below), so that the CUDA target's
 * passes can evaluate them too (SPH_CUDA_RECOMPUTE, docs/cuda.md). */
double sph_kernel_w(sph_kernel_kind k, int dim, double r, double h);

SPH_FN double sph_kernel_norm(sph_kernel_kind k, int dim, double h)
{
    const double pi = 3.14159265358979323846;
    if (k == SPH_CUBIC)
        return dim == 2 ? 10.0 / (7.0 * pi * h * h) : 1.0 / (pi * h * h * h);
    return dim == 2 ? 7.0 / (4.0 * pi * h * h) : 21.0 / (16.0 * pi * h * h * h);
}

/* Eq. 60 for one pair without gathering X_j in the hot loop: w_ij = V_j grad W is parallel
 * to dX = X_i - X_j, so G_ij = h (v_ij . dX) / (r^2 + 0.001 h^2) = g (v_ij . w_ij) with
 * g = h r^2 / ((w . dX) (r^2 + 0.001 h^2)); 0 where w vanishes (r = 2h). */
SPH_FN double sph_viscosity_factor(int dim, double h, const double *dX, const double *w)
{
    double r2 = 0, wdx = 0;
    for (int k = 0; k < dim; k++)
        r2 += dX[k] * dX[k], wdx += w[k] * dX[k];
    return wdx != 0 ? h * r2 / (wdx * (r2 + 0.001 * h * h)) : 0.0;
}

SPH_FN double sph_kernel_dwdr_over_r(sph_kernel_kind k, int dim, double r, double h)
{
    const double q = r / h, ad = sph_kernel_norm(k, dim, h) / (h * h);
    if (q >= 2.0)
        return 0.0;
    if (k == SPH_CUBIC) {
        if (q < 1.0)
            return ad * (-3.0 + 2.25 * q);
        const double t = 2.0 - q;
        return -0.75 * ad * t * t / q;
    }
    const double t = 1.0 - 0.5 * q;
    return -5.0 * ad * t * t * t;
}

/* A pair at reference offset dX = X_i - X_j: V_j grad_i W_ij = V_j (dW/dr / r) dX into w,
 * and V_j dW/dr / r returned (half the Laplacian weight of eq. 62).  What the set-up's
 * gradients and offset tables are made of (gradients.c, setup.c), and what the CUDA target
 * recomputes per pair with SPH_CUDA_RECOMPUTE. */
SPH_FN double sph_pair_w(sph_kernel_kind k, int dim, double h, double vol, const double *dX,
                         double *w)
{
    double r2 = 0;
    for (int c = 0; c < dim; c++)
        r2 += dX[c] * dX[c];
    const double f = vol * sph_kernel_dwdr_over_r(k, dim, sqrt(r2), h);
    for (int c = 0; c < dim; c++)
        w[c] = f * dX[c];
    return f;
}

/* ------------------------------------------------------------------ neighbours */

/* Cell-list search in the reference configuration: pairs (i, j), j != i, with
 * |X_i - X_j| <= radius (1 + 1e-9) and, when range > 0, |X_i^k - X_j^k| <= (range + 0.01) dx
 * for every component k (SoliDualSPHysics' nbsrange).  Pairs at exactly r == radius are
 * included (W = 0 there): with radius = 2h, h = sqrt(dim) dx, an interior lattice particle
 * has 24 neighbours in 2D and 178 in 3D.  Output in CSR form (both directions, symmetric),
 * each list sorted by j.  *start has n+1 entries. */
void sph_neighbours(const double *X, int n, int dim, double radius, int range, double dx,
                    int **start, int **nb);
/* The O(n^2) reference used by the tests. */
void sph_neighbours_brute(const double *X, int n, int dim, double radius, int range,
                          double dx, int **start, int **nb);

/* Every particle's correction matrix L_i = M_i^{-T}, M_i = sum_j V_j (X_j - X_i) ⊗
 * grad_i W_ij, so that sum_j V_j (X_j - X_i) ⊗ (L_i grad_i W_ij) = I exactly (dim×dim per
 * particle, malloc'ed; where M_i is singular, too few neighbours, L_i = I), and unless w is
 * NULL every pair's w = V_j grad_i W_ij (dim values per pair, malloc'ed: 24 bytes a pair in
 * 3D, which the set-up does not keep but recomputes where it needs them).  Returns the
 * number of particles whose M_i is singular, the first of them in *first_singular (-1 for
 * none) unless it is NULL. */
int sph_gradients(const double *X, int n, int dim, const int *start, const int *nb,
                  sph_kernel_kind kernel, double h, double vol, double **w, double **L,
                  int *first_singular);
/* One pair's w = V_j grad_i W_ij (dim values), as sph_gradients computes it. */
void sph_pair_gradient(const double *X, int dim, int i, int j, sph_kernel_kind kernel, double h,
                       double vol, double *w);

/* ------------------------------------------------------------------ model description */

typedef enum { SPH_VERLET = 0, SPH_SYMPLECTIC = 1 } sph_integrator;

/* A measurement plane: quad p[0..3]; particles whose cell the plane cuts
 * (distance <= dx/2, projection inside the quad grown by dx/2) are measured.
 * In 2D the y direction is ignored. */
typedef struct {
    const char *name;
    double p[4][3];
} sph_measure_desc;

/* A boundary condition's static part; the value comes from generated code. */
struct sph_pt;
typedef struct {
    int has_near;       /* restricted to particles near a region */
    sph_region near;    /* within dx of this region (reference configuration) */
    const char *where;  /* for messages: its model line, "beam.sph:12", */
    const char *what;   /* and what it sets, "velocity z" */
    /* the BC's value at a particle: 0 where its expression skips the particle (the
     * passes' own function; the set-up counts what it selects) */
    int (*value)(const struct sph_pt *p, double *out);
} sph_bc_desc;

/* Phase-field fracture of a body (section 2.2; eq. 6-9, 61-63). */
typedef struct {
    double p[4][3];
} sph_quad;

typedef struct {
    double Gc;             /* critical energy release rate */
    double eps0;           /* length scale */
    double limit;          /* s_l of eq. 63 */
    const sph_quad *notches; /* pairs whose segment crosses a notch are cut at set-up */
    int nnotches;
    const char *const *notch_where; /* per notch its model line ("beam.sph:24"), for messages */
    /* the lower bound of s (`restrict`): its model line and its value, 0 where it skips */
    const char *restrict_where;
    int (*restrict_value)(const struct sph_pt *p, double *out);
} sph_fracture_desc;

typedef struct sph_body sph_body;
typedef struct sph_sim sph_sim;
struct sph_monitor_sums;
struct sph_advance;

typedef struct {
    const char *name;
    sph_region region;
    int refine;         /* mapfac */
    int nbsrange;       /* 0: full kernel support */
    double rho0;        /* density */
    double c0;          /* reference sound speed, eq. 59 */
    double y_plane;     /* 2D: y of the plane */
    const sph_bc_desc *bcs;
    int nbcs;
    const sph_measure_desc *measures;
    int nmeasures;
    const sph_fracture_desc *fracture; /* NULL: no fracture */
    int nstate;                 /* state values per particle of the material law (plasticity) */
    const double *state_init;   /* their initial values */
    const char *const *state_names; /* per value: the law's name of a scalar state variable
                                       (written to the VTU files), NULL for tensor entries */
    int dissipation;            /* 1 + the state value holding the dissipated energy density
                                   (plastic work); 0: none */
    int viscous;                /* 1: artificial viscosity, whose dissipated energy the run
                                   reports */
    int crush;                  /* 1: the time step follows the current spacing where the body
                                   is compressed (sph_model.dt_lambda_on; lam2 below) */
    int offset_blocks;          /* the CPU's pair passes by offset blocks where the body is a
                                   lattice (offset_blocks.c): bit 0 the gradient pass, bit 1
                                   the momentum pass; 0: the lists alone */
    /* Contact with the other bodies (scenes with contact, see sph_contact_desc). */
    double young, poisson;      /* elastic constants of the contact stiffness */
    double restitution;         /* coefficient of restitution, 0 < e <= 1 */
    double friction;            /* Coulomb friction coefficient */
} sph_body_desc;

/* Contact between the particles of different bodies (runtime/contact.c): particles are
 * spheres of diameter dx in 3D and cylinders of diameter dx and unit length in 2D (plane
 * strain); two touch when closer than the mean of their diameters.  The normal force is
 * Hertz's law of the touching spheres (cylinders: linear), times `coef`, with damping from
 * the restitution and Coulomb friction. */
typedef struct {
    double coef;                /* multiplies the contact stiffness (SoliDualSPHysics' contcoeff) */
} sph_contact_desc;

/* Expectations, checked at the end of the run and written to summary.json. */
typedef enum { SPH_EXPECT_PERIOD, SPH_EXPECT_AMPLITUDE, SPH_EXPECT_ENERGY,
               SPH_EXPECT_REFERENCE } sph_expect_kind;

typedef struct {
    sph_expect_kind kind;
    const char *text;      /* the model line, for reports */
    int body, measure;     /* which measurement (-1 for energy) */
    int quantity;          /* 0..2 = ux uy uz, 3..5 = fx fy fz */
    double value;          /* expected value (period, amplitude) */
    double tolerance;      /* relative, e.g. 0.03; < 0: report only */
    double (*reference)(double t); /* SPH_EXPECT_REFERENCE */
} sph_expect_desc;

typedef struct {
    const char *name;      /* model name, used for the default output folder */
    const char *source;    /* model file */
    int dim;
    double dp;
    sph_kernel_kind kernel;
    double coefh;
    sph_integrator integrator;
    double cfl;
    double dtmin_coef;
    double dt_fixed;       /* > 0: fixed time step */
    double t_end;
    double t_out;
    double t_checkpoint;   /* > 0: a checkpoint every this long (the scene's `checkpoint`; the
                              program's --checkpoint overrides it) */
    double gravity[3];
    const sph_body_desc *bodies;
    int nbodies;
    const sph_expect_desc *expects;
    int nexpects;
    /* 1: besides its own files, the run writes the files SoliDualSPHysics names
     * (DeformStruc_Energies.csv, MeasuringPlData_MK<mk>_PL<k>.csv; docs/xml.md).  Set for
     * models imported from XML case files. */
    int compat_outputs;
    /* The scene setting `timestep`: where a body's smallest principal stretch lambda is
     * below dt_lambda_on, the bound of eq. 65 is multiplied by lambda / dt_lambda_on
     * (docs/stability.md): `auto` (the default) CFL / 0.4, at most 1, so that the Courant
     * number on the current spacing lambda h stays below 0.4 (0.5 at CFL 0.2); `stretch` 1;
     * 0 `undeformed` (never: eq. 65 on h as the paper writes it). */
    double dt_lambda_on;
    const sph_contact_desc *contact; /* NULL: the bodies do not touch each other */

    /* Generated passes. */
    /* Apply velocity boundary conditions at time t (v set, fix bits set). */
    void (*velocity_bcs)(sph_sim *s, double t);
    /* One full time step of size dt from s->t (integrator + forces + BCs). */
    void (*step)(sph_sim *s, double dt);
    /* Cauchy stress (xx yy zz xy yz zx) of every particle into body->sigma. */
    void (*stress_output)(sph_sim *s);
    /* Device targets (CUDA): copy the state the device holds back into the bodies' host
     * arrays before the runtime reads them (outputs, energies, the stability monitor);
     * NULL on the CPU, where the host arrays are the state. */
    void (*sync_host)(sph_sim *s);
    /* Device targets: every state array of the bodies (sph_body_state_arrays) and their sums
     * between the device and the host, to_device 0 for a checkpoint, 1 for a run resumed
     * from one (also the contact's sums); NULL on the CPU. */
    void (*copy_state)(sph_sim *s, int to_device);
    /* Device targets: the stability monitor's look at every body without copying its state
     * to the host (sph_monitor_sums, one per body); NULL on the CPU.  The runtime copies the
     * state and looks itself only when these show something wrong (runtime/monitor.c). */
    void (*monitor)(sph_sim *s, struct sph_monitor_sums *out);
    /* Device targets: steps on the device, which chooses each time step itself as
     * sph_sim_stable_dt would (sph_advance); NULL on the CPU.  See sph_sim_advance. */
    void (*advance)(sph_sim *s, struct sph_advance *a);
} sph_model;

/* Steps until the next output or check (sph_sim_advance, sph_model.advance). */
typedef struct sph_advance {
    int steps;          /* at most this many steps, */
    double t_stop, eps; /* and none that starts at t >= t_stop - eps; each ends at t_stop at
                           the latest (the next output time, or the end) */
    double floor_dt;    /* the floor of the time step: dtmin times the smallest h/c0 */
    /* NULL, or a flag that a signal handler sets: once it is non-zero no further step starts
     * (a run with checkpoints stopping at once, runtime/run.c) */
    const volatile sig_atomic_t *stop;
    /* out: 1 when a time step chosen fell below its floor (sph_dt_floor_now), and was not
     * taken; then that time step and that floor */
    int collapsed;
    double dt_bad, floor_bad;
} sph_advance;

/* What a device target's monitor pass sums over a body, for sph_model.monitor. */
typedef struct sph_monitor_sums {
    int bad;         /* 1: a particle fails one of the monitor's checks (a non-finite u, v or a;
                        det F <= 0; a speed above 10 c0) */
    double energy;   /* strain + kinetic energy (sph_body_energies) */
    double stretch2; /* the smallest squared principal stretch (sph_stretch2_min, at most 1) */
} sph_monitor_sums;

/* ------------------------------------------------------------------ state */

/* Precision of the pair passes' working arrays: the offset tables, A, Q and Cv.  double,
 * or float in the runtime built with SPH_SINGLE (libsphrt_single), which programs of models
 * with `precision single` link (their generated code defines SPH_SINGLE).  Positions,
 * displacements, velocities, accelerations, F, the material law and the time integration
 * are double in both. */
/* Entry (r, c) of particle i's D x D tensor Q or Cv (the pair passes' working arrays, which
 * only generated code reads), of n particles.  The CPU target stores a particle's tensor
 * column by column, each column padded with zeros to SPH_ROW(D) entries, so that its pair
 * loops handle a column as one short vector (templates/body_forces.c); the CUDA target
 * stores it entry by entry, a structure of arrays (sph_cuda.h defines SPH_TENSOR first), so
 * that a warp's threads read consecutive words.  A per-particle tensor takes
 * SPH_TENSOR_SIZE(D) entries on the CPU, D * D on the device; the offset table of kernel
 * gradients wtab holds SPH_ROW(D) entries per offset on both. */
#define SPH_ROW(D) ((D) == 3 ? 4 : (D))
#define SPH_TENSOR_SIZE(D) ((D) * SPH_ROW(D))
#ifndef SPH_TENSOR
#define SPH_TENSOR(i, r, c, D, n) (((size_t)(i) * (D) + (size_t)(c)) * SPH_ROW(D) + (size_t)(r))
#endif
/* A short vector of R sph_real (GCC's and Clang's vector extensions), in which the CPU pair
 * passes hold a row of A, a column of Q or Cv, or a table entry: whole-vector arithmetic,
 * a scalar operand standing for R copies of itself.  Aligned like sph_real and aliasing it,
 * so it loads from any place in those arrays. */
#define SPH_VECTOR(name, R)                                                                    \
    typedef sph_real name                                                                      \
        __attribute__((vector_size((R) * sizeof(sph_real)), aligned(sizeof(sph_real)), may_alias))

/* Two doubles, aligned like one, aliasing double: the x and y components of a particle's
 * velocity or acceleration (runs of D doubles) in one vector load or store (the CPU's pair
 * passes). */
#ifndef __CUDACC__
typedef double sph_double2
    __attribute__((vector_size(2 * sizeof(double)), aligned(sizeof(double)), may_alias));
#endif

/* A time the passes read, t or dt: a double on the CPU; in the CUDA target (sph_cuda.h defines
 * it first) a reference to the device's clock, which the device advances itself. */
#ifndef SPH_TIME_DEFINED
typedef double sph_time;
#endif

#ifdef SPH_SINGLE
typedef float sph_real;
#else
typedef double sph_real;
#endif

/* Values of a body's particles that a pass reads from neighbours: bytes per particle at
 * base (particle i at base + i size), for the halo exchange of runs on many processes. */
typedef struct {
    void *base;
    size_t size;
} sph_field;
#define SPH_FIELD(array, per_particle) ((sph_field){(array), (per_particle) * sizeof *(array)})

struct sph_par;

/* One task of a block of the gradient pass's offset blocks (offset_blocks.c): particle
 * i0 + l of the block, for each lane l in the mask key & 255, has the pair with particle
 * i0 + l + off at offset table entry key >> 8. */
#define SPH_OB_LANES 8
enum { SPH_MB_Q = 0, SPH_MB_CV = 9, SPH_MB_CS = 18, SPH_MB_V = 19, SPH_MB_A = 22, SPH_MB_ROWS = 25 };
typedef struct {
    int off;
    unsigned key;
} sph_ob_task;

struct sph_body {
    const sph_body_desc *desc;
    int n, dim;
    /* Runs on many processes (docs/mpi.md): this process's own particles are 0 .. nown - 1,
     * its halo (particles of other processes within the kernel support of its own, whose
     * values the exchanges bring) nown .. n - 1.  On one process nown = n.  Particle loops
     * run over the own particles, the pair passes over the pairs of own particles. */
    int nown;
    int64_t *gid;         /* n global ids (lattice ids, partition.h); NULL on one process */
    int *halo_part;       /* n - nown: the process each halo particle belongs to */
    /* Pairs of an own particle i with halo particles: xb_start[i] .. xb_start[i + 1] - 1,
     * neighbour xb[p], offset table entry xb_k[p] (as i sees the pair).  A process computes
     * them for its own particle only; the other process computes the same pair for its own.
     * NULL on one process. */
    int *xb_start, *xb, *xb_k;
    const struct sph_par *par; /* the processes of the run (one, or MPI's) */
    void *halo;                /* the halo exchange's plan (the MPI runtime's) */
    void *halo_dev;            /* device targets: the plan's lists and buffers on the device */
    double dx, h, vol, mass, rho0, c0, y_plane;

    double *X;          /* n*dim reference positions */
    double *u, *v, *a;  /* n*dim displacement, velocity, acceleration */
    double *F;          /* n*9 deformation gradient (3×3) */
    double *L;          /* n*dim*dim correction */
    sph_real *Q;        /* P·L (first Piola–Kirchhoff times correction), SPH_TENSOR */
    sph_real *Cv;       /* cof(F) = J F^-T for artificial viscosity, SPH_TENSOR */
    sph_real *Cs;       /* 1 / cof(F)'s largest singular value (sph_viscous_scale) */
    double *psi;        /* n strain energy density */
    double *sigma;      /* n*6 Cauchy stress, filled at output */
    double *work;       /* n*dim scratch for integrators (symplectic: v at n) */
    uint8_t *fix;       /* n bit masks: bit k = component k has a prescribed velocity */
    uint8_t *rare_hint; /* laws with state, at each CPU stress block's first particle: steps
                         * left that take the whole law (templates/body_forces.c, RARE) */

    int *nb_start, *nb;   /* CSR neighbour lists, both directions (set-up only; freed) */
    int *nb_k;            /* per pair: entry of the offset tables (set-up only; freed) */
    sph_real *wtab;       /* ntab*SPH_ROW(dim): V_j grad W for each distinct offset (0-padded) */
    sph_real *gtab;       /* ntab: G_ij = gtab * (v_i - v_j) . w_ij  (eq. 60) */
    sph_real *htab;       /* ntab: V W(r0) / (rho0 r0^2), for the hourglass penalty */
    int ntab;
    /* Half lists (j > i only) for the passes that visit each pair once and add its share
     * to both particles.  Particles are cut into stripes of consecutive indices, at least as
     * long as the largest j - i, so a pair of stripe s touches only stripes s and s + 1:
     * the even stripes can run in parallel, then the odd ones, without two threads ever
     * writing the same particle. */
    int *hb_start, *hb, *hb_k;
    int *stripe;          /* nstripes + 1 particle indices */
    int nstripes;
    double *stripe_sum;   /* nstripes: a sum over each stripe's pairs (the viscous power),
                           * added up in stripe order after the pass: the same bits on any
                           * number of threads */
    /* The lattice stencil (stencil.c; CPU only).  Where particles sit on a lattice, most
     * have the same half list relative to their own index: neighbours i + st_o[q] at offset
     * table entries st_k[q], q < st_m.  A particle whose pairs are exactly those and their
     * mirror images (i - st_o[q], the same entries as i - st_o[q] sees them), none with the
     * halo, belongs to one of the runs [st_run[2r], st_run[2r + 1]) of consecutive such
     * particles (ascending, r < nruns).  The pair passes do a run offset by offset, the
     * same pair of many particles in one vector instruction; the stress pass takes the run
     * particles' gradient sums from the stencil.  st_m = 0, nruns = 0: none (off a lattice,
     * or the program's --no-stencil). */
    int st_m, *st_k, *st_o;
    int nruns, *st_run;
    /* With a stencil, the gradient pass's lists: the particles it still visits (rest[c],
     * ascending, c < nrest: those not in a run, and run particles with a neighbour that is
     * not), each with the pairs it must add (rest_start[c] .. rest_start[c + 1] - 1,
     * neighbour rest_j, entry rest_k): a particle not in a run its whole half list, a run
     * particle its pairs with particles not in a run.  The momentum pass reads them for the
     * particles not in a run.  Compact, so that the passes do not load the half lists'
     * cache lines for a few particles apiece (they took a sixth of crack branching's step).
     * NULL without a stencil. */
    int nrest, *rest, *rest_start, *rest_j, *rest_k;
    /* The gradient pass's offset blocks (offset_blocks.c; 3D, CPU only): block B, the
     * SPH_OB_LANES own particles from SPH_OB_LANES B on, sums its particles' own pairs by the
     * tasks ob[ob_start[B] .. ob_start[B + 1] - 1] (sph_ob_task), reading u by component from
     * ob_u (row r from ob_u + r ob_stride, particle i at ob_pad + i); ob_pairs: the pairs,
     * in both directions, that the tasks' lanes hold.  nob = 0, NULL: none (the half lists
     * sum the pairs). */
    int nob, *ob_start, ob_pad, ob_stride;
    sph_ob_task *ob;
    double *ob_u;
    long ob_pairs;
    /* The momentum pass's offset blocks (offset_blocks.c; 3D, CPU only), over the half lists:
     * stripe s's blocks mb_stripe[s] .. mb_stripe[s + 1] - 1, block B the up to
     * SPH_OB_LANES particles from mb_i0[B] (within the stripe), its tasks
     * mb[mb_start[B] .. mb_start[B + 1] - 1].  mb_soa: SPH_MB_ROWS rows of mb_stride doubles,
     * particle i at mb_pad + i: Q and cof F entry (r, c) in rows 3 r + c and 9 + 3 r + c, Cs,
     * v and the pass's sums (SPH_MB_*).  mb_pairs: the pairs the lanes hold.  NULL, nmb = 0:
     * none. */
    int nmb, *mb_start, *mb_i0, *mb_stripe, mb_pad, mb_stride;
    sph_ob_task *mb;
    double *mb_soa;
    long mb_pairs;
    sph_real *A;          /* n*SPH_TENSOR_SIZE(dim): sum_j (u_j - u_i) (x) w_ij, the pair part of
                           * eq. 53, row by row, rows padded like wtab (CPU only) */
    /* Full lists (both directions) for device targets, whose threads each sum their own
     * particle's pairs, stored slot by slot: pair s of particle i (s < fb_count[i]) is
     * fb[s*n + i], so the threads of a warp read consecutive words.  fb_k is the offset table
     * entry k of the pair as the half list holds it, or ~k for the reversed pair
     * (w_ji = -w_ij).  On a lattice every offset has its own slot, the same for all
     * particles (where a particle lacks that neighbour, near a surface or a notch, the slot
     * holds a particle near i + the offset, sph_hole, and the zero table entry ntab the
     * device tables end with), so a warp's threads at one slot read j = i + const,
     * consecutive words; off a lattice each particle's pairs are packed and sorted by entry.
     * Where every pair of a body lies at i + its slot's offset (a box), fb and fb_k are NULL
     * and fb_mask holds the pairs: bit s & 31 of fb_mask[(s >> 5)*n + i] says whether
     * particle i has slot s's neighbour i + fb_off[s], of table entry fb_slotk[s] (sph_slot,
     * sph_cuda.h).  NULL on the CPU. */
    int *fb_count, *fb, *fb_k;
    unsigned *fb_mask;
    int *fb_off, *fb_slotk;
    /* Device targets: u and v by component (us[r*n + i]), as the pair passes read their
     * neighbours' (sph_cuda_components, sph_cuda.h).  NULL on the CPU. */
    double *us, *vs;
    /* Device targets: the reductions below as the device sums them (SPH_RED_* of
     * sph_cuda.h), read back once per step.  NULL on the CPU. */
    double *red;

    double *state;        /* n*nstate state of the material law (NULL without state) */

    /* Phase-field fracture (NULL unless the body has fracture). */
    double *s, *sd, *sdd; /* n phase field (1 intact, 0 broken), ds/dt, d2s/dt2 */
    double *H;            /* n history field: the largest psi+ so far (eq. 8) */
    double *lap;          /* n Laplacian of s (eq. 62), summed by the gradient pass */
    double *sd_n;         /* n symplectic: ds/dt at the start of the step */
    sph_real *ltab;       /* ntab: 2 V dW/dr / r, so lap_i = sum_j ltab (s_i - s_j) */
    long npairs;          /* neighbour relations, both directions (2 x the half lists) */

    int **bc_list;      /* per BC with `near`: particle indices */
    int *bc_count;
    int **ms_list;      /* per measure: particle indices */
    int *ms_count;

    /* reductions written by the generated update pass */
    double vmax2, amax2;
    /* the time step's bound on compression (desc->crush): each particle's squared smallest
     * principal stretch from the last stress pass, and their minimum (update; 1 before) */
    double *lam2, lam2min;
    /* artificial viscosity: the rate at which it dissipates energy (momentum pass) and the
     * energy it has dissipated so far (update) */
    double visc_rate, visc_dissipated;
};

/* The arrays of body b that its passes carry from one step to the next: what a checkpoint
 * saves (checkpoint.c) and a device target copies both ways for it (sph_cuda.h), in this
 * order, those the body has.  nstate: the law's state values per particle (b->desc->nstate;
 * a device view has no desc).  The rest (Q, Cv, A, sigma) every step or output makes anew. */
#define SPH_STATE_ARRAYS 15
typedef struct {
    const char *name;
    void *data;
    size_t bytes;
} sph_state_array;
static inline int sph_body_state_arrays(sph_body *b, int nstate, sph_state_array *out)
{
    const size_t n = (size_t)b->n, n1 = n * sizeof(double), nd = n1 * (size_t)b->dim;
    const sph_state_array all[SPH_STATE_ARRAYS] = {
        {"u", b->u, nd},       {"v", b->v, nd},        {"a", b->a, nd},
        {"work", b->work, nd}, {"F", b->F, 9 * n1},    {"psi", b->psi, n1},
        {"fix", b->fix, n},    {"lam2", b->lam2, n1},  {"state", b->state, n1 * (size_t)nstate},
        {"s", b->s, n1},       {"sd", b->sd, n1},      {"sdd", b->sdd, n1},
        {"H", b->H, n1},       {"lap", b->lap, n1},    {"sd_n", b->sd_n, n1}};
    int k = 0;
    for (int i = 0; i < SPH_STATE_ARRAYS; i++)
        if (all[i].data && all[i].bytes)
            out[k++] = all[i];
    return k;
}

/* The first k < n with a[k stride] >= v (n when none): a binary search of ascending values. */
static inline int sph_first_at_least(const int *a, int n, int stride, int v)
{
    int lo = 0, hi = n;
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (a[(size_t)mid * stride] >= v)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* The first of body b's stencil runs that ends after particle i (b->nruns when none does):
 * where a pass over particles i .. finds its runs. */
static inline int sph_run_after(const sph_body *b, int i)
{
    return sph_first_at_least(b->st_run + 1, b->nruns, 2, i + 1);
}

/* The first of body b's rest particles (above) at or after particle i (b->nrest when none). */
static inline int sph_rest_after(const sph_body *b, int i)
{
    return sph_first_at_least(b->rest, b->nrest, 1, i);
}

/* stencil.c: the body's lattice stencil and its runs (st_* above), from its half lists;
 * nothing with sph_stencil_off (the program's --no-stencil). */
extern int sph_stencil_off;
void sph_stencil_setup(sph_body *b);

/* offset_blocks.c: the body's offset blocks (ob_* above), from its full lists (the set-up,
 * before the half lists), and the momentum pass's (mb_*), from its half lists and stripes;
 * nothing with sph_stencil_off, in 2D, or where its desc's offset_blocks leaves them out. */
void sph_offset_blocks_setup(sph_body *b);
void sph_momentum_blocks_setup(sph_body *b);

/* The program's --whole-law: the CPU's stress pass takes no law's fast path (setup.c;
 * templates/body_forces.c, RARE). */
extern int sph_fast_law_off;

typedef struct sph_contact sph_contact;

/* The processes of a run: one (sph_par_one), or many under MPI (libsphrt_mpi, sph_mpi_main).
 * The runtime calls these at the points where processes must agree; on one process they
 * do nothing.  Sums add the processes' values in process order, so that every process gets
 * the same bits whatever the library's reduction order. */
typedef struct sph_par {
    int rank, size;
    void (*sum)(double *x, int n);          /* in place, elementwise over the processes */
    void (*min)(double *x, int n);
    void (*max)(double *x, int n);
    /* Collective: 1 when `bad` on any process; then the first message (sph_error) of the
     * lowest failing process is printed by process 0, unless process 0 failed too. */
    int (*agree)(int bad);
    void (*bcast)(void *buf, int bytes, int root);
    /* Every process's `bytes` at mine into all (size blocks, in process order). */
    void (*allgather)(const void *mine, void *all, int bytes);
    /* Collective: process 0 gets every process's block (any length) in process order, and
     * calls take(ctx, process, data, bytes) with each; the others only send. */
    void (*gather0)(const void *data, size_t bytes,
                    void (*take)(void *ctx, int from, const void *data, size_t bytes),
                    void *ctx);
    /* Every process sends out[q] (bytes[q] bytes) to process q and gets what each sent it:
     * *in (malloc'd; free it) holds the blocks in process order, got[q] bytes from q. */
    void (*swap)(const void *const *out, const size_t *bytes, void **in, size_t *got);
    /* Collective, once after every body's set-up: the plan of body b's halo exchange;
     * 0, or -1 after a message. */
    int (*body_ready)(sph_body *b);
    void (*body_free)(sph_body *b);
    /* The halo's values of nf fields of body b from their processes: post starts the
     * exchange, wait ends it (the same fields); passes that need no halo value run between. */
    void (*post)(sph_body *b, const sph_field *f, int nf);
    void (*wait)(sph_body *b, const sph_field *f, int nf);
    /* For device targets, which pack and unpack the values themselves: body b's halo plan,
     * the own particles whose values go out (in this order) and, for each value that comes
     * in, the halo particle it is of (0 .. n - nown - 1); 0 of each on one process.  Then the
     * exchange itself of packed values, `bytes` per particle, blocking. */
    void (*halo_lists)(const sph_body *b, const int **send, int *nsend, const int **recv,
                       int *nrecv);
    void (*exchange_packed)(sph_body *b, const void *out, void *in, size_t bytes);
    /* 1: exchange_packed takes device memory (an MPI library that reads and writes a
     * device's memory itself, CUDA-aware), so a device target's halo goes from device buffer
     * to device buffer; 0: through host buffers. */
    int device_buffers;
    /* The bytes this process has sent in all exchanges so far, and the seconds it waited
     * for them (in wait). */
    double (*bytes_sent)(void);
    double (*wait_seconds)(void);
} sph_par;

/* The run on one process. */
extern const sph_par sph_par_one;

struct sph_sim {
    const sph_model *m;
    sph_body *bodies;
    int nbodies;
    double t, dt;
    long step;
    int threads;
    sph_contact *contact;  /* contact state (contact.c); NULL until the first contact pass */
    double dt_factor;      /* the smallest factor on eq. 65 of any body at the last
                              sph_sim_stable_dt (timestep auto or stretch; 1 otherwise) */
    const sph_par *par;    /* the processes of the run (sph_par_one unless under MPI) */
};

/* Entry point of a generated program; sph_mpi_main that of one built with sphc --mpi, on
 * every process of the run (libsphrt_mpi). */
int sph_main(const sph_model *m, int argc, char **argv);
int sph_mpi_main(const sph_model *m, int argc, char **argv);
/* sph_main for the processes par (run.c). */
int sph_main_par(const sph_model *m, int argc, char **argv, const sph_par *par);

/* The runtime's messages on stderr, "NAME: error: ..." (a line each), NAME the program's
 * model once sph_main or sph_sim_init has set it (message.c). */
void sph_message_program(const char *name);
#if defined(__GNUC__)
#define SPH_PRINTF __attribute__((format(printf, 1, 2)))
#else
#define SPH_PRINTF
#endif
void sph_error(const char *fmt, ...) SPH_PRINTF;
void sph_warning(const char *fmt, ...) SPH_PRINTF;
void sph_note(const char *fmt, ...) SPH_PRINTF;
/* On the processes other than the first of a run on many processes: messages are not printed,
 * the first error is kept (sph_message_kept; "" when none). */
void sph_message_keep(int keep);
const char *sph_message_kept(void);

/* Where the time of a run goes (the program's --profile; profile.c).  The CPU target's step
 * calls its passes through SPH_PASS(fn, (args)), and the set-up times its stages with
 * SPH_TIMED(name, statement): when profiling is on, the wall time of the call is added to
 * its entry (found once per call site) in the phase the run is in; otherwise it costs one
 * test.  The CUDA target's SPH_PASS is the bare call: its kernels are timed on the device
 * (sph_cuda.h). */
enum { SPH_PHASE_STEPS, SPH_PHASE_CHECKS, SPH_PHASE_SETUP }; /* sph_profile_phase */
extern int sph_profile_on, sph_profile_phase;
int sph_profile_slot(const char *pass);
double sph_profile_start(int *slot, const char *pass); /* the wall clock, and *slot found */
void sph_profile_add(int slot, double seconds);
double sph_wall_time(void); /* the wall clock in seconds, monotonic (progress.c) */
double sph_cpu_time(void);  /* the CPU time of the process's threads, seconds (progress.c) */
double sph_idle_time(void); /* the machine's idle seconds summed over its cores, or -1 */
#define SPH_TIMED(name, statement)                                                             \
    do {                                                                                       \
        if (sph_profile_on) {                                                                  \
            static int slot_ = -1;                                                             \
            const double t0_ = sph_profile_start(&slot_, name);                                \
            statement;                                                                         \
            sph_profile_add(slot_, sph_wall_time() - t0_);                                     \
        } else {                                                                               \
            statement;                                                                         \
        }                                                                                      \
    } while (0)
#define SPH_PASS(fn, args) SPH_TIMED(#fn, fn args)

/* The simulation without the program around it (used by sph_main and by tests):
 * build every body and apply the velocity boundary conditions at t = 0 (initial
 * conditions); the stable time step of eq. 64-66 (or the fixed one); one step. */
int sph_sim_init(sph_sim *s, const sph_model *m, int verbose);
/* The same on the processes par; collective. */
int sph_sim_init_par(sph_sim *s, const sph_model *m, int verbose, const sph_par *par);
double sph_sim_stable_dt(sph_sim *s);
/* The smallest principal stretch of any particle (finite ones; capped at 1), from the host's
 * F (or, for a body that tracks it for its time step, its lam2min of the same F). */
double sph_sim_stretch(const sph_sim *s);
void sph_sim_step(sph_sim *s, double dt);
/* Up to a->steps steps, each of the stable time step (eq. 64-66) cut to end at a->t_stop at
 * the latest, none starting at t >= t_stop - eps: stops early at t_stop, or before a step
 * whose time step falls below its floor (a->collapsed).  A device target runs them on the
 * device, which then chooses each time step itself (sph_model.advance), and the host waits
 * once, at the end; on the CPU sph_sim_stable_dt and sph_sim_step.  Returns the steps taken. */
int sph_sim_advance(sph_sim *s, sph_advance *a);
void sph_sim_free(sph_sim *s);
/* Energies of a body: strain (sum V psi) and kinetic (sum m |v|^2 / 2). */
void sph_body_energies(const sph_body *b, double *strain, double *kinetic);
/* Fracture energy of a body: sum V Gc ((1 - s)^2 / (4 eps0) + eps0 |grad s|^2); 0 without
 * fracture. */
double sph_fracture_energy(const sph_body *b);
/* A table of n rows (t strictly increasing) at x, linearly interpolated; NaN outside
 * [t[0], t[n-1]] (reference solutions read from CSV files). */
double sph_table_interp(const double *t, const double *v, int n, double x);
/* Energy a body has dissipated in its material law (plastic work): sum V w; 0 without. */
double sph_dissipated_energy(const sph_body *b);

/* Contact (m->contact set; runtime/contact.c).  The contact pass adds every body's contact
 * accelerations to its `a`, from the current positions X + u and velocities v; generated
 * steps call it after the bodies' force passes and before their updates.  dt is the step's
 * length (friction stops a pair's sliding at most within one step). */
void sph_contact_forces(sph_sim *s, double dt);
/* The contact's bound on the time step, sqrt(m_pair / k) of the stiffest contact (before eq. 64's
 * C_CFL), for a step of `step` (the bodies' own): the pairs in contact, and the laws'
 * reference stiffness while a pair is in contact or may touch before the step ends
 * (contact_law.h, sph_contact_near); INFINITY without contact or far from it. */
double sph_contact_dt(const sph_sim *s, double step);
/* The energy stored in the contacts now and the energy the contacts' damping and friction
 * have dissipated so far (both 0 without contact). */
void sph_contact_energies(const sph_sim *s, double *stored, double *dissipated);
/* The largest omega^2 of the contacts of the last contact pass (0 without contact). */
double sph_contact_w2max(const sph_sim *s);
/* Frees the contact state (sph_sim_free calls it). */
void sph_contact_free(sph_sim *s);

/* Component k (0..dim-1) of a compact vector -> 3D axis (0 = x, 1 = y, 2 = z). */
SPH_HD static inline int sph_axis(int dim, int k) { return dim == 2 ? 2 * k : k; }

/* max and min of the model language (material laws, expressions): the larger or smaller of a
 * and b, and not a number where either is, so that a state gone wrong stays visible to the
 * stability checks.  Comparisons the compiler makes branch-free: C's fmax and fmin return the
 * other operand of a NaN, and on x86-64 they are library calls, which cost a fracture law's
 * stress pass a tenth of its time. */
SPH_HD static inline double sph_max(double a, double b) { return a > b || a != a ? a : b; }
SPH_HD static inline double sph_min(double a, double b) { return a < b || a != a ? a : b; }

/* ------------------------------------------------------------------ the time step
 * One source for the host (sim.c, run.c) and a device target's own choice (sph_cuda.h). */

/* The factor on eq. 65 of a body whose smallest squared principal stretch is lam2min: where it
 * is compressed below lambda_on (the scene's `timestep`, 0 for `undeformed`) the bound follows
 * the current spacing lambda h (the reference wave speed of total-Lagrangian SPH grows like
 * 1/lambda), scaled so that it is continuous: lambda / lambda_on (docs/stability.md).  crush:
 * whether the body follows its compression at all. */
SPH_HD static inline double sph_stretch_factor(double lambda_on, int crush, double lam2min)
{
    if (!(lambda_on > 0) || !crush || !(lam2min >= 0))
        return 1.0; /* (a non-finite state is the monitor's to report) */
    const double lam = sqrt(lam2min);
    return lam < lambda_on ? lam / lambda_on : 1.0;
}

/* The running maximum m of eq. 65-66's |v|^2 or |a|^2 with x: a value that is not a number
 * counts as infinite, so a state gone non-finite gives a time step of 0 and stops the run at
 * the very next step (reported with the particle, run.c), not at the monitor's next check. */
SPH_HD static inline double sph_max_bound(double m, double x)
{
    return x <= m ? m : x == x ? x : INFINITY;
}

/* The squared principal stretch that the compression bound of a body takes for a particle's
 * l2 (the smallest eigenvalue of C): one at or below 0 (F inverted or degenerate), or not a
 * number, is a stretch of 0, which collapses the time step. */
SPH_HD static inline double sph_bound_stretch2(double l2)
{
    return l2 > 0 ? l2 : 0.0;
}

/* A body's bound on the time step before eq. 64's CFL: eq. 65 on its factor f and eq. 66. */
SPH_HD static inline double sph_body_dt(double f, double h, double c0, double vmax2, double amax2)
{
    const double dtv = f * h / (c0 + sqrt(vmax2));                      /* eq. 65 */
    const double dta = amax2 > 0 ? sqrt(h / sqrt(amax2)) : INFINITY;   /* eq. 66 */
    return fmin(dtv, dta);
}

/* The time step from the bodies' and contacts' smallest bound: eq. 64, or the scene's fixed
 * step, which a bound of 0 (a state that is not finite, sph_max_bound) makes not a number
 * too, so that a fixed step stops at once like an adaptive one. */
SPH_HD static inline double sph_chosen_dt(double dt_fixed, double cfl, double bound)
{
    if (dt_fixed > 0)
        return bound > 0 ? dt_fixed : NAN;
    return cfl * bound; /* eq. 64 */
}

/* Where a body is compressed the bound follows the current spacing, and so does dtmin, down
 * to a hundredth of it (a stretch below 0.005 is a collapse too): the floor of a step whose
 * smallest factor is `factor`. */
SPH_HD static inline double sph_dt_floor_now(double floor_dt, double factor)
{
    return floor_dt * fmax(factor, 0.01);
}

/* ------------------------------------------------------------------ per-particle helpers
 * Shared by generated code and the runtime (3×3 row-major). */

/* Cofactor (i, j) of F: the (i, j) entry of J F^-T. */
SPH_HD static inline double sph_cofactor(const double F[9], int i, int j)
{
    const int r0 = (i + 1) % 3, r1 = (i + 2) % 3, c0 = (j + 1) % 3, c1 = (j + 2) % 3;
    return F[3 * r0 + c0] * F[3 * r1 + c1] - F[3 * r0 + c1] * F[3 * r1 + c0];
}

SPH_HD static inline double sph_det3(const double F[9])
{
    return F[0] * sph_cofactor(F, 0, 0) + F[1] * sph_cofactor(F, 0, 1) +
           F[2] * sph_cofactor(F, 0, 2);
}

/* cos(acos(r)/3 + 2 pi/3) for r in [-1, 1]: the smallest root t of 4 t^3 - 3 t = r, in
 * [-1, -1/2].  As a function of v = sqrt(1 - r) in [0, sqrt 2] it is smooth at both ends (at
 * r = 1 the root is double and t = -1/2 - v/sqrt 6 + ...), so a polynomial of degree 13 in v
 * (Chebyshev interpolation, in powers of v) gives it to 6e-13, for a square root and 13
 * multiply-adds where acos and cos took a tenth of a 3D J2 step. */
SPH_HD static inline double sph_cubic_smallest_root(double r)
{
    const double v = sqrt(1.0 - r);
    double t = -5.0499436039345169e-07; /* Horner, from the highest power (no table: device code too) */
    t = t * v + 5.8193484437651875e-06;
    t = t * v + -3.1639447787630489e-05;
    t = t * v + 0.00010999046411598091;
    t = t * v + -0.00028284931836711972;
    t = t * v + 0.00059839020369508908;
    t = t * v + -0.0011417008712306207;
    t = t * v + 0.002119189610894948;
    t = t * v + -0.0040388736219674473;
    t = t * v + 0.0082298344043034172;
    t = t * v + -0.018900321412135129;
    t = t * v + 0.05555555224484722;
    t = t * v + -0.40824829039446131;
    t = t * v + -0.50000000000023759;
    return t;
}

/* The square of the smallest principal stretch of F: the smallest eigenvalue of C = F^T F.
 * In 2D (plane strain, F_yy = 1) of the in-plane block, in closed form; in 3D the
 * trigonometric solution of the characteristic cubic, to about 1e-9 relative (a few 1e-7
 * where two stretches coincide; tests/unit/test_stretch.c). */
SPH_HD static inline double sph_stretch2_least(const double F[9], int dim)
{
    double C[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            C[3 * r + c] = F[r] * F[c] + F[3 + r] * F[3 + c] + F[6 + r] * F[6 + c];
    if (dim == 2) {
        const double m = 0.5 * (C[0] + C[8]), d = 0.5 * (C[0] - C[8]);
        return m - sqrt(d * d + C[2] * C[2]);
    }
    const double off = C[1] * C[1] + C[2] * C[2] + C[5] * C[5];
    const double q = (C[0] + C[4] + C[8]) / 3.0;
    const double d0 = C[0] - q, d1 = C[4] - q, d2 = C[8] - q;
    const double p = sqrt((d0 * d0 + d1 * d1 + d2 * d2 + 2.0 * off) / 6.0);
    /* a multiple of I: q (a select, as the clamp below: no branch, so that a loop over
     * particles calling this can be vectorised) */
    const int iso = p <= 1e-14 * fabs(q);
    const double ip = iso ? 0.0 : 1.0 / p;
    const double b0 = d0 * ip, b1 = d1 * ip, b2 = d2 * ip, b01 = C[1] * ip, b02 = C[2] * ip,
                 b12 = C[5] * ip;
    double r = 0.5 * (b0 * (b1 * b2 - b12 * b12) - b01 * (b01 * b2 - b12 * b02) +
                      b02 * (b01 * b12 - b1 * b02));
    r = r < -1.0 ? -1.0 : r > 1.0 ? 1.0 : r;
    return iso ? q : q + 2.0 * p * sph_cubic_smallest_root(r); /* cos(acos(r) / 3 + 2 pi / 3) */
}

/* The same with the out-of-plane stretch 1 of plane strain counted in 2D.  A time-step bound
 * uses it, which does not feel the 1e-7. */
SPH_HD static inline double sph_stretch2_min(const double F[9], int dim)
{
    const double l2 = sph_stretch2_least(F, dim);
    return dim == 2 && l2 > 1.0 ? 1.0 : l2;
}

/* 1 / the largest singular value of cof F = J F^-T (in 2D of its in-plane block), which is
 * lambda_min / J: what the artificial viscosity scales its pair's approach rate by to measure
 * it in the pair's reference length as eq. 60 does (templates/body_forces.c).  1 for F = I
 * and for any rotation; 0 for a degenerate F. */
SPH_HD static inline double sph_viscous_scale(const double F[9], int dim)
{
    const double l2 = sph_stretch2_least(F, dim), J = fabs(sph_det3(F));
    return sqrt(l2 > 0.0 ? l2 : 0.0) / (J > 1e-300 ? J : 1e-300);
}

/* C = A B */
SPH_HD static inline void sph_mat3_mul(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
}

/* C = A B^T */
SPH_HD static inline void sph_mat3_mul_bt(const double A[9], const double B[9], double C[9])
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            C[3 * i + j] = A[3 * i] * B[3 * j] + A[3 * i + 1] * B[3 * j + 1] +
                           A[3 * i + 2] * B[3 * j + 2];
}

/* The variables of user expressions (paper Table 1) at one particle. */
typedef struct sph_pt {
    double x0, y0, z0, x, y, z, ux, uy, uz, t, dt, dx;
} sph_pt;

SPH_HD static inline void sph_point(const sph_body *b, int i, int dim, double t, double dt, sph_pt *p)
{
    double X[3] = {0, b->y_plane, 0}, U[3] = {0, 0, 0};
    for (int k = 0; k < dim; k++) {
        X[sph_axis(dim, k)] = b->X[(size_t)i * dim + k];
        U[sph_axis(dim, k)] = b->u[(size_t)i * dim + k];
    }
    p->x0 = X[0], p->y0 = X[1], p->z0 = X[2];
    p->ux = U[0], p->uy = U[1], p->uz = U[2];
    p->x = X[0] + U[0], p->y = X[1] + U[1], p->z = X[2] + U[2];
    p->t = t, p->dt = dt, p->dx = b->dx;
}

#ifdef __cplusplus
}
#endif
#endif
