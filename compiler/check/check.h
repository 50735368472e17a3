/* check.h — helpers shared by the checker's files (check*.c, elastic.c). */
#ifndef SPHC_CHECK_H
#define SPHC_CHECK_H

#include "model.h"

typedef struct {
    const Model *model;
    char **params;      /* function parameters in scope */
    int nparams;
    int allow_vars;     /* particle variables x0 ... dx allowed */
    int allow_skip;     /* `skip` allowed as a branch of if */
    const char *what;   /* context for messages, e.g. "a boundary condition" */
} ExprScope;

/* Check a scalar expression; tail = e is in tail position (skip allowed there).
 * Returns 0 or -1 after reporting. */
int check_scalar_expr(const ExprScope *s, const Expr *e, int tail);
int check_const_expr(const Model *m, const Expr *e, const char *what, double *out);
int check_vec3(const Model *m, const Expr *e, const char *what, double out[3]);

/* Bodies (check_body.c). */
int check_body(Model *m, const BodyDecl *d, BodyModel *b);
int check_region(const Model *m, const ShapeExpr *s, Region *r);

/* Fracture (check_fracture.c): a fracture(...), notch or restrict item of a body, and
 * the body's consistency once all its items are read. */
int check_fracture_item(const Model *m, const BodyItem *it, FractureModel *f);
int check_fracture_body(const BodyModel *b, const BodyDecl *d);

/* A reference solution's (t, value) rows from a CSV file (reference_csv.c); errors at loc. */
int reference_csv_read(const char *path, SrcLoc loc, double **t, double **v, int *n);

/* Elastic constants (elastic.c): from the named arguments of a material use. */
typedef struct {
    int has_E, has_nu, has_lambda, has_mu, has_K;
    double E, nu, lambda, mu, K;
} ElasticInput;
int elastic_complete(const ElasticInput *in, SrcLoc loc, BodyModel *b);

/* Material laws (law.c): check a law's statements with the body's arguments. */
int law_check(const Model *m, const MaterialDef *law);

#endif
