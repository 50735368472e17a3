/* check_body.h — checking a body (check_body.c). */
#ifndef SPHC_CHECK_BODY_H
#define SPHC_CHECK_BODY_H

#include "model/model.h"

/* Body d of model m checked into b: 0, or -1 after reporting. */
int check_body(Model *m, const BodyDecl *d, BodyModel *b);

#endif
