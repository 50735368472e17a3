/* builtins.c — the built-in names of the expression language (paper Tables 1 and 2). */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "arith.h"
#include "builtins.h"

/* Order matters: it is the field order of sph_pt in runtime/scene/point.h. */
const char *const BUILTIN_VARIABLES[] = {
    "x0", "y0", "z0", "x", "y", "z", "ux", "uy", "uz", "t", "dt", "dx",
};
const int NBUILTIN_VARIABLES = (int)(sizeof BUILTIN_VARIABLES / sizeof BUILTIN_VARIABLES[0]);

int builtin_variable(const char *name)
{
    for (int i = 0; i < NBUILTIN_VARIABLES; i++)
        if (strcmp(name, BUILTIN_VARIABLES[i]) == 0)
            return i;
    return -1;
}

const Builtin BUILTIN_FUNCTION[NBUILTIN_FUNCTIONS] = {
#define X(name, arity, form, c, value, derivative) {#name, arity, form, c},
    BUILTIN_FUNCTIONS(X)
#undef X
};

int builtin_function(const char *name)
{
    for (int f = 0; f < NBUILTIN_FUNCTIONS; f++)
        if (strcmp(name, BUILTIN_FUNCTION[f].name) == 0)
            return f;
    return -1;
}

int builtin_function_arity(const char *name)
{
    int f = builtin_function(name);
    return f < 0 ? -1 : BUILTIN_FUNCTION[f].arity;
}

double builtin_value(int f, const double *a)
{
    switch (f) {
#define X(name, arity, form, c, value, derivative) case BI_##name: return value;
        BUILTIN_FUNCTIONS(X)
#undef X
    }
    return NAN;
}

int builtin_of_c(const char *c)
{
    for (int f = 0; f < NBUILTIN_FUNCTIONS; f++)
        if (BUILTIN_FUNCTION[f].form == BF_CALL && strcmp(c, BUILTIN_FUNCTION[f].c) == 0)
            return f;
    return -1;
}
