/* Static bending in plane strain at 5 particles through the thickness (bending2d5.sph,
 * bending_check.h): within 2 % of the finite-element deflection (+1.2 %; with eq. 63's
 * gradient and a held clamp +57 %). */
#define main generated_main
#include "bending2d5.c"
#undef main

#include "bending_check.h"

int main(void)
{
    /* P: 50 N/m^3 over the end layer, 2 x 10 mm (per metre of width); FE: L/t = 5, s = 0.2 t */
    const bending_case c = {0.15, -50 * 2e-3 * 10e-3, 1e6, 1.0, -440.319, 0.02,
                            "plane strain, 5 particles through the thickness"};
    return bending_run(&c);
}
