/* quad.h — whether the four corners of a quad span an area (quad.c). */
#ifndef SPHC_QUAD_H
#define SPHC_QUAD_H

#include "util/source.h"

/* The four corners of a quad (a measurement plane, a notch) must be four points spanning an
 * area: two equal or three in a line measure nothing (select.c would find no particle, or
 * divide by a zero normal).  0, or -1 after reporting at loc, naming the quad `what`. */
int quad_spans(const double p[4][3], SrcLoc loc, const char *what);

#endif
