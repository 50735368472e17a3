/* admissible.c — the physical admissibility of a body's numbers (admissible.h): one rule per
 * quantity, which the checker and the XML importer both report. */
#include <math.h>

#include "admissible.h"
#include "util/diag.h"

_Static_assert(SETTING_INT_MAX == 1000, "SETTING_INT_MAX_TEXT says 1000");

const char *inadmissible(Quantity q, double v)
{
    switch (q) {
    case Q_POISSON:
        return v > -1.0 && v < 0.5 ? NULL : "must lie in (-1, 0.5)";
    case Q_VISCOSITY:
    case Q_FRICTION:
        return v >= 0 && isfinite(v) ? NULL : "must not be negative";
    case Q_RESTITUTION:
        return v > 0 && v <= 1 ? NULL : "must be in (0, 1], 1 for an elastic contact";
    case Q_LIMIT: /* s_l of eq. 63 */
        return v >= 0 && v < 1 ? NULL : "must lie in [0, 1)";
    case Q_COUNT:
        return v == floor(v) && v >= 1 && v <= SETTING_INT_MAX
                   ? NULL
                   : "must be an integer from 1 to " SETTING_INT_MAX_TEXT;
    case Q_HOURGLASS:
        return v >= 0 && v <= 10 ? NULL : "must lie in [0, 10] (typically 0.01 to 0.3)";
    case Q_ANY:
        return isfinite(v) ? NULL : "must be finite";
    case Q_GC:
    case Q_SPEED:
    case Q_LENGTH:
        return v > 0 && isfinite(v) ? NULL : "must be positive";
    case Q_DENSITY:
    case Q_YOUNG:
    case Q_SHEAR:
    case Q_BULK:
        break;
    }
    return v > 0 ? NULL : "must be positive";
}

int check_admissible(SrcLoc loc, const char *name, Quantity q, double v)
{
    const char *why = inadmissible(q, v);
    if (why)
        diag_error(loc, "%s %s (got %g)", name, why, v);
    return why ? -1 : 0;
}
