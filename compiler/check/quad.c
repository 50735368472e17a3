/* quad.c — whether the four corners of a quad (a measurement plane, a notch) span an area. */
#include <math.h>

#include "quad.h"
#include "util/diag.h"

int quad_spans(const double p[4][3], SrcLoc loc, const char *what)
{
    double size = 0, area = 0;
    for (int a = 0; a < 4; a++)
        for (int c = 0; c < 3; c++)
            size = fmax(size, fabs(p[a][c] - p[0][c]));
    for (int a = 0; a < 4; a++)
        for (int b = a + 1; b < 4; b++)
            if (p[a][0] == p[b][0] && p[a][1] == p[b][1] && p[a][2] == p[b][2]) {
                diag_error(loc, "the %s has corners %d and %d at the same point", what, a + 1, b + 1);
                return -1;
            }
    for (int t = 0; t < 2; t++) { /* the triangles (0, 1, 2) and (0, 2, 3) */
        double u[3], v[3];
        for (int c = 0; c < 3; c++) {
            u[c] = p[t + 1][c] - p[0][c];
            v[c] = p[t + 2][c] - p[0][c];
        }
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                             u[0] * v[1] - u[1] * v[0]};
        area += 0.5 * sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    }
    if (!(area > 1e-9 * size * size)) {
        diag_error(loc, "the %s's corners lie on a line: they span no area", what);
        return -1;
    }
    return 0;
}
