/* scalar_eval.c — the scalar graph evaluated with numbers: the reference the compiler checks
 * a derived quantity against (and the tests, a derivative against finite differences). */
#include <math.h>

#include "lang/builtins.h"
#include "scalar.h"
#include "spectral.h"

/* The outputs of runtime routine ext (NaN for one the compiler does not know). */
static void eval_ext(const SGraph *g, int ext, const double *val, double *out)
{
    const SNode *s = &g->nodes[ext];
    double args[SG_MAX_ARGS];
    for (int k = 0; k < s->nargs; k++)
        args[k] = val[s->args[k]];
    if (spectral_eval(s->name, args, s->nargs, out))
        for (int k = 0; k < s->b; k++)
            out[k] = NAN;
}

void sg_eval(const SGraph *g, int upto, SgInput input, void *ctx, const double *params,
             double *val)
{
    double out[SG_MAX_ARGS]; /* the outputs of the routine last evaluated, ext */
    int ext = -1;
    for (int id = 0; id <= upto && id < g->n; id++) {
        const SNode *s = &g->nodes[id];
        switch (s->op) {
        case SN_CONST: val[id] = s->v; break;
        case SN_INPUT: val[id] = input(s->name, (int)s->v, ctx); break;
        case SN_PARAM: val[id] = params ? params[(int)s->v] : NAN; break;
        case SN_NEG:
        case SN_NOT: val[id] = sg_apply(s->op, val[s->a], 0); break;
        case SN_CALL: val[id] = builtin_value(s->fn, &val[s->a]); break;
        case SN_SELECT: val[id] = val[s->a] != 0.0 ? val[s->b] : val[s->c]; break;
        case SN_EXT: val[id] = NAN; break; /* its outputs are its parts */
        case SN_PART:
            if (ext != s->a)
                eval_ext(g, ext = s->a, val, out);
            val[id] = out[(int)s->v];
            break;
        default: val[id] = sg_apply(s->op, val[s->a], val[s->b]); break;
        }
    }
}
