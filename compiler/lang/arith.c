/* arith.c — the arithmetic of constant folding (arith.h). */
#include <math.h>

#include "arith.h"

double arith_binary(ArithOp op, double x, double y)
{
    switch (op) {
    case AR_ADD: return x + y;
    case AR_SUB: return x - y;
    case AR_MUL: return x * y;
    case AR_DIV: return x / y;
    case AR_POW: return pow(x, y);
    case AR_MIN: return x < y || isnan(x) ? x : y; /* NaN wins, as in the programs (sph_min) */
    case AR_MAX: return x > y || isnan(x) ? x : y;
    case AR_LT: return x < y;
    case AR_LE: return x <= y;
    case AR_GT: return x > y;
    case AR_GE: return x >= y;
    case AR_EQ: return x == y;
    case AR_NE: return x != y;
    case AR_AND: return x != 0.0 && y != 0.0;
    case AR_OR: return x != 0.0 || y != 0.0;
    default: return NAN;
    }
}

double arith_unary(ArithOp op, double x)
{
    return op == AR_NEG ? -x : (double)(x == 0.0);
}
