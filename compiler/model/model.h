/* model.h — the checked model: names resolved, constants folded, settings turned into
 * numbers, elastic constants completed.  Produced by check.c from the AST; read by
 * lower.c and the emitters.  Expressions stay as AST nodes (already checked) because the
 * emitters print them as C; the model records what each name refers to. */
#ifndef SPHC_MODEL_H
#define SPHC_MODEL_H

#include "front/ast.h"
#include "util/name_index.h"
#include "body_settings.h"

/* in the order of sph_shape_kind (runtime/geom/region.h) */
typedef enum { SHAPE_BOX, SHAPE_CYLINDER, SHAPE_SPHERE, SHAPE_SURFACE, SHAPE_PRISM,
               SHAPE_PYRAMID } ShapeKind;

typedef struct {
    ShapeKind kind;
    double a[3], b[3], r;   /* as sph_shape (runtime/geom/region.h); a surface, prism or pyramid:
                             * its bounding box */
    int subtract;
    char *file;             /* surface: the file, absolute (read by the program at run time) */
    double *pts;            /* prism, pyramid: npts corners, as sph_shape's; surface: NULL
                             * or the map that moves it (npts 4, sph_mesh_load_moved) */
    int npts;
    double volume;          /* surface, prism, pyramid: the volume it encloses */
} ShapePrim;

typedef struct {
    ShapePrim *prims;
    int n;
} Region;

typedef struct {
    char *name;
    double value;
    SrcLoc loc;
} ConstDef;

typedef struct {
    char *name;
    char **params;
    int nparams;
    Expr *body;
    SrcLoc loc;
    double size;    /* nodes of its body with every call of a function written out */
} FnDef;

typedef struct {
    BcKind kind;        /* lang/bc_kinds.h */
    int comps;          /* bit mask over 3D axes: 1 = x, 2 = y, 4 = z */
    Expr *value;
    int has_window;
    double t0, t1;      /* active for t0 <= t <= t1 */
    int has_near;
    Region near;
    SrcLoc loc;
} BcModel;

typedef struct {
    char *name;
    double p[4][3];
    SrcLoc loc;
} MeasureModel;

/* Phase-field fracture of a body (paper section 2.2, eq. 6-9, 61-63). */
typedef struct {
    int on;
    SrcLoc loc;                    /* the fracture(...) item */
    double Gc;                     /* critical energy release rate, J/m^2 */
    double eps0;                   /* phase-field length scale, m */
    double limit;                  /* s_l of eq. 63: F = I where s <= s_l */
    double (*notches)[4][3];       /* quads; pairs crossing one are cut at set-up */
    SrcLoc *notch_locs;            /* per notch: its item */
    int nnotches;
    Expr *restrict_expr;           /* lower bound of s per particle (skip: none), or NULL */
    SrcLoc restrict_loc;
} FractureModel;

typedef struct BodyModel {
    char *name;
    SrcLoc loc;
    Region region;
    double rho0;
    double E, nu, lambda, mu, K;   /* elastic constants, all five derived */
    double c0;                     /* eq. 59, or the `soundspeed` setting */
    /* the settings of body_settings.h's table: refine, nbsrange, hourglass, lattice,
     * restitution, friction, soundspeed (0: eq. 59's), ... */
    BODY_SETTINGS(SETTING_MEMBER)
    /* and the settings with members of their own (SET_OWN): */
    double beta1, beta2;           /* `viscosity beta1 beta2`: artificial viscosity, eq. 58 */
    int has_plane;                 /* 2D: `plane y0`, the y of the plane the shapes are cut in */
    double plane;
    SrcLoc plane_loc;
    /* `clamp P, N`: clamped on the plane through P with unit normal N into the body, by the
     * mirror images of its particles (runtime/run/clamp.c) */
    int has_clamp;
    double clamp_p[3], clamp_n[3];
    SrcLoc clamp_loc;
    const MaterialDef *law;
    double *law_args;              /* value of each law parameter, in law order */
    BcModel *bcs;
    int nbcs;
    MeasureModel *measures;
    int nmeasures;
    FractureModel fracture;
} BodyModel;

/* A body's settings by row of the table (body_settings.h; body_setting_rows.c): */
/* The row of keyword, or NULL. */
const BodySetting *body_setting_find(const char *keyword);
/* Every setting of b at its default. */
void body_settings_default(BodyModel *b);
/* The value of setting s of b (SET_POINT: whether given; SET_OWN: 0). */
double body_setting_value(const BodyModel *b, const BodySetting *s);
/* Where its value goes: an int (SET_INT), a double or three (SET_NUMBER, SET_POINT). */
int *body_setting_int(BodyModel *b, const BodySetting *s);
double *body_setting_number(BodyModel *b, const BodySetting *s);
/* SET_POINT: its three numbers, to read (NULL for the other forms). */
const double *body_setting_point(const BodyModel *b, const BodySetting *s);
/* SET_POINT: the flag that it was given. */
int *body_setting_given(BodyModel *b, const BodySetting *s);

typedef struct {
    ExpectKind kind;
    SrcLoc loc;
    int body, measure, quantity;   /* quantity 0..2 = ux uy uz, 3..5 = fx fy fz */
    double value, tolerance;       /* tolerance relative (0.03), < 0: report only */
    Expr *reference;               /* EXPECT_REFERENCE: expression of t, or NULL and ... */
    double *ref_t, *ref_v;         /* ... a table of (t, value) rows from a CSV file */
    int ref_n;
    const char *ref_file;
} ExpectModel;

typedef enum { KERNEL_WENDLAND = 0, KERNEL_CUBIC = 1 } KernelKind;
typedef enum { INTEGRATOR_VERLET = 0, INTEGRATOR_SYMPLECTIC = 1 } IntegratorKind;
/* `timestep`: eq. 65 follows the current spacing of compressed bodies where the Courant
 * number on it would exceed SPH_CFL_CURRENT (auto), always (stretch), or never (undeformed:
 * the paper's bound, on the undeformed spacing); docs/stability.md */
/* The corrected gradient: eq. 63's, exact for linear fields, or the fit exact for quadratic
 * ones with its strain-gradient quadrature (templates/body_quadratic.c). */
typedef enum { GRADIENT_LINEAR = 0, GRADIENT_QUADRATIC = 1 } GradientKind;
typedef enum { TIMESTEP_AUTO = 0, TIMESTEP_UNDEFORMED = 1, TIMESTEP_STRETCH = 2 } TimestepKind;
#define SPH_CFL_CURRENT 0.4

typedef struct {
    const char *name;     /* program name (file stem) */
    const char *source;   /* model file */
    int dim;
    double dp, coefh, cfl, dtmin, dt, t_end, t_out;
    double t_checkpoint;  /* scene `checkpoint`: the interval of checkpoints, 0 none */
    KernelKind kernel;
    IntegratorKind integrator;
    int single;           /* precision single: the pair passes' arrays in float */
    TimestepKind dt_mode; /* how eq. 65 sees compressed bodies (docs/stability.md) */
    GradientKind gradient;
    SrcLoc gradient_loc;  /* where the scene sets it (for the targets that refuse it) */
    double gravity[3];
    ConstDef *consts;
    int nconsts;
    FnDef *fns;
    int nfns;
    NameIndex const_index, fn_index; /* name -> index in consts, fns (model_add_*) */
    const MaterialDef **laws;
    int nlaws;
    BodyModel *bodies;
    int nbodies;
    ExpectModel *expects;
    int nexpects;
    int compat_outputs;   /* also write SoliDualSPHysics' output files (imported cases) */
    int no_simd;          /* sphc --no-simd: scalar CPU code (lower/layouts.c, the update) */
    double contact;       /* contact stiffness multiplier (1); 0: bodies pass through each other */
} Model;

/* 1 when the scene's bodies touch each other: several bodies and contact not switched off. */
static inline int model_has_contact(const Model *m) { return m->nbodies > 1 && m->contact > 0; }
/* The time step's bound on compression: an adaptive step not `timestep undeformed`. */
static inline int model_has_crush(const Model *m)
{
    return m->dt <= 0 && m->dt_mode != TIMESTEP_UNDEFORMED;
}

/* Print the checked model (sphc --dump=model). */
void model_dump(const Model *m, FILE *out);

#endif
