/* ast.h — the syntax tree produced by the parser (and, later, the XML importer).
 *
 * The tree is plain data: every node carries its source location, and later stages
 * (check.c, lower.c) read it without changing it.  Lists are growable arrays. */
#ifndef SPHC_AST_H
#define SPHC_AST_H

#include <stddef.h>
#include <stdio.h>

#include "lang/bc_kinds.h"
#include "util/source.h"

/* ---------------------------------------------------------------- expressions */

typedef enum {
    EX_NUM,    /* num                                         */
    EX_NAME,   /* name: variable, constant, parameter, local  */
    EX_VEC,    /* [a, b, c]: args                             */
    EX_UNARY,  /* op args[0]            (op: '-', '!' = not)  */
    EX_BINARY, /* args[0] op args[1]                           */
    EX_CALL,   /* name(args...)  (functions, if(c,a,b) too)   */
    EX_SKIP    /* the keyword skip                            */
} ExprKind;

/* Binary and unary operators. */
typedef enum {
    OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_POW,
    OP_LT, OP_GT, OP_LE, OP_GE, OP_EQ, OP_NE,
    OP_AND, OP_OR,
    OP_NEG, OP_NOT
} OpKind;

typedef struct Expr Expr;
struct Expr {
    ExprKind kind;
    SrcLoc loc;
    double num;     /* EX_NUM */
    char *name;     /* EX_NAME, EX_CALL */
    OpKind op;      /* EX_UNARY, EX_BINARY */
    Expr **args;    /* EX_VEC, EX_UNARY (1), EX_BINARY (2), EX_CALL */
    int nargs;
    int depth;      /* levels of nodes from here down: 1 for a leaf */
};

/* The deepest expression or shape the front ends accept: later stages walk the tree
 * recursively, and a chain such as 1 + 1 + ... + 1 parses into one level per operator. */
#define AST_MAX_DEPTH 1000
/* The deepest nesting of blocks (if, else, tension) in a material law: the law evaluator
 * takes several kilobytes of stack per level. */
#define AST_MAX_BLOCK_DEPTH 100

/* "key value" pair: scene settings, body settings, named arguments of a call
 * such as box(from [..] to [..]) or svk(density 1000, shear 0.7e6).  A named argument may
 * be a string instead, surface(file "beam.vtk"): then text is set and nvalues is 0. */
typedef struct {
    char *key;
    SrcLoc loc;
    Expr **values; /* one or more, comma separated in the source */
    int nvalues;
    char *text;    /* a string value (without its quotes), or NULL */
} Setting;

typedef struct {
    Setting *items;
    int n;
} SettingList;

/* name(named args): shapes and material uses. */
typedef struct {
    char *name;
    SrcLoc loc;
    SettingList args;
} NamedCall;

/* ---------------------------------------------------------------- material laws */

typedef enum {
    MS_LET,    /* let name = expr                        */
    MS_STRESS, /* stress name = expr   (2nd Piola-Kirchhoff) */
    MS_ENERGY, /* energy name = expr   (strain energy density); energy name(C) = expr */
    MS_STATE,  /* state name = expr    (per-particle state, its initial value) */
    MS_IF,     /* if cond { body } else { orelse }        */
    MS_BLOCK,  /* named block, e.g. tension { ... }       */
    MS_ASSIGN, /* name = expr          (a new value of a let or state) */
    MS_DISSIPATION, /* dissipation name: state `name` is the dissipated energy density */
    MS_REQUIRE, /* require cond [, "message"]: what the parameters must satisfy (law_require.c) */
    MS_TEMPERATURE, /* temperature name, c: state `name` is a temperature, c its specific heat */
    MS_WAVESPEED, /* wavespeed c: the particle's longitudinal wave speed now (the time step) */
    MS_VISCOUSHEAT /* viscousheat name: state `name` gathers the artificial viscosity's heat */
} MatStmtKind;

typedef struct MatStmt MatStmt;
typedef struct {
    MatStmt *items;
    int n;
} MatStmtList;

struct MatStmt {
    MatStmtKind kind;
    SrcLoc loc;
    char *name;        /* LET/STRESS/ENERGY/STATE/ASSIGN target, BLOCK name */
    Expr *value;       /* LET/STRESS/ENERGY/STATE/ASSIGN value, IF/REQUIRE condition,
                        * TEMPERATURE specific heat, WAVESPEED its speed */
    MatStmtList body;  /* IF then-part, BLOCK contents */
    MatStmtList orelse;/* IF else-part */
    int depth;         /* levels of blocks from here down: 1 for a statement without */
    char *of;          /* ENERGY: the variable it is a function of (C or E), or NULL */
    char *message;     /* REQUIRE: its message (without the quotes), or NULL */
};

typedef struct {
    char *name;
    SrcLoc loc;
    char **params; /* parameter names, e.g. lambda, mu */
    SrcLoc *param_locs;
    int nparams;
    MatStmtList body;
} MaterialDef;

/* ---------------------------------------------------------------- bodies */

/* Shapes: a primitive call or a union/difference of shapes. */
typedef struct ShapeExpr ShapeExpr;
struct ShapeExpr {
    char op;           /* 0 = primitive, '+' = union, '-' = difference */
    SrcLoc loc;
    NamedCall prim;    /* op == 0: box(...), cylinder(...), sphere(...), surface(...) */
    ShapeExpr *lhs, *rhs;
    int depth;         /* levels of nodes from here down: 1 for a primitive */
};

/* velocity x, z = expr [from t0] [to t1] [near shape]
 * force surface z = expr [from t0] [to t1] [near shape] */
typedef struct {
    BcKind kind;       /* lang/bc_kinds.h */
    SrcLoc loc;
    int comps;         /* bit mask: 1 = x, 2 = y, 4 = z */
    SrcLoc comps_loc;
    Expr *value;
    Expr *t_from;      /* NULL: from the start */
    Expr *t_to;        /* NULL: until the end */
    ShapeExpr *near;   /* NULL: the whole body */
} BcDecl;

/* measure name plane [p1] [p2] [p3] [p4] */
typedef struct {
    char *name;
    SrcLoc loc;
    Expr *points[4];
} MeasureDecl;

typedef enum {
    BI_SHAPE,    /* shape <shape expr>               */
    BI_MATERIAL, /* material name(named args)        */
    BI_SETTING,  /* refine 4, viscosity 0.015, 0.01  */
    BI_BC,       /* velocity / force                  */
    BI_MEASURE,  /* measure ...                       */
    BI_NOTCH,    /* notch [p1] [p2] [p3] [p4]   (points in `measure`) */
    BI_FRACTURE  /* fracture(Gc 3, length 0.125e-3, limit 0.1)  (in `material`) */
} BodyItemKind;

typedef struct {
    BodyItemKind kind;
    SrcLoc loc;
    ShapeExpr *shape;
    NamedCall material; /* BI_MATERIAL, BI_FRACTURE */
    Setting setting;
    BcDecl bc;
    MeasureDecl measure;
} BodyItem;

typedef struct {
    char *name;
    SrcLoc loc;
    BodyItem *items;
    int n;
    char *comment;       /* comment lines to print before it (--to-sph of a case), or NULL */
} BodyDecl;

/* ---------------------------------------------------------------- expectations */

/* expect period tip.uz = 0.2553 within 3%
 * expect amplitude tip.uz = 23.2e-3 within 5%
 * expect energy within 2%
 * reference tip.uz = expr(t) [within 5%]
 * reference tip.uz = file "tip.csv" [within 5%]                  */
typedef enum { EXPECT_PERIOD, EXPECT_AMPLITUDE, EXPECT_ENERGY, EXPECT_REFERENCE } ExpectKind;

typedef struct {
    ExpectKind kind;
    SrcLoc loc;
    char *measure;     /* "tip" (NULL for energy) */
    char *quantity;    /* "uz", "fx", ...          */
    SrcLoc target_loc;
    Expr *value;       /* expected value, or reference expression of t */
    Expr *tolerance;   /* percent; NULL for a bare reference */
    char *file;        /* reference from a CSV file of (t, value) rows (value NULL) */
    SrcLoc file_loc;
} ExpectDecl;

/* ---------------------------------------------------------------- top level */

typedef enum { IT_IMPORT, IT_SCENE, IT_LET, IT_FN, IT_MATERIAL, IT_BODY, IT_EXPECT } ItemKind;

typedef struct {
    ItemKind kind;
    SrcLoc loc;
    char *name;          /* IMPORT module, LET/FN name */
    Expr *value;         /* LET value, FN body */
    char **params;       /* FN parameters */
    int nparams;
    SettingList scene;   /* IT_SCENE */
    MaterialDef material;/* IT_MATERIAL */
    BodyDecl body;       /* IT_BODY */
    ExpectDecl expect;   /* IT_EXPECT */
} Item;

typedef struct {
    Item *items;
    int n;
    const char *file;    /* main model file */
    int from_xml;        /* imported from a SoliDualSPHysics case file (xml_import) */
    char *comment;       /* the case's own comment lines (--to-sph prints them), or NULL */
} Program;

/* ---------------------------------------------------------------- construction (ast.c) */

Expr *ast_num(SrcLoc loc, double v);
Expr *ast_name(SrcLoc loc, const char *name);
Expr *ast_unary(SrcLoc loc, OpKind op, Expr *a);
Expr *ast_binary(SrcLoc loc, OpKind op, Expr *a, Expr *b);
Expr *ast_call(SrcLoc loc, const char *name, Expr **args, int nargs);
Expr *ast_vec(SrcLoc loc, Expr **args, int nargs);
Expr *ast_skip(SrcLoc loc);

/* arr, a list of count elements that grows one element at a time, with room for one more:
 * the room doubles when count reaches a power of two, so that n appends copy O(n) elements;
 * exits when memory runs out.  (The append helpers below instead keep arrays of exactly n
 * elements, which may come from elsewhere.) */
void *ast_room(void *arr, size_t count, size_t elem);

/* Append helpers for the growable arrays (ast.c). */
void ast_push_expr(Expr ***arr, int *n, Expr *e);
void ast_push_setting(SettingList *l, Setting s);
/* The first setting of l named key, or NULL. */
const Setting *ast_find_setting(const SettingList *l, const char *key);
void ast_push_matstmt(MatStmtList *l, MatStmt s);
void ast_push_bodyitem(BodyDecl *b, BodyItem it);
void ast_push_item(Program *p, Item it);
void ast_push_name(char ***arr, SrcLoc **locs, int *n, const char *name, SrcLoc loc);

/* Parse a model file into prog (appending its items).  Returns the number of
 * errors reported (0 on success).  Errors go to stderr as file:line:col. */
int parse_file(const char *path, Program *prog);
/* Forget the names parse_file interned (their table, not the names): for a program that
 * parses many models in one process and frees each tree before the next. */
void lex_forget_names(void);

/* Print the tree (sphc --dump=ast). */
void ast_dump(const Program *p, FILE *out);

const char *op_spelling(OpKind op);

/* ---------------------------------------------------------------- more helpers (ast.c, ast_dump.c) */

/* Allocation that never returns NULL (prints "out of memory" and exits). */
void *ast_alloc(size_t size);
char *ast_strdup(const char *s);

/* A setting / named argument with its first value; further values are added
 * with ast_push_expr(&s.values, &s.nvalues, e). */
Setting ast_setting(SrcLoc loc, const char *key, Expr *value);
/* A named argument whose value is a string. */
Setting ast_setting_text(SrcLoc loc, const char *key, const char *text);
/* Shapes: a primitive, or lhs op rhs with op '+' (union) or '-' (difference). */
ShapeExpr *ast_shape_prim(NamedCall call);
ShapeExpr *ast_shape_op(SrcLoc loc, char op, ShapeExpr *lhs, ShapeExpr *rhs);
/* A material-law statement without nested blocks (LET/STRESS/ENERGY/STATE),
 * or the head of an IF/BLOCK whose lists are filled in afterwards. */
MatStmt ast_matstmt(MatStmtKind kind, SrcLoc loc, const char *name, Expr *value);
/* Component bit of an axis name: x -> 1, y -> 2, z -> 4, anything else -> 0. */
int ast_axis_bit(const char *name);

/* Print one expression, fully parenthesised, on one line (no newline). */
void ast_dump_expr(const Expr *e, FILE *out);

#endif
