/* arith.h — the arithmetic of constant folding.  The interpreter (check/eval.c) and the
 * scalar graph (ir/scalar.c) both fold through it, so a constant has one value whichever
 * stage computes it. */
#ifndef SPHC_ARITH_H
#define SPHC_ARITH_H

typedef enum {
    AR_ADD, AR_SUB, AR_MUL, AR_DIV, AR_POW, AR_MIN, AR_MAX,
    AR_LT, AR_LE, AR_GT, AR_GE, AR_EQ, AR_NE, AR_AND, AR_OR,
    AR_NEG, AR_NOT
} ArithOp;

/* x op y for the binary operators (NaN for the unary ones); comparisons and logic give
 * 0 or 1, any nonzero operand being true. */
double arith_binary(ArithOp op, double x, double y);
/* -x (AR_NEG) or not x (AR_NOT: 1 for 0, else 0). */
double arith_unary(ArithOp op, double x);

#endif
