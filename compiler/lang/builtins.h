/* builtins.h — the built-in names of the expression language (paper Tables 1 and 2). */
#ifndef SPHC_BUILTINS_H
#define SPHC_BUILTINS_H

/* Names of the expression variables of paper Table 1, in the order of sph_pt. */
int builtin_variable(const char *name); /* index or -1 */
extern const char *const BUILTIN_VARIABLES[];
extern const int NBUILTIN_VARIABLES;

/* Built-in scalar functions (Table 2): arity or -1 when unknown. */
int builtin_function_arity(const char *name);

#endif
