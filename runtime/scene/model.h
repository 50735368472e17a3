/* model.h — the scene description that generated code fills (sph_model: the bodies, the
 * time integration, contact, expectations, the generated passes) and hands to sph_main, and
 * what its device passes exchange with the runtime (sph_advance, sph_monitor_sums). */
#ifndef SPHRT_SCENE_MODEL_H
#define SPHRT_SCENE_MODEL_H

#include <signal.h>

#include "body_desc.h"
#include "core/kernel.h"

typedef enum { SPH_VERLET = 0, SPH_SYMPLECTIC = 1 } sph_integrator;

typedef struct sph_body sph_body;
typedef struct sph_sim sph_sim;
struct sph_monitor_sums;
struct sph_advance;

/* Contact between the particles of different bodies (contact/contact.c): particles are
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
    /* 1: built with sphc --no-simd, scalar code: the pair passes on the half lists alone, as
     * the program's --no-stencil makes them (no lattice stencil, no offset blocks). */
    int scalar;

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
     * state and looks itself only when these show something wrong (run/monitor.c). */
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
     * (a run with checkpoints stopping at once, run/run.c) */
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

#endif
