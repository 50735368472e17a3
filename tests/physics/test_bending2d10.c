/* Static bending in plane strain at 10 particles through the thickness (bending2d10.sph,
 * bending_check.h): within 1 % of the finite-element deflection (+0.5 %). */
#define main generated_main
#include "bending2d10.c"
#undef main

#include "bending_check.h"

int main(void)
{
    /* P: 100 N/m^3 over the end layer, 1 x 10 mm (per metre of width); FE: L/t = 5, s = 0.1 t */
    const bending_case c = {0.15, -100 * 1e-3 * 10e-3, 1e6, 1.0, -453.723, 0.01,
                            "plane strain, 10 particles through the thickness"};
    return bending_run(&c);
}
