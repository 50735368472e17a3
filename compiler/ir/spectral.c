/* spectral.c — the spectral routines of the runtime (sph_tensor.h) in the compiler: their
 * values for sg_eval and their reverse-mode derivatives for derivative.c.
 *
 * The derivative of pos (Daleckii-Krein, eq. 13-16 differentiated): for a symmetric A with
 * eigenpairs (l_k, q_k) and F(A) = sum f(l_k) q_k q_k^T, the adjoint B of F(A) reaches A as
 * Q (Gamma o (Q^T sym(B) Q)) Q^T, Gamma_ij the divided differences of f = max(., 0).  It is
 * exact for any adjoint, and for a trace of a function of A it reduces to
 * d tr(F(A)) / dA = f'(A): d tr(pos(A)^2) / dA = 2 pos(A), d tr(neg(A)^2) / dA = 2 neg(A).
 * The adjoint is one more runtime routine (an SN_EXT node of the inputs and the output's
 * adjoints), which the emitters print as any other. */
#include <math.h>
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

int spectral_adjoint(SGraph *g, int ext, const int *bar, int *arg_bar)
{
    const SNode s = g->nodes[ext]; /* a copy: g grows */
    const int k = find(s.name, s.nargs);
    if (k < 0 || !ROUTINES[k].adjoint || s.nargs + s.b > SG_MAX_ARGS)
        return -1;
    int args[SG_MAX_ARGS], any = 0;
    memcpy(args, s.args, (size_t)s.nargs * sizeof(int));
    for (int q = 0; q < s.b; q++) {
        double v;
        args[s.nargs + q] = bar[q] >= 0 ? bar[q] : sg_const(g, 0.0);
        any |= !sg_is_const(g, args[s.nargs + q], &v) || v != 0.0;
    }
    if (!any) { /* no adjoint reaches the routine */
        for (int q = 0; q < s.nargs; q++)
            arg_bar[q] = sg_const(g, 0.0);
        return 0;
    }
    const int adj = sg_ext(g, ROUTINES[k].adjoint, args, s.nargs + s.b, s.nargs);
    for (int q = 0; q < s.nargs; q++)
        arg_bar[q] = sg_part(g, adj, q);
    return 0;
}

/* Whether node id is the constant 0. */
static int is_zero(const SGraph *g, int id)
{
    double v;
    return sg_is_const(g, id, &v) && v == 0.0;
}

/* Whether the 3x3 tensor args[0 .. 8] has the plane-strain structure: no y coupling, and (yy)
 * 0 unless any_yy. */
static int plane(const SGraph *g, const int *args, int any_yy)
{
    return is_zero(g, args[1]) && is_zero(g, args[3]) && is_zero(g, args[5]) &&
           is_zero(g, args[7]) && (any_yy || is_zero(g, args[4]));
}

int spectral_fold_part(SGraph *g, int ext, int k)
{
    const SNode s = g->nodes[ext]; /* a copy: g grows */
    const int pos = s.nargs == 9 && !strcmp(s.name, SPECTRAL_POS3);
    const int adj = s.nargs == 18 && !strcmp(s.name, SPECTRAL_POS3_ADJOINT);
    if (!(pos || adj) || !plane(g, s.args, 0) || (adj && !plane(g, s.args + 9, 1)))
        return -1;
    /* y is an eigenvector of eigenvalue 0: pos_yy = 0, and the adjoint's y row and column
     * are 0 (Gamma(0, 0) = f'(0) = 0, eq. 13-16 differentiated) */
    if (k != 0 && k != 2 && k != 6 && k != 8)
        return sg_const(g, 0.0);
    const int out = k == 0 ? 0 : k == 8 ? 2 : 1;
    if (pos) {
        const int args[3] = {s.args[0], s.args[2], s.args[8]};
        return sg_part(g, sg_ext(g, SPECTRAL_POS2, args, 3, 3), out);
    }
    /* the adjoint of pos2's xz output is that of pos3's (x, z) and (z, x) outputs together;
     * its xz adjoint stands for both entries: half each */
    const int b_xz = sg_binary(g, SN_ADD, s.args[9 + 2], s.args[9 + 6]);
    const int args[6] = {s.args[0], s.args[2], s.args[8], s.args[9], b_xz, s.args[9 + 8]};
    const int part = sg_part(g, sg_ext(g, SPECTRAL_POS2_ADJOINT, args, 6, 3), out);
    return out == 1 ? sg_binary(g, SN_MUL, sg_const(g, 0.5), part) : part;
}
