/* builtins.h — the built-in names of the expression language (paper Tables 1 and 2). */
#ifndef SPHC_BUILTINS_H
#define SPHC_BUILTINS_H

/* Names of the expression variables of paper Table 1, in the order of sph_pt. */
int builtin_variable(const char *name); /* index or -1 */
extern const char *const BUILTIN_VARIABLES[];
extern const int NBUILTIN_VARIABLES;

/* How a built-in function is computed, in the generated C and in the law's scalar graph. */
typedef enum {
    BF_CALL,   /* c(x, ...); in the graph a call (SN_CALL) */
    BF_RECIP,  /* 1.0 / c(x), c the function of a BF_CALL row; in the graph 1 / that call */
    BF_POW,    /* c(x, y); in the graph the operator SN_POW (as x ^ y) */
    BF_MIN,    /* c(x, y); in the graph SN_MIN */
    BF_MAX,    /* c(x, y); in the graph SN_MAX */
    BF_IF,     /* x ? y : z, only the chosen branch evaluated; in the graph a select */
} BuiltinForm;

/* The built-in functions (Table 2), one row each: X(name, arity, form, c, value, derivative)
 * with
 *   name        the function in the language (`log` is base 10, `ln` the natural logarithm);
 *   form        a BuiltinForm;
 *   c           the C function of the generated code (NULL for if);
 *   value       its value for the arguments a[0], a[1], ... (<math.h>, lang/arith.h): what the
 *               interpreter (check/eval.c) and the graph (ir/scalar.c) fold constants to;
 *   derivative  a BF_CALL's d f(x) / dx as a node of the law's graph, built from its argument
 *               x and its value fx, nodes both, with ir/derivative.c's builders: call(f, x),
 *               neg, add, sub, mul, divide, num(v), select(cond, a, b), lt(a, b); NONE for
 *               the other forms, which the graph holds as its own operators.
 * A new scalar function is one BF_CALL row; the checker, both folders, the law's graph, its
 * derivatives (the stress of an energy) and the emitted C all read this table. */
#define BUILTIN_FUNCTIONS(X)                                                                    \
    X(sin,  1, BF_CALL,  "sin",   sin(a[0]),   call(cos, x))                                     \
    X(cos,  1, BF_CALL,  "cos",   cos(a[0]),   neg(call(sin, x)))                                \
    X(tan,  1, BF_CALL,  "tan",   tan(a[0]),   add(num(1), mul(fx, fx)))                         \
    X(cot,  1, BF_RECIP, "tan",   1.0 / tan(a[0]), NONE)                                         \
    X(sinh, 1, BF_CALL,  "sinh",  sinh(a[0]),  call(cosh, x))                                    \
    X(cosh, 1, BF_CALL,  "cosh",  cosh(a[0]),  call(sinh, x))                                    \
    X(tanh, 1, BF_CALL,  "tanh",  tanh(a[0]),  sub(num(1), mul(fx, fx)))                         \
    X(coth, 1, BF_RECIP, "tanh",  1.0 / tanh(a[0]), NONE)                                        \
    X(asin, 1, BF_CALL,  "asin",  asin(a[0]),  divide(num(1), call(sqrt, sub(num(1), mul(x, x))))) \
    X(acos, 1, BF_CALL,  "acos",  acos(a[0]),  divide(num(-1), call(sqrt, sub(num(1), mul(x, x))))) \
    X(atan, 1, BF_CALL,  "atan",  atan(a[0]),  divide(num(1), add(num(1), mul(x, x))))          \
    X(sqrt, 1, BF_CALL,  "sqrt",  sqrt(a[0]),  divide(num(0.5), fx))                             \
    X(log,  1, BF_CALL,  "log10", log10(a[0]), divide(num(1 / log(10.0)), x))                    \
    X(ln,   1, BF_CALL,  "log",   log(a[0]),   divide(num(1), x))                                \
    X(exp,  1, BF_CALL,  "exp",   exp(a[0]),   fx)                                               \
    X(abs,  1, BF_CALL,  "fabs",  fabs(a[0]),  select(lt(x, num(0)), num(-1), num(1)))           \
    X(pow,  2, BF_POW,   "pow",   arith_binary(AR_POW, a[0], a[1]), NONE)                        \
    X(min,  2, BF_MIN,   "sph_min", arith_binary(AR_MIN, a[0], a[1]), NONE)                      \
    X(max,  2, BF_MAX,   "sph_max", arith_binary(AR_MAX, a[0], a[1]), NONE)                      \
    X(if,   3, BF_IF,    NULL,    a[0] != 0.0 ? a[1] : a[2], NONE)

/* Their indices: BI_sin, BI_cos, ... */
typedef enum {
#define X(name, arity, form, c, value, derivative) BI_##name,
    BUILTIN_FUNCTIONS(X)
#undef X
    NBUILTIN_FUNCTIONS
} BuiltinId;

typedef struct {
    const char *name;
    int arity;
    BuiltinForm form;
    const char *c;
} Builtin;

extern const Builtin BUILTIN_FUNCTION[NBUILTIN_FUNCTIONS];

int builtin_function(const char *name);          /* its BuiltinId, or -1 when unknown */
int builtin_function_arity(const char *name);    /* its arity, or -1 when unknown */
/* The value of built-in f for the arguments a[0 .. arity-1] (all of them, also for if). */
double builtin_value(int f, const double *a);
/* The BF_CALL row of C function c (what a BF_RECIP row inverts), or -1. */
int builtin_of_c(const char *c);

#endif
