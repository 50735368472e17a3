/* check_fracture.h — checking a body's phase-field fracture (check_fracture.c). */
#ifndef SPHC_CHECK_FRACTURE_H
#define SPHC_CHECK_FRACTURE_H

#include "model/model.h"

/* A fracture(...), notch or restrict item of a body, and the body's consistency once all
 * its items are read: 0, or -1 after reporting. */
int check_fracture_item(const Model *m, const BodyItem *it, FractureModel *f);
int check_fracture_body(const BodyModel *b, const BodyDecl *d);

#endif
