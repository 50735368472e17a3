/* kernel.c — SPH kernels with support 2h (q = r/h in [0, 2)).
 *
 *  Wendland C2 (as in DualSPHysics):  W = aD (1 - q/2)^4 (2q + 1),
 *      aD = 7 / (4 pi h^2) in 2D, 21 / (16 pi h^3) in 3D;
 *      dW/dr / r = -5 aD / h^2 (1 - q/2)^3.
 *  Cubic spline (Monaghan 1992):  W = aD (1 - 1.5 q^2 + 0.75 q^3)  for q < 1,
 *                                 W = aD 0.25 (2 - q)^3            for 1 <= q < 2,
 *      aD = 10 / (7 pi h^2) in 2D, 1 / (pi h^3) in 3D;
 *      dW/dr / r = aD / h^2 (-3 + 2.25 q)            for q < 1,
 *                = -0.75 aD / h^2 (2 - q)^2 / q      for 1 <= q < 2.
 *  Both dW/dr / r are finite as r -> 0; the formulas above give the limit at r = 0.
 *  Everything is 0 for q >= 2.
 */
#include <math.h>

#include "kernel.h"

double sph_kernel_w(sph_kernel_kind k, int dim, double r, double h)
{
    double q = r / h, ad = sph_kernel_norm(k, dim, h);
    if (q >= 2.0)
        return 0.0;
    if (k == SPH_CUBIC) {
        if (q < 1.0)
            return ad * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
        double t = 2.0 - q;
        return ad * 0.25 * t * t * t;
    }
    double t = 1.0 - 0.5 * q, t2 = t * t;
    return ad * t2 * t2 * (2.0 * q + 1.0);
}
