/* admissible.h — the physical admissibility of a body's numbers, one rule each, shared by the
 * checker (reported at the model's line) and the XML importer (at the card and attribute). */
#ifndef SPHC_ADMISSIBLE_H
#define SPHC_ADMISSIBLE_H

#include "util/source.h"

typedef enum {
    Q_DENSITY, Q_YOUNG, Q_POISSON, Q_SHEAR, Q_BULK, Q_VISCOSITY, Q_RESTITUTION, Q_FRICTION,
    Q_GC, Q_LENGTH, Q_LIMIT,
    Q_COUNT,     /* a whole-number setting: 1 to SETTING_INT_MAX */
    Q_HOURGLASS, /* the hourglass control's coefficient */
    Q_SPEED,     /* a positive speed */
    Q_ANY        /* any finite number */
} Quantity;

/* NULL when v is admissible as q, else the reason, a predicate that follows the number's
 * name ("must be positive"). */
const char *inadmissible(Quantity q, double v);
/* Reports "NAME REASON (got V)" at loc when v is not admissible: 0, or -1 after reporting. */
int check_admissible(SrcLoc loc, const char *name, Quantity q, double v);

/* The largest whole-number body setting (refine, nbsrange). */
#define SETTING_INT_MAX 1000
#define SETTING_INT_MAX_TEXT "1000" /* the same, for messages */

#endif
