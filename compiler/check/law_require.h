/* law_require.h — what a law's parameters must satisfy: `require cond [, "message"]`
 * (law_require.c). */
#ifndef SPHC_LAW_REQUIRE_H
#define SPHC_LAW_REQUIRE_H

#include "model/model.h"
#include "util/source.h"

/* The requirements of a law checked with the law: each at the law's top level (not in an
 * `if` or the `tension` block), a scalar condition that reads only the law's parameters,
 * numbers and the model's constants and functions.  0, or -1 after reporting. */
int law_require_check(const Model *m, const MaterialDef *law);

/* Every requirement of body b's law evaluated with the body's parameter values (b->law_args,
 * the elastic constants derived): one that is false or not a finite number is an error at
 * loc (the body's `material` item), with a note at the requirement.  Requirements that
 * law_require_check refused are left out (reported there).  0, or -1 after reporting. */
int law_require_body(const Model *m, const BodyModel *b, SrcLoc loc);

#endif
