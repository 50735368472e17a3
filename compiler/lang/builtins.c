/* builtins.c — the built-in names of the expression language (paper Tables 1 and 2). */
#include <string.h>

#include "builtins.h"

/* Order matters: it is the field order of sph_pt in runtime/sphrt.h. */
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

static const struct {
    const char *name;
    int arity;
} FUNCTIONS[] = {
    {"sin", 1},  {"cos", 1},  {"tan", 1},  {"cot", 1},   {"sinh", 1}, {"cosh", 1},
    {"tanh", 1}, {"coth", 1}, {"sqrt", 1}, {"log", 1},   {"ln", 1},   {"exp", 1},
    {"abs", 1},  {"pow", 2},  {"min", 2},  {"max", 2},   {"if", 3},
};

int builtin_function_arity(const char *name)
{
    for (size_t i = 0; i < sizeof FUNCTIONS / sizeof FUNCTIONS[0]; i++)
        if (strcmp(name, FUNCTIONS[i].name) == 0)
            return FUNCTIONS[i].arity;
    return -1;
}
