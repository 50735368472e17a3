/* parser.y — grammar of the sph modelling language (docs/language.md).
 *
 * A pure (reentrant) LALR parser with lookahead correction, so the expected
 * tokens in syntax errors are exact.  Error recovery works per item: an error
 * inside a top-level item, a scene/body/material block or an if/named block of
 * a material law discards tokens up to the start of the next statement of that
 * list, so several errors are reported per file.  A block whose '}' is missing
 * before a new top-level item (or the end of the file) is closed implicitly
 * with an "expected '}'" error, and parsing continues with that item.
 *
 * Top-level items are appended to ParseState.prog as soon as they are reduced
 * (a "let a = 1, b = 2" gives one IT_LET item per name).
 *
 * Locations: Item.loc is the name for import/let/fn and the keyword otherwise;
 * MaterialDef.loc and BodyDecl.loc are the names; a LET/STRESS/ENERGY/STATE
 * statement is located at its name, IF at the keyword, a named block at its
 * name; a binary or unary expression at its operator, a call at its name, a
 * vector at its '['; a setting or named argument at its key; BcDecl.loc at
 * velocity/force and comps_loc at the first component; ExpectDecl.loc at
 * expect/reference and target_loc at the measure name. */

%define api.pure full
%define api.value.type union
%define api.token.prefix {TK_}
%define parse.error custom
%define parse.lac full
%locations

%param {yyscan_t scanner}
%parse-param {ParseState *ps}

%code requires {
#include "front/ast.h"

#ifndef YY_TYPEDEF_YY_SCANNER_T
#define YY_TYPEDEF_YY_SCANNER_T
typedef void *yyscan_t;
#endif

/* The longest model file, identifier or number, and string (a file name) the scanner takes. */
enum { LEX_MAX_FILE = 256 << 20, LEX_MAX_NAME = 1024, LEX_MAX_STRING = 4096 };

/* Scanner state (yyextra of the flex scanner). */
typedef struct LexState {
    const char *file;        /* SrcLoc.file of every token */
    int line, col;           /* position of the next character, 1-based */
    int last_line, last_col; /* last character of the last token */
    char *text;              /* text of the last token, for messages */
    size_t text_cap;
} LexState;

/* Parser state (the parse parameter). */
typedef struct ParseState {
    const char *file;
    Program *prog;
    LexState *lex;
} ParseState;

/* Semantic values of a few nonterminals. */
typedef struct { char **names; SrcLoc *locs; int n; } NameList;
typedef struct { Expr **items; int n; } ExprList;
typedef struct { int mask; SrcLoc loc; } CompList;
typedef struct { char *measure, *quantity; SrcLoc loc; } Target;
}

%code provides {
int yylex(YYSTYPE *yylval, YYLTYPE *yylloc, yyscan_t scanner);
}

%code {
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "util/diag.h"
#include "lexer.h"

#define LOC(l) mkloc(ps, &(l))

static SrcLoc mkloc(const ParseState *ps, const YYLTYPE *l)
{
    SrcLoc s = { ps->file, l->first_line, l->first_column };
    return s;
}

void yyerror(YYLTYPE *loc, yyscan_t scanner, ParseState *ps, const char *msg);

/* A node nested deeper than AST_MAX_DEPTH is reported once, where its chain passes the
 * limit; after errors in parsing, no stage walks the tree. */
static Expr *depth_limited(Expr *e)
{
    if (e->depth == AST_MAX_DEPTH + 1)
        diag_error(e->loc, "expression nested too deeply (more than %d levels)", AST_MAX_DEPTH);
    return e;
}

static ShapeExpr *shape_depth_limited(ShapeExpr *s)
{
    if (s->depth == AST_MAX_DEPTH + 1)
        diag_error(s->loc, "shape nested too deeply (more than %d levels)", AST_MAX_DEPTH);
    return s;
}

/* A block statement: its depth from its parts, reported once where it passes the limit. */
static MatStmt block_depth_limited(MatStmt s)
{
    const MatStmtList *parts[2] = {&s.body, &s.orelse};
    s.depth = 1;
    for (int p = 0; p < 2; p++)
        for (int k = 0; k < parts[p]->n; k++)
            if (parts[p]->items[k].depth >= s.depth)
                s.depth = parts[p]->items[k].depth + 1;
    if (s.depth == AST_MAX_BLOCK_DEPTH + 1)
        diag_error(s.loc, "blocks of a material law nested too deeply (more than %d levels)",
                   AST_MAX_BLOCK_DEPTH);
    return s;
}

static Item new_item(ItemKind kind, SrcLoc loc)
{
    Item it = { 0 };
    it.kind = kind;
    it.loc = loc;
    return it;
}

/* import NAME, let NAME = value */
static void push_named(ParseState *ps, ItemKind kind, SrcLoc loc, const char *name, Expr *value)
{
    Item it = new_item(kind, loc);
    it.name = ast_strdup(name);
    it.value = value;
    ast_push_item(ps->prog, it);
}

static void push_fn(ParseState *ps, SrcLoc loc, const char *name, NameList params, Expr *body)
{
    Item it = new_item(IT_FN, loc);
    it.name = ast_strdup(name);
    it.params = params.names;
    it.nparams = params.n;
    free(params.locs); /* Item keeps no parameter locations */
    it.value = body;
    ast_push_item(ps->prog, it);
}

static void push_scene(ParseState *ps, SrcLoc loc, SettingList settings)
{
    Item it = new_item(IT_SCENE, loc);
    it.scene = settings;
    ast_push_item(ps->prog, it);
}

static void push_material(ParseState *ps, SrcLoc loc, SrcLoc name_loc, const char *name,
                          NameList params, MatStmtList body)
{
    Item it = new_item(IT_MATERIAL, loc);
    it.material.name = ast_strdup(name);
    it.material.loc = name_loc;
    it.material.params = params.names;
    it.material.param_locs = params.locs;
    it.material.nparams = params.n;
    it.material.body = body;
    ast_push_item(ps->prog, it);
}

static void push_body(ParseState *ps, SrcLoc loc, SrcLoc name_loc, const char *name, BodyDecl body)
{
    Item it = new_item(IT_BODY, loc);
    it.body = body;
    it.body.name = ast_strdup(name);
    it.body.loc = name_loc;
    ast_push_item(ps->prog, it);
}

static void push_expect(ParseState *ps, ExpectKind kind, SrcLoc loc, const Target *target,
                        Expr *value, Expr *tolerance)
{
    Item it = new_item(IT_EXPECT, loc);
    it.expect.kind = kind;
    it.expect.loc = loc;
    if (target) {
        it.expect.measure = target->measure;
        it.expect.quantity = target->quantity;
        it.expect.target_loc = target->loc;
    }
    it.expect.value = value;
    it.expect.tolerance = tolerance;
    ast_push_item(ps->prog, it);
}

/* reference M.Q = file "F.csv": the word before the string must be `file`. */
static void push_reference_file(ParseState *ps, SrcLoc loc, const Target *target, SrcLoc kw_loc,
                                const char *kw, SrcLoc file_loc, char *file, Expr *tolerance)
{
    if (strcmp(kw, "file") != 0) {
        diag_error(kw_loc, "expected 'file \"NAME.csv\"' or an expression of t after "
                           "'reference ... =' (got '%s')", kw);
        free(file);
        return;
    }
    push_expect(ps, EXPECT_REFERENCE, loc, target, NULL, tolerance);
    ExpectDecl *d = &ps->prog->items[ps->prog->n - 1].expect;
    d->file = file;
    d->file_loc = file_loc;
}

/* The word after "expect" (energy is a keyword and has its own rule). */
static int expect_kind(SrcLoc loc, const char *word, ExpectKind *kind)
{
    if (strcmp(word, "period") == 0)
        *kind = EXPECT_PERIOD;
    else if (strcmp(word, "amplitude") == 0)
        *kind = EXPECT_AMPLITUDE;
    else {
        diag_error(loc, "unknown expectation '%s' (expected period, amplitude or energy)", word);
        return 0;
    }
    return 1;
}

static BodyItem new_bodyitem(BodyItemKind kind, SrcLoc loc)
{
    BodyItem b = { 0 };
    b.kind = kind;
    b.loc = loc;
    return b;
}

/* The kind of boundary condition written `keyword word` (lang/bc_kinds.h; word NULL: the
 * keyword alone, or a kind left out).  An unknown or missing kind is reported with the
 * keyword's kinds (the tree is not read after an error). */
static BcKind bc_kind(SrcLoc loc, const char *keyword, const char *word)
{
    int k = bc_kind_find(keyword, word);
    if (k >= 0)
        return (BcKind)k;
    char words[256];
    bc_kind_words(keyword, words, sizeof words);
    if (word)
        diag_error(loc, "unknown %s kind '%s' (expected %s)", keyword, word, words);
    else
        diag_error(loc, "missing %s kind (expected %s)", keyword, words);
    return (BcKind)0;
}

static BodyItem bc_item(SrcLoc loc, BcKind kind, CompList comps, Expr *value, BcDecl opts)
{
    BodyItem b = new_bodyitem(BI_BC, loc);
    b.bc = opts;
    b.bc.kind = kind;
    b.bc.loc = loc;
    b.bc.comps = comps.mask;
    b.bc.comps_loc = comps.loc;
    b.bc.value = value;
    return b;
}

static BodyItem points_item(BodyItemKind kind, SrcLoc loc, const char *name, SrcLoc name_loc,
                            Expr *p1, Expr *p2, Expr *p3, Expr *p4)
{
    BodyItem b = new_bodyitem(kind, loc);
    b.measure.name = ast_strdup(name);
    b.measure.loc = name ? name_loc : loc;
    b.measure.points[0] = p1;
    b.measure.points[1] = p2;
    b.measure.points[2] = p3;
    b.measure.points[3] = p4;
    return b;
}

static void add_comp(CompList *c, SrcLoc loc, const char *name)
{
    int bit = ast_axis_bit(name);
    if (!bit)
        diag_error(loc, "unknown component '%s' (expected x, y or z)", name);
    else if (c->mask & bit)
        diag_warning(loc, "component '%s' given twice", name);
    c->mask |= bit;
}

/* from/to of a boundary condition, each at most once. */
static void set_once(Expr **slot, Expr *value, SrcLoc loc, const char *what)
{
    if (*slot)
        diag_error(loc, "'%s' given twice", what);
    *slot = value;
}

/* A scene/body/material block ended without '}' before the lookahead token
 * (a new item or the end of input).  Nothing is said while recovering from a
 * syntax error: that error explains it already. */
static void report_unclosed(ParseState *ps, const YYLTYPE *at, int at_eof, const YYLTYPE *open,
                            int recovering)
{
    if (recovering)
        return;
    if (at_eof)
        diag_error(mkloc(ps, at), "expected '}' at end of input");
    else
        diag_error(mkloc(ps, at), "expected '}' before '%s'", ps->lex->text);
    diag_note(mkloc(ps, open), "to match this '{'");
}

#define UNCLOSED(open) \
    report_unclosed(ps, &yylloc, yychar == TK_YYEOF, &(open), YYRECOVERING())
}

%token <double> NUMBER "number"
%token <const char *> IDENT "identifier"
%token <char *> STRING "string"
%token IMPORT "import" SCENE "scene" LET "let" FN "fn" MATERIAL "material" BODY "body"
%token SHAPE "shape" STRESS "stress" ENERGY "energy" STATE "state" IF "if" ELSE "else"
%token DISSIPATION "dissipation" REQUIRE "require" TEMPERATURE "temperature" WAVESPEED "wavespeed"
%token VISCOUSHEAT "viscousheat"
%token VELOCITY "velocity" FORCE "force"
%token FROM "from" TO "to" NEAR "near" MEASURE "measure" PLANE "plane"
%token EXPECT "expect" REFERENCE "reference" WITHIN "within"
%token AND "and" OR "or" NOT "not" SKIP "skip" NOTCH "notch" FRACTURE "fracture"
%token LE "<=" GE ">=" EQ "==" NE "!="

%nterm <SettingList> settings namedargs namedargs_opt
%nterm <Setting> setting namedarg
%nterm <const char *> argkey
%nterm <NameList> names names_opt
%nterm <MatStmtList> matstmts else_opt
%nterm <MatStmt> matstmt
%nterm <BodyDecl> bodyitems
%nterm <BodyItem> bodyitem
%nterm <CompList> comps
%nterm <BcDecl> bcopts
%nterm <ShapeExpr *> shape primshape
%nterm <NamedCall> call
%nterm <Target> target
%nterm <int> rbrace
%nterm <ExprList> exprs args_opt
%nterm <Expr *> reference_tol expr or_e and_e cmp_e add_e mul_e unary_e pow_e primary vec

/* A block may end without its '}' (rbrace: %empty) only where the lookahead
 * cannot continue the block: ';', material, let and error continue it. */
%precedence UNCLOSED
%precedence ';' MATERIAL LET error

%start program

%%

program
    : items
    ;

items
    : %empty
    | items item
    | items ';'
    | items error
    ;

item
    : IMPORT IDENT                      { push_named(ps, IT_IMPORT, LOC(@2), $2, NULL); }
    | SCENE '{' settings rbrace         { push_scene(ps, LOC(@1), $3); if (!$4) UNCLOSED(@2); }
    | LET letbinds
    | FN IDENT '(' names_opt ')' '=' expr
                                        { push_fn(ps, LOC(@2), $2, $4, $7); }
    | MATERIAL IDENT '(' names_opt ')' '{' matstmts rbrace
                                        { push_material(ps, LOC(@1), LOC(@2), $2, $4, $7);
                                          if (!$8) UNCLOSED(@6); }
    | BODY IDENT '{' bodyitems rbrace   { push_body(ps, LOC(@1), LOC(@2), $2, $4);
                                          if (!$5) UNCLOSED(@3); }
    | EXPECT IDENT target '=' expr WITHIN expr '%'
                                        { ExpectKind k;
                                          if (expect_kind(LOC(@2), $2, &k))
                                              push_expect(ps, k, LOC(@1), &$3, $5, $7); }
    | EXPECT ENERGY WITHIN expr '%'     { push_expect(ps, EXPECT_ENERGY, LOC(@1), NULL, NULL, $4); }
    | REFERENCE target '=' expr         { push_expect(ps, EXPECT_REFERENCE, LOC(@1), &$2, $4, NULL); }
    | REFERENCE target '=' expr WITHIN expr '%'
                                        { push_expect(ps, EXPECT_REFERENCE, LOC(@1), &$2, $4, $6); }
    | REFERENCE target '=' IDENT STRING reference_tol
                                        { push_reference_file(ps, LOC(@1), &$2, LOC(@4), $4,
                                                              LOC(@5), $5, $6); }
    ;

reference_tol
    : %empty                            { $$ = NULL; }
    | WITHIN expr '%'                   { $$ = $2; }
    ;

rbrace
    : '}'                               { $$ = 1; }
    | %empty %prec UNCLOSED             { $$ = 0; }
    ;

letbinds
    : letbind
    | letbinds ',' letbind
    ;

letbind
    : IDENT '=' expr                    { push_named(ps, IT_LET, LOC(@1), $1, $3); }
    ;

target
    : IDENT '.' IDENT                   { $$ = (Target){ ast_strdup($1), ast_strdup($3), LOC(@1) }; }
    ;

names_opt
    : %empty                            { $$ = (NameList){ 0 }; }
    | names
    ;

names
    : IDENT                             { $$ = (NameList){ 0 };
                                          ast_push_name(&$$.names, &$$.locs, &$$.n, $1, LOC(@1)); }
    | names ',' IDENT                   { $$ = $1;
                                          ast_push_name(&$$.names, &$$.locs, &$$.n, $3, LOC(@3)); }
    ;

/* ---------------------------------------------------------------- settings */

settings
    : %empty                            { $$ = (SettingList){ 0 }; }
    | settings setting                  { $$ = $1; ast_push_setting(&$$, $2); }
    | settings ';'                      { $$ = $1; }
    | settings error                    { $$ = $1; }
    ;

setting
    : IDENT expr                        { $$ = ast_setting(LOC(@1), $1, $2); }
    | setting ',' expr                  { $$ = $1; ast_push_expr(&$$.values, &$$.nvalues, $3); }
    ;

/* ---------------------------------------------------------------- material laws */

matstmts
    : %empty                            { $$ = (MatStmtList){ 0 }; }
    | matstmts matstmt                  { $$ = $1; ast_push_matstmt(&$$, $2); }
    | matstmts ';'                      { $$ = $1; }
    | matstmts error                    { $$ = $1; }
    ;

matstmt
    : LET IDENT '=' expr                { $$ = ast_matstmt(MS_LET, LOC(@2), $2, $4); }
    | STRESS IDENT '=' expr             { $$ = ast_matstmt(MS_STRESS, LOC(@2), $2, $4); }
    | ENERGY IDENT '=' expr             { $$ = ast_matstmt(MS_ENERGY, LOC(@2), $2, $4); }
    | ENERGY IDENT '(' IDENT ')' '=' expr
                                        { $$ = ast_matstmt(MS_ENERGY, LOC(@2), $2, $7);
                                          $$.of = ast_strdup($4); }
    | STATE IDENT '=' expr              { $$ = ast_matstmt(MS_STATE, LOC(@2), $2, $4); }
    | IF expr '{' matstmts '}' else_opt { $$ = ast_matstmt(MS_IF, LOC(@1), NULL, $2);
                                          $$.body = $4; $$.orelse = $6;
                                          $$ = block_depth_limited($$); }
    | IDENT '{' matstmts '}'            { $$ = ast_matstmt(MS_BLOCK, LOC(@1), $1, NULL);
                                          $$.body = $3; $$ = block_depth_limited($$); }
    | IDENT '=' expr                    { $$ = ast_matstmt(MS_ASSIGN, LOC(@1), $1, $3); }
    | DISSIPATION IDENT                 { $$ = ast_matstmt(MS_DISSIPATION, LOC(@2), $2, NULL); }
    | REQUIRE expr                      { $$ = ast_matstmt(MS_REQUIRE, LOC(@1), NULL, $2); }
    | REQUIRE expr ',' STRING           { $$ = ast_matstmt(MS_REQUIRE, LOC(@1), NULL, $2);
                                          $$.message = $4; }
    | TEMPERATURE IDENT ',' expr        { $$ = ast_matstmt(MS_TEMPERATURE, LOC(@2), $2, $4); }
    | WAVESPEED expr                    { $$ = ast_matstmt(MS_WAVESPEED, LOC(@1), NULL, $2); }
    | VISCOUSHEAT IDENT                 { $$ = ast_matstmt(MS_VISCOUSHEAT, LOC(@2), $2, NULL); }
    ;

else_opt
    : %empty                            { $$ = (MatStmtList){ 0 }; }
    | ELSE '{' matstmts '}'             { $$ = $3; }
    ;

/* ---------------------------------------------------------------- bodies */

bodyitems
    : %empty                            { $$ = (BodyDecl){ 0 }; }
    | bodyitems bodyitem                { $$ = $1; ast_push_bodyitem(&$$, $2); }
    | bodyitems ';'                     { $$ = $1; }
    | bodyitems error                   { $$ = $1; }
    ;

bodyitem
    : SHAPE shape                       { $$ = new_bodyitem(BI_SHAPE, LOC(@1)); $$.shape = $2; }
    | MATERIAL call                     { $$ = new_bodyitem(BI_MATERIAL, LOC(@1)); $$.material = $2; }
    | VELOCITY comps '=' expr bcopts    { $$ = bc_item(LOC(@1), bc_kind(LOC(@1), "velocity", NULL),
                                                       $2, $4, $5); }
    | FORCE IDENT comps '=' expr bcopts { $$ = bc_item(LOC(@1), bc_kind(LOC(@2), "force", $2),
                                                       $3, $5, $6); }
    | FORCE comps '=' expr bcopts       { $$ = bc_item(LOC(@1), bc_kind(LOC(@2), "force", NULL),
                                                       $2, $4, $5); }
    | MEASURE IDENT PLANE vec vec vec vec
                                        { $$ = points_item(BI_MEASURE, LOC(@1), $2, LOC(@2),
                                                           $4, $5, $6, $7); }
    | NOTCH vec vec vec vec             { $$ = points_item(BI_NOTCH, LOC(@1), NULL, LOC(@1),
                                                           $2, $3, $4, $5); }
    | FRACTURE '(' namedargs_opt ')'    { $$ = new_bodyitem(BI_FRACTURE, LOC(@1));
                                          $$.material = (NamedCall){ ast_strdup("fracture"), LOC(@1), $3 }; }
    | PLANE expr                        { $$ = new_bodyitem(BI_SETTING, LOC(@1));
                                          $$.setting = ast_setting(LOC(@1), "plane", $2); }
    | setting                           { $$ = new_bodyitem(BI_SETTING, $1.loc); $$.setting = $1; }
    ;

comps
    : IDENT                             { $$ = (CompList){ 0, LOC(@1) }; add_comp(&$$, LOC(@1), $1); }
    | comps ',' IDENT                   { $$ = $1; add_comp(&$$, LOC(@3), $3); }
    ;

bcopts
    : %empty                            { $$ = (BcDecl){ 0 }; }
    | bcopts FROM expr                  { $$ = $1; set_once(&$$.t_from, $3, LOC(@2), "from"); }
    | bcopts TO expr                    { $$ = $1; set_once(&$$.t_to, $3, LOC(@2), "to"); }
    | bcopts NEAR shape                 { $$ = $1;
                                          if ($$.near) diag_error(LOC(@2), "'near' given twice");
                                          $$.near = $3; }
    ;

shape
    : primshape
    | shape '+' primshape               { $$ = shape_depth_limited(
                                                  ast_shape_op(LOC(@2), '+', $1, $3)); }
    | shape '-' primshape               { $$ = shape_depth_limited(
                                                  ast_shape_op(LOC(@2), '-', $1, $3)); }
    ;

primshape
    : call                              { $$ = ast_shape_prim($1); }
    | '(' shape ')'                     { $$ = $2; }
    ;

call
    : IDENT '(' namedargs_opt ')'       { $$ = (NamedCall){ ast_strdup($1), LOC(@1), $3 }; }
    ;

namedargs_opt
    : %empty                            { $$ = (SettingList){ 0 }; }
    | namedargs
    ;

namedargs
    : namedarg                          { $$ = (SettingList){ 0 }; ast_push_setting(&$$, $1); }
    | namedargs namedarg                { $$ = $1; ast_push_setting(&$$, $2); }
    | namedargs ',' namedarg            { $$ = $1; ast_push_setting(&$$, $3); }
    ;

/* A key with one value, or with several vectors: prism(base [..] [..] [..] top ...). */
namedarg
    : argkey expr                       { $$ = ast_setting(LOC(@1), $1, $2); }
    | argkey STRING                     { $$ = ast_setting_text(LOC(@1), $1, $2); free($2); }
    | namedarg vec                      { $$ = $1; ast_push_expr(&$$.values, &$$.nvalues, $2); }
    ;

argkey
    : IDENT
    | FROM                              { $$ = "from"; }
    | TO                                { $$ = "to"; }
    ;

vec
    : '[' exprs ']'                     { $$ = depth_limited(ast_vec(LOC(@1), $2.items, $2.n)); }
    ;

/* ---------------------------------------------------------------- expressions */

exprs
    : expr                              { $$ = (ExprList){ 0 }; ast_push_expr(&$$.items, &$$.n, $1); }
    | exprs ',' expr                    { $$ = $1; ast_push_expr(&$$.items, &$$.n, $3); }
    ;

args_opt
    : %empty                            { $$ = (ExprList){ 0 }; }
    | exprs
    ;

expr
    : or_e
    ;

or_e
    : and_e
    | or_e OR and_e                     { $$ = depth_limited(ast_binary(LOC(@2), OP_OR, $1, $3)); }
    ;

and_e
    : cmp_e
    | and_e AND cmp_e                   { $$ = depth_limited(ast_binary(LOC(@2), OP_AND, $1, $3)); }
    ;

cmp_e
    : add_e
    | cmp_e '<' add_e                   { $$ = depth_limited(ast_binary(LOC(@2), OP_LT, $1, $3)); }
    | cmp_e '>' add_e                   { $$ = depth_limited(ast_binary(LOC(@2), OP_GT, $1, $3)); }
    | cmp_e LE add_e                    { $$ = depth_limited(ast_binary(LOC(@2), OP_LE, $1, $3)); }
    | cmp_e GE add_e                    { $$ = depth_limited(ast_binary(LOC(@2), OP_GE, $1, $3)); }
    | cmp_e EQ add_e                    { $$ = depth_limited(ast_binary(LOC(@2), OP_EQ, $1, $3)); }
    | cmp_e NE add_e                    { $$ = depth_limited(ast_binary(LOC(@2), OP_NE, $1, $3)); }
    ;

add_e
    : mul_e
    | add_e '+' mul_e                   { $$ = depth_limited(ast_binary(LOC(@2), OP_ADD, $1, $3)); }
    | add_e '-' mul_e                   { $$ = depth_limited(ast_binary(LOC(@2), OP_SUB, $1, $3)); }
    ;

mul_e
    : unary_e
    | mul_e '*' unary_e                 { $$ = depth_limited(ast_binary(LOC(@2), OP_MUL, $1, $3)); }
    | mul_e '/' unary_e                 { $$ = depth_limited(ast_binary(LOC(@2), OP_DIV, $1, $3)); }
    ;

unary_e
    : '-' unary_e                       { $$ = depth_limited(ast_unary(LOC(@1), OP_NEG, $2)); }
    | NOT unary_e                       { $$ = depth_limited(ast_unary(LOC(@1), OP_NOT, $2)); }
    | pow_e
    ;

/* right associative, and tighter than unary minus: -2^2 = -(2^2), 2^-1 is fine */
pow_e
    : primary
    | primary '^' unary_e               { $$ = depth_limited(ast_binary(LOC(@2), OP_POW, $1, $3)); }
    ;

primary
    : NUMBER                            { $$ = ast_num(LOC(@1), $1); }
    | IDENT                             { $$ = ast_name(LOC(@1), $1); }
    | IDENT '(' args_opt ')'            { $$ = depth_limited(
                                                  ast_call(LOC(@1), $1, $3.items, $3.n)); }
    | IF '(' args_opt ')'               { $$ = depth_limited(
                                                  ast_call(LOC(@1), "if", $3.items, $3.n)); }
    | '(' expr ')'                      { $$ = $2; }
    | vec
    | SKIP                              { $$ = ast_skip(LOC(@1)); }
    ;

%%

/* ---------------------------------------------------------------- syntax error messages */

/* Whether t is the single-character token c. */
static int is_char(yysymbol_kind_t t, char c)
{
    const char *n = yysymbol_name(t);
    return n[0] == '\'' && n[1] == c && n[2] == '\'' && n[3] == '\0';
}

static int is_expr_start(yysymbol_kind_t t)
{
    switch (t) {
    case YYSYMBOL_NUMBER: case YYSYMBOL_IDENT: case YYSYMBOL_IF: case YYSYMBOL_NOT:
    case YYSYMBOL_SKIP:
        return 1;
    default:
        return is_char(t, '(') || is_char(t, '[') || is_char(t, '-');
    }
}

static int is_operator(yysymbol_kind_t t)
{
    switch (t) {
    case YYSYMBOL_AND: case YYSYMBOL_OR: case YYSYMBOL_LE: case YYSYMBOL_GE:
    case YYSYMBOL_EQ: case YYSYMBOL_NE:
        return 1;
    default:
        return is_char(t, '+') || is_char(t, '-') || is_char(t, '*') || is_char(t, '/')
            || is_char(t, '^') || is_char(t, '<') || is_char(t, '>');
    }
}

/* Tokens that can only start a top-level item (or end the input). */
static int is_toplevel_only(yysymbol_kind_t t)
{
    switch (t) {
    case YYSYMBOL_YYEOF: case YYSYMBOL_IMPORT: case YYSYMBOL_SCENE: case YYSYMBOL_FN:
    case YYSYMBOL_BODY: case YYSYMBOL_EXPECT: case YYSYMBOL_REFERENCE:
        return 1;
    default:
        return 0;
    }
}

/* How an expected token is named: 'let', ';', number, identifier. */
static void symbol_text(yysymbol_kind_t t, char *buf, size_t size)
{
    const char *n = yysymbol_name(t);
    switch (t) {
    case YYSYMBOL_YYEOF:  snprintf(buf, size, "end of input"); break;
    case YYSYMBOL_NUMBER: snprintf(buf, size, "number"); break;
    case YYSYMBOL_IDENT:  snprintf(buf, size, "identifier"); break;
    case YYSYMBOL_STRING: snprintf(buf, size, "string"); break;
    default: /* keywords come unquoted, single characters quoted */
        if (n[0] == '\'')
            snprintf(buf, size, "%s", n);
        else
            snprintf(buf, size, "'%s'", n);
    }
}

static int contains(const yysymbol_kind_t *set, int n, yysymbol_kind_t t)
{
    for (int i = 0; i < n; i++)
        if (set[i] == t)
            return 1;
    return 0;
}

/* gcc-like messages: "expected '=' before 'sin'", "expected expression before ')'",
 * "expected '}' at end of input"; "unexpected X" when too many tokens would fit. */
static int yyreport_syntax_error(const yypcontext_t *ctx, yyscan_t scanner, ParseState *ps)
{
    (void)scanner;
    yysymbol_kind_t bad = yypcontext_token(ctx);
    if (bad == YYSYMBOL_YYUNDEF)
        return 0; /* an unexpected character, reported by the scanner */

    SrcLoc loc = mkloc(ps, yypcontext_location(ctx));
    const char *text = ps->lex->text;
    char where[200];
    if (bad == YYSYMBOL_YYEOF)
        snprintf(where, sizeof where, "at end of input");
    else
        snprintf(where, sizeof where, "before '%.160s'", text);

    yysymbol_kind_t exp[YYNTOKENS];
    int n = yypcontext_expected_tokens(ctx, exp, YYNTOKENS);
    if (n < 0)
        n = 0;
    int want_expr = contains(exp, n, YYSYMBOL_NUMBER);
    int want_close = 0;
    for (int i = 0; i < n; i++)
        want_close |= is_char(exp[i], '}');

    if (bad == YYSYMBOL_STRING) {
        diag_error(loc, "unexpected string %.160s (strings are only file names, as in "
                        "surface(file \"beam.vtk\"), and the messages of requirements)", text);
        return 0;
    }
    if (want_close && is_toplevel_only(bad)) {
        diag_error(loc, "expected '}' %s", where);
        return 0;
    }

    /* Keep the tokens worth naming: an expression counts as one; what could
     * merely continue the construct before (operators, the '(' of a call) is
     * named only when nothing else fits, and ';' and what a missing '}' would
     * allow are left out. */
    enum { MAXLIST = 4 };
    char list[MAXLIST][40];
    int nlist = 0, too_many = 0;
    for (int pass = 0; pass < 2 && nlist == 0; pass++) {
        too_many = 0;
        if (want_expr)
            snprintf(list[nlist++], sizeof list[0], "expression");
        for (int i = 0; i < n && !too_many; i++) {
            yysymbol_kind_t t = exp[i];
            if ((want_expr && is_expr_start(t)) || is_char(t, ';'))
                continue;
            if (pass == 0 && (is_operator(t) || is_char(t, '(')))
                continue;
            if (want_close && is_toplevel_only(t))
                continue;
            if ((t == YYSYMBOL_FROM || t == YYSYMBOL_TO) && contains(exp, n, YYSYMBOL_IDENT))
                continue; /* named-argument keys: "identifier" says it */
            if (nlist == MAXLIST)
                too_many = 1;
            else
                symbol_text(t, list[nlist++], sizeof list[0]);
        }
    }

    if (nlist == 0 || too_many) {
        int only_items = contains(exp, n, YYSYMBOL_IMPORT) && !want_close;
        for (int i = 0; i < n && only_items; i++)
            only_items = is_toplevel_only(exp[i]) || exp[i] == YYSYMBOL_LET
                      || exp[i] == YYSYMBOL_MATERIAL || is_operator(exp[i])
                      || is_char(exp[i], ';') || is_char(exp[i], '(');
        if (only_items) {
            diag_error(loc, "expected import, scene, let, fn, material, body, expect or "
                            "reference %s", where);
        } else if (bad == YYSYMBOL_YYEOF) {
            diag_error(loc, "unexpected end of input");
        } else if (bad == YYSYMBOL_IDENT || bad == YYSYMBOL_NUMBER) {
            char kind[40];
            symbol_text(bad, kind, sizeof kind);
            diag_error(loc, "unexpected %s '%.160s'", kind, text);
        } else {
            diag_error(loc, "unexpected '%.160s'", text);
        }
        return 0;
    }

    char msg[300] = "expected ";
    for (int i = 0; i < nlist; i++) {
        if (i > 0)
            strcat(msg, i == nlist - 1 ? " or " : ", ");
        strcat(msg, list[i]);
    }
    diag_error(loc, "%s %s", msg, where);
    return 0;
}

/* Only "memory exhausted" (a nesting deeper than YYMAXDEPTH) ends up here. */
void yyerror(YYLTYPE *loc, yyscan_t scanner, ParseState *ps, const char *msg)
{
    (void)scanner;
    if (strcmp(msg, "memory exhausted") == 0)
        diag_error(mkloc(ps, loc), "nesting too deep (parser stack exhausted)");
    else
        diag_error(mkloc(ps, loc), "%s", msg);
}

/* ---------------------------------------------------------------- entry point */

/* The whole file in memory (*len bytes): the scanner then never refills its buffer, which
 * made a token of millions of characters cost time quadratic in its length.  NULL after
 * reporting. */
static char *read_model(const char *path, size_t *len)
{
    FILE *f = fopen(path, "r");
    struct stat st;
    if (f && fstat(fileno(f), &st) == 0 && S_ISDIR(st.st_mode)) {
        fclose(f);
        f = NULL;
        errno = EISDIR;
    }
    if (!f) {
        diag_fatal_noloc("cannot open '%s': %s", path, strerror(errno));
        return NULL;
    }
    size_t cap = 1 << 16, n = 0, got;
    char *buf = malloc(cap);
    while ((got = fread(buf + n, 1, cap - n, f)) > 0) {
        n += got;
        if (n == cap && cap >= LEX_MAX_FILE) {
            diag_fatal_noloc("'%s' is larger than %d MiB, the most a model file may be", path,
                             LEX_MAX_FILE >> 20);
            free(buf);
            fclose(f);
            return NULL;
        }
        if (n == cap)
            buf = realloc(buf, cap *= 2);
    }
    fclose(f);
    *len = n;
    return buf;
}

int parse_file(const char *path, Program *prog)
{
    int before = diag_error_count();
    size_t len;
    char *text = read_model(path, &len);
    if (!text)
        return 1;

    LexState lex = { 0 };
    lex.file = ast_strdup(path); /* lives as long as the tree */
    lex.line = lex.col = 1;
    lex.last_line = 1;
    lex.last_col = 0;
    lex.text_cap = 64;
    lex.text = ast_alloc(lex.text_cap);

    ParseState ps = { lex.file, prog, &lex };
    if (!prog->file)
        prog->file = lex.file;

    yyscan_t scanner;
    if (yylex_init_extra(&lex, &scanner) != 0) {
        free(text);
        diag_fatal_noloc("out of memory");
        return 1;
    }
    yy_scan_bytes(text, (int)len, scanner);
    free(text);
    int rc = yyparse(scanner, &ps);
    yylex_destroy(scanner);
    free(lex.text);

    int errors = diag_error_count() - before;
    if (rc != 0 && errors == 0) {
        diag_error((SrcLoc){ lex.file, 0, 0 }, "could not parse the file");
        errors = 1;
    }
    return errors;
}
