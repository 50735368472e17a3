/* ---- body @B@: output --------------------------------------------------------------------
 * Cauchy stress sigma = F S F^T / J of every particle (xx yy zz xy yz zx), on the host from
 * F as the last step left it (the CUDA target copies it back first). */
static void @B@_stress_output(sph_body *b)
{
#pragma omp parallel for schedule(static)
    for (int i = 0; i < b->nown; i++) {
        const double *F = b->F + (size_t)i * 9;
        double S[9], e, FS[9], sig[9];
//@if FRACTURE
        double ep;
        @B@_material(F, b->s[i], S, &e, &ep);
//@else
//@if LAW_FDOT
        const double *Fd = b->Fd + (size_t)i * 9; /* the rate of the last stress pass */
//@endif
//@if LAW_DT
        const double dt = 0; /* no time passes: the law's response at its state */
//@endif
//@if LAW_WAVE
        double cw; /* (not needed here) */
//@endif
//@if STATE
        double st_new[@NSTATE@]; /* the state as the last step left it: not advanced here */
        @B@_material(F, @LAW_ARGS@b->state + (size_t)i * @NSTATE@, st_new, S, &e@LAW_OUTS@);
//@else
        @B@_material(F, @LAW_ARGS@S, &e@LAW_OUTS@);
//@endif
//@endif
        sph_mat3_mul(F, S, FS);
        sph_mat3_mul_bt(FS, F, sig);
        const double J = sph_det3(F);
        static const int idx[6] = {0, 4, 8, 1, 5, 2};
        for (int k = 0; k < 6; k++)
            b->sigma[(size_t)i * 6 + k] = sig[idx[k]] / J;
    }
}
