/* sph_print.h — printing a Program as an .sph model (sphc --to-sph). */
#ifndef SPHC_SPH_PRINT_H
#define SPHC_SPH_PRINT_H

#include <stdio.h>

#include "ast.h"

/* The items of the program's main file, as a model that parses back to the same tree. */
void sph_print_program(const Program *p, FILE *out);
/* One expression with the parentheses precedence needs. */
void sph_print_expr(const Expr *e, FILE *out);

/* Each line of text (NULL: none) as a `# ` comment. */
void sph_print_comment(const char *text, FILE *out);

#endif
