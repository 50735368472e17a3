/* xml_internal.h — what the files of the XML importer share (xml_*.c).
 *
 *   xml_read.c      loading the file, the <case> tree, assembling the Program
 *   xml_util.c      elements, attributes and their values, with errors naming both
 *   xml_expr.c      the expression language of attribute values and <userexpression>s
 *   xml_scene.c     <constantsdef> and <execution><parameters>: the scene settings
 *   xml_geometry.c  <geometry>: the GenCase lattice, <drawbox>, <drawcylinder>, <drawfile*>
 *   xml_transform.c GenCase's transformation matrix (<move>, <rotate>, <scale>, ...)
 *   xml_shape.c     the drawings of an mk as an sph shape (and lattice) of a body or `near`
 *   xml_mathexpr.c  <mathexpressions>: user expressions and their locals (lets)
 *   xml_deform.c    <deformstrucs>: bodies, material and settings cards; the constitutive models
 *   xml_fracture.c  the phase-field fracture cards of a body
 *   xml_bc.c        <bcvel>, <bcforce>, <measureplane> of a body
 *   xml_functions.c shapes the expressions write out twice, as user functions
 *
 * Every value keeps the line of its element: errors read "file:line: error: <elem>: ...". */
#ifndef SPHC_XML_INTERNAL_H
#define SPHC_XML_INTERNAL_H

#include <libxml/tree.h>

#include "front/ast.h"
#include "model/admissible.h"
#include "xml.h"

/* One drawing of the mainlist.  lo..hi: the GenCase lattice nodes a <drawbox> covers, per
 * axis, or those of the bounding box of another drawing (inclusive; in 2D y is 0..0). */
typedef enum { XD_BOX, XD_CYLINDER, XD_SURFACE, XD_SPHERE, XD_PRISM, XD_PYRAMID } XmlDrawKind;

/* GenCase's affine transformation of the drawings (xml_transform.c): x -> A x + a[.][3]. */
typedef struct {
    double a[3][4];
} XmlMatrix;

/* The mk of drawings made after <setmkvoid/>: they take nodes over from every mk and give
 * them to none.  Before any <setmk...> the mk is XML_MK_NONE. */
enum { XML_MK_NONE = -1, XML_MK_VOID = -2 };

/* The largest line a libxml2 node holds (16 bits); an element past it keeps its line in psvi
 * (xml_read.c), which xml_loc reads. */
enum { XML_NODE_LINE_MAX = 65535 };

typedef struct {
    XmlDrawKind kind;
    int mk;
    long lo[3], hi[3];
    double p[2][3], r;        /* <drawcylinder>: the ends of its axis and its radius;
                                 <drawsphere>: its centre (p[0]) and radius (in a 2D case
                                 the disc it cuts from the plane of the case) */
    const char *file;         /* <drawfilevtk>, <drawfilestl>: the file, as written */
    double *pts;              /* <drawprism>, <drawpyramid>: npts corners, in the order of */
    int npts;                 /* the card (a prism: the base's, then the top's) */
    int freedraw;             /* drawn in GenCase's free drawing mode (<setfrdrawmode>) */
    SrcLoc loc;
    const XmlMatrix *map;     /* a surface drawn under a transformation: it, else NULL */
    double reach[2][3];       /* a drawing other than a box: its bounding box */
} XmlDraw;

/* The constitutive models of <constitmodel value="N">, N = 1 .. XML_NLAWS (xml_deform.c): laws
 * of the standard library (stdlib/<law>.sph), imported and used by that name. */
enum { XML_NLAWS = 3, XML_LAW_CARDS = 2 };
typedef struct {
    const char *law;
    const char *what;                   /* the model in messages about its own cards */
    const char *cards[XML_LAW_CARDS];   /* the cards of its own parameters, all required */
    const char *args[XML_LAW_CARDS];    /* the law's arguments they give */
    int no_fracture;                    /* SoliDualSPHysics turns fracture off under it */
} XmlLaw;

/* One <userexpression>: its expression with its locals renamed to the model's lets. */
typedef struct {
    int id;
    Expr *value;
    SrcLoc loc;
} XmlUserExpr;

typedef struct {
    const char *file;
    XmlOptions opt;           /* sphc's --xml-* options */
    /* <definition>: the lattice pointmin + k dp, 2D when pointmin.y == pointmax.y */
    int has_domain, dim;
    double dp, pmin[3], pmax[3];
    long nodes[3];            /* largest node number inside the domain, per axis */
    /* <newvar> variables (#name) */
    char **var_names;
    double *var_values;
    int nvars;
    /* the mainlist */
    XmlDraw *draws;
    int ndraws;
    int refused_drawings;     /* drawings beyond the most a case may make */
    int freedraw;             /* <setfrdrawmode auto="true"/> in force */
    const xmlNode *commands;  /* <commands>: the <list>s <runlist> runs */
    XmlMatrix matrix;         /* the transformation in force, and those <matrixsave/> kept */
    XmlMatrix *saved;
    int nsaved;
    long ncommands;           /* commands run so far, lists included */
    /* <mathexpressions> */
    XmlUserExpr *exprs;
    int nexprs;
    Item *lets;               /* IT_LET items for the locals */
    int nlets;
    /* scene settings from <constantsdef>, <parameters> and <deformstrucs> */
    SettingList scene;
    SrcLoc scene_loc;
    int has_end;
    /* bodies, and the constitutive models they use (by constitmodel, xml_law) */
    Item *bodies;
    int nbodies;
    int uses_law[XML_NLAWS + 1];
    SrcLoc law_loc[XML_NLAWS + 1];
    int nmeasures;            /* measurement planes so far (their names count on) */
} XmlCtx;

/* ---------------------------------------------------------------- xml_util.c */

SrcLoc xml_loc(const XmlCtx *x, const xmlNode *n);
const char *xml_name(const xmlNode *n);
int xml_is(const xmlNode *n, const char *name);
/* The text of comment node c (lines trimmed) appended to *acc, a malloc'ed string of
 * lines, or NULL; other nodes leave it as it is. */
void xml_add_comment(const xmlNode *c, char **acc);

/* Element children: for (c = xml_first(n); c; c = xml_next(c)). */
xmlNode *xml_first(const xmlNode *n);
xmlNode *xml_next(const xmlNode *n);
/* The first child element called name, or NULL. */
xmlNode *xml_child(const xmlNode *n, const char *name);
/* An attribute's value (a copy that lives as long as the tree), or NULL. */
char *xml_attr(const xmlNode *n, const char *name);
/* The element's text with surrounding blanks removed (a copy). */
char *xml_text(const xmlNode *n);

/* Every attribute must be one of allowed (NULL-terminated); comment and units_comment
 * are always allowed.  Returns 0 or -1 after reporting each unknown attribute. */
int xml_check_attrs(const XmlCtx *x, const xmlNode *n, const char *const *allowed);
/* Reports each child element not in allowed (NULL-terminated); -1 when there was one. */
int xml_check_children(const XmlCtx *x, const xmlNode *n, const char *const *allowed);

/* A numeric attribute: a number or an expression of the <newvar> variables (#name).
 * Returns 1 when given (value in *out), 0 when absent and not required, -1 on error. */
int xml_number(const XmlCtx *x, const xmlNode *n, const char *attr, int required, double *out);
/* The same for a whole number in [lo, hi]. */
int xml_integer(const XmlCtx *x, const xmlNode *n, const char *attr, int required, long lo,
                long hi, long *out);
/* A card <name value="..."/>: checks its attributes and reads value (required). */
int xml_card_number(const XmlCtx *x, const xmlNode *n, double *out);
/* The same, and the value must be positive. */
int xml_card_positive(const XmlCtx *x, const xmlNode *n, double *out);
/* Whether v, the value of attribute attr of n, is admissible as q (model/admissible.h): 0, or -1 after
 * reporting "<elem> attribute 'attr': REASON (got v)". */
int xml_admissible(const XmlCtx *x, const xmlNode *n, const char *attr, Quantity q, double v);
/* A card <name value="..."/> whose value is admissible as q. */
int xml_card_admissible(const XmlCtx *x, const xmlNode *n, Quantity q, double *out);
/* A card <name value="true|false|1|0"/>. */
int xml_card_bool(const XmlCtx *x, const xmlNode *n, int *out);
/* x, y and z of a point element such as <point x=".." y=".." z=".."/> (all required). */
int xml_point(const XmlCtx *x, const xmlNode *n, double out[3]);

/* The <point> children of n: their number in *count, their coordinates (3 a point) in an
 * array with room for `copies` times as many points; NULL after reporting an error in one
 * of them. */
double *xml_points(const XmlCtx *x, const xmlNode *n, int copies, int *count);

/* A double as the shortest decimal within tol of it (geometry computed from the lattice,
 * so that -1.5e-3 - 0.5e-3 reads -0.002 again). */
double xml_snap(double v, double tol);

/* ---------------------------------------------------------------- xml_expr.c */

/* The longest name of an expression or a local. */
#define XML_MAX_NAME 127

/* Parses text in the expression language of SoliDualSPHysics (paper section 3.4: Table 3
 * precedence, if(c, a, b), skip/Skip).  Names may carry GenCase's '#' marker, which is
 * dropped.  Every node is located at loc; errors name `what` (e.g. "<expression>
 * attribute 'value'") and the position in the text.  Returns NULL after reporting. */
Expr *xml_parse_expr(const char *text, SrcLoc loc, const char *what);
/* Evaluates a constant expression of the <newvar> variables (names[i] = values[i]).
 * Returns 0 or -1 after reporting (unknown name, function, a particle variable, skip). */
int xml_eval(const Expr *e, char *const *names, const double *values, int n, const char *what,
             double *out);
/* Renames the variables called from (not functions) to to, in place. */
void xml_rename(Expr *e, const char *from, const char *to);

/* ---------------------------------------------------------------- sections */

int xml_constants(XmlCtx *x, const xmlNode *constantsdef);
int xml_parameters(XmlCtx *x, const xmlNode *parameters);
/* A scene setting with one value (a number or a word such as wendland). */
void xml_scene_number(XmlCtx *x, SrcLoc loc, const char *key, double v);
void xml_scene_word(XmlCtx *x, SrcLoc loc, const char *key, const char *word);
/* The scene settings in the order a .sph scene lists them. */
SettingList xml_scene_settings(const XmlCtx *x);

int xml_geometry(XmlCtx *x, const xmlNode *geometry);
/* Whether something was drawn with mk. */
int xml_mk_drawn(const XmlCtx *x, int mk);

/* xml_transform.c.  A transformation command (<move>, <rotate>, <rotateline>, <scale>,
 * <matrixreset>, <matrixsave>, <matrixload>) applied to x->matrix: 0, or -1 after
 * reporting; 1 when n is none of them. */
int xml_transform_command(XmlCtx *x, const xmlNode *n);
/* The map of a surface file's drawing (<drawfilestl>, <drawfilevtk>): x->matrix times its
 * own <drawscale> or <drawmove> (either, not both), which apply first: 0, or -1 after
 * reporting. */
int xml_file_transform(XmlCtx *x, const xmlNode *n, XmlMatrix *map);
void xml_matrix_identity(XmlMatrix *m);
int xml_matrix_is_identity(const XmlMatrix *m);
void xml_matrix_point(const XmlMatrix *m, const double p[3], double out[3]);
/* The n points pts (3 coordinates each) through m, in place. */
void xml_matrix_points(const XmlMatrix *m, double *pts, int n);
/* Whether m takes the axes to axes (moves, scales, turns by multiples of 90 degrees about
 * an axis): an axis-aligned box stays one. */
int xml_matrix_keeps_axes(const XmlMatrix *m);
/* s when m's linear part is s times a rotation or reflection (a circle stays a circle of
 * s times the radius), else 0. */
double xml_matrix_similarity(const XmlMatrix *m);
/* Whether m takes the y axis to itself and the x-z plane to itself (a 2D case's plane stays
 * parallel to itself). */
int xml_matrix_keeps_y(const XmlMatrix *m);
/* m as the map of sph_mesh_load_moved: its matrix's columns, then its translation. */
void xml_matrix_columns(const XmlMatrix *m, double xf[12]);

/* xml_shape.c: the sph shape of what GenCase gives mk: its drawings in drawing order, less
 * what later drawings of other mks take over (the auxiliary geometry of a `near`). */
ShapeExpr *xml_mk_shape(const XmlCtx *x, int mk, SrcLoc loc);
/* The shape and lattice of body mk: xml_mk_shape, or with --xml-fill=gencase the shape and
 * lattice corner that give GenCase's particles (docs/xml.md).  *has_corner is set when the
 * body needs a `lattice` corner.  Returns NULL after reporting an error. */
ShapeExpr *xml_mk_body_shape(const XmlCtx *x, int mk, SrcLoc loc, int *has_corner,
                             double corner[3]);
/* Whether mk was drawn with boxes only. */
int xml_mk_boxes_only(const XmlCtx *x, int mk);
/* Bounding box of mk's boxes as sph volumes (node -/+ dp/2). */
void xml_mk_bbox(const XmlCtx *x, int mk, double lo[3], double hi[3]);

int xml_mathexpressions(XmlCtx *x, const xmlNode *mathexpressions);
const XmlUserExpr *xml_user_expr(const XmlCtx *x, long id);

int xml_deformstrucs(XmlCtx *x, const xmlNode *deformstrucs);
/* The model of <constitmodel value="n">, 1 <= n <= XML_NLAWS. */
const XmlLaw *xml_law(int n);

/* Cards of one body that become body items (xml_bc.c).  mk is the body's own mk;
 * refine its mapfac (for the measurement-plane rule). */
int xml_bc(XmlCtx *x, const xmlNode *n, int mk, BodyDecl *body);
int xml_measureplane(XmlCtx *x, const xmlNode *n, int mk, int refine, BodyDecl *body);

/* ---------------------------------------------------------------- xml_fracture.c */

/* The cards <Gc>, <pflenscale>, <pflim>, in that order. */
enum { XF_GC, XF_LENGTH, XF_LIMIT, XF_N };

/* The fracture cards of one body, read whether or not <fracture> turns fracture on. */
typedef struct {
    const xmlNode *first;          /* the first fracture card (for the warning when off) */
    const xmlNode *card[XF_N];     /* the last <Gc>, <pflenscale>, <pflim>; NULL: absent */
    double value[XF_N];
    const xmlNode *restrict_card;  /* <restrictphi>, or NULL */
    long restrict_id;              /* the <userexpression> it names */
    BodyItem *notches;             /* BI_NOTCH items, one per <notch> */
    int nnotches;
} XmlFracture;

/* Reads and checks n into f when it is one of the cards above, <notch> or <restrictphi>:
 * 0, or -1 after reporting; 1 when n is none of them. */
int xml_fracture_card(const XmlCtx *x, const xmlNode *n, XmlFracture *f);
/* With fracture on (the card `fracture`): <Gc> and <pflenscale> are required; -1 after
 * reporting each one missing, naming body mk. */
int xml_fracture_check(const XmlCtx *x, const XmlFracture *f, const xmlNode *fracture, int mk);
/* The body items of fracture on: fracture(Gc, length, limit), restrict, the notches. */
void xml_fracture_items(const XmlCtx *x, const XmlFracture *f, const xmlNode *fracture,
                        BodyDecl *b);

/* The bodies' BC expressions with every shape they write out for two arguments turned into
 * a user function of one parameter (xml_functions.c): the functions (IT_FN items, to come
 * after the lets) in *fns, their number returned. */
int xml_factor_functions(XmlCtx *x, Item **fns, int *nfns);

#endif
