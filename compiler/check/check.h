/* check.h — the second stage, the syntax tree checked into the Model (model/model.h); the
 * helpers its files share (check*.c). */
#ifndef SPHC_CHECK_H
#define SPHC_CHECK_H

#include "model/admissible.h"
#include "model/elastic.h"
#include "model/model.h"

/* Check the program; returns 0 and fills *m when there are no errors. */
int check_program(const Program *p, Model *m);

/* The settings of a scene or a body seen so far, to refuse one given twice. */
typedef struct {
    NameIndex keys;           /* key -> its setting in first[] */
    const Setting **first;
    int n;
} SeenSettings;
/* 0 the first time s's key is seen; -1 after reporting it as given twice (with a note at
 * the first).  `where` names the scene or the body for the message. */
int setting_once(SeenSettings *seen, const Setting *s, const char *where);
void seen_settings_free(SeenSettings *seen);

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
int quad_spans(const double p[4][3], SrcLoc loc, const char *what);
int check_body(Model *m, const BodyDecl *d, BodyModel *b);
int check_region(const Model *m, const ShapeExpr *s, Region *r);

/* Fracture (check_fracture.c): a fracture(...), notch or restrict item of a body, and
 * the body's consistency once all its items are read. */
int check_fracture_item(const Model *m, const BodyItem *it, FractureModel *f);
int check_fracture_body(const BodyModel *b, const BodyDecl *d);

/* A reference solution's (t, value) rows from a CSV file (reference_csv.c); errors at loc. */
int reference_csv_read(const char *path, SrcLoc loc, double **t, double **v, int *n);

#endif
