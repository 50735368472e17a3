/* body_desc.h — a body as the scene describes it (generated code fills these): its region
 * and material constants, boundary conditions, measurements, fracture and contact
 * properties. */
#ifndef SPHRT_SCENE_BODY_DESC_H
#define SPHRT_SCENE_BODY_DESC_H

#include "geom/region.h"

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
    /* its time window, `from t0 to t1` (-INFINITY, INFINITY without one): the set-up warns
     * of a window that opens only after the run's end */
    double t0, t1;
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
    int temperature;            /* 1 + the state value holding the temperature [K]; 0: none */
    double heat_capacity;       /* its specific heat [J/(kg K)]: the body's heat is
                                   sum m c (T - T at the start) */
    int viscous;                /* 1: artificial viscosity, whose dissipated energy the run
                                   reports */
    int vheat;                  /* 1 + the state value the artificial viscosity's heat [J/m^3]
                                   is added to after each step (a law's `viscousheat`; b->vq);
                                   0: none */
    int crush;                  /* 1: the time step follows the current spacing where the body
                                   is compressed (sph_model.dt_lambda_on; lam2 below) */
    /* `clamp P, N`: clamped on the plane through clamp_p with unit normal clamp_n into the
     * body, the particles behind it the mirror images of those in front (run/clamp.c) */
    int clamp;
    double clamp_p[3], clamp_n[3];
    const char *clamp_where;    /* its model line, for messages */
    int wavespeed;              /* 1: the law gives its wave speed, which the compression bound
                                   takes with the stretch (lam2 below) */
    double lam2_rest;           /* with wavespeed: the squared stretch the bound takes at rest,
                                   (c0 / the law's wave speed at F = I)^2 where that is above
                                   c0, else 1 (0: 1), before the first stress pass gives it */
    int fdot;                   /* 1: the law reads the rate of F (the gradient pass sums the
                                   velocity's gradient into Ad; CPU lists) */
    int quadratic;              /* 1: the corrected gradient exact for quadratic fields, with
                                   its strain-gradient quadrature (pairs/quadratic.h); CPU */
    int offset_blocks;          /* the CPU's pair passes by offset blocks where the body is a
                                   lattice (offset_blocks.c): bit 0 the gradient pass, bit 1
                                   the momentum pass; 0: the lists alone */
    /* Contact with the other bodies (scenes with contact, see sph_contact_desc). */
    double young, poisson;      /* elastic constants of the contact stiffness */
    double restitution;         /* coefficient of restitution, 0 < e <= 1 */
    double friction;            /* Coulomb friction coefficient */
} sph_body_desc;

#endif
