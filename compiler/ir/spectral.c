/* spectral.c — the spectral routines of the runtime (sph_tensor.h) in the compiler: their
 * values for sg_eval and the routines of their reverse-mode derivatives for derivative.c.
 *
 * The derivative of pos (Daleckii-Krein, eq. 13-16 differentiated): for a symmetric A with
 * eigenpairs (l_k, q_k) and F(A) = sum f(l_k) q_k q_k^T, the adjoint B of F(A) reaches A as
 * Q (Gamma o (Q^T sym(B) Q)) Q^T, Gamma_ij the divided differences of f = max(., 0).  It is
 * exact for any adjoint, and for a trace of a function of A it reduces to
 * d tr(F(A)) / dA = f'(A): d tr(pos(A)^2) / dA = 2 pos(A), d tr(neg(A)^2) / dA = 2 neg(A).
 * The adjoint is one more runtime routine (an SN_EXT node of the inputs and the output's
 * adjoints), which the emitters print as any other. */
#include <stddef.h>
#include <string.h>

#include "sph_tensor.h"
#include "spectral.h"

typedef void (*Routine)(const double *args, double *out);

static void pos3(const double *a, double *out) { sph_sym_pos3(a, out); }
static void pos2(const double *a, double *out) { sph_sym_pos2(a[0], a[1], a[2], out); }
static void pos3_adjoint(const double *a, double *out) { sph_sym_pos3_adjoint(a, out); }
static void pos2_adjoint(const double *a, double *out) { sph_sym_pos2_adjoint(a, out); }

static const struct {
    const char *name;
    int nargs, nout;
    Routine fn;
    const char *adjoint; /* the routine of its derivative, or NULL */
} ROUTINES[] = {
    {SPECTRAL_POS3, 9, 9, pos3, SPECTRAL_POS3_ADJOINT},
    {SPECTRAL_POS2, 3, 3, pos2, SPECTRAL_POS2_ADJOINT},
    {SPECTRAL_POS3_ADJOINT, 18, 9, pos3_adjoint, NULL},
    {SPECTRAL_POS2_ADJOINT, 6, 3, pos2_adjoint, NULL},
};
enum { NROUTINES = sizeof ROUTINES / sizeof ROUTINES[0] };

static int find(const char *name, int nargs)
{
    for (int k = 0; k < NROUTINES; k++)
        if (!strcmp(ROUTINES[k].name, name) && ROUTINES[k].nargs == nargs)
            return k;
    return -1;
}

int spectral_eval(const char *name, const double *args, int nargs, double *out)
{
    const int k = find(name, nargs);
    if (k < 0)
        return -1;
    ROUTINES[k].fn(args, out);
    return 0;
}

const char *spectral_adjoint_of(const char *name, int nargs)
{
    const int k = find(name, nargs);
    return k < 0 ? NULL : ROUTINES[k].adjoint;
}
