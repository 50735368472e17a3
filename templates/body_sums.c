/* ---- body @B@: its step sums at the end of a step -----------------------------------------
 * What both targets add to the body's step sums (runtime/scene/step_sums.h) once its update
 * is done, written once in the words SPH_STEP_SUM (the CPU's member of sph_body, the device's
 * slot of b->red), SPH_STEP_ONCE (statements once) and SPH_STEP_SUM_OVER (a sum over the
 * particles, in a pass of its own).  The sums that ride in a pass's own loop are that pass's:
 * the update's maxima (body_update.c, body_cuda.cu), the momentum pass's viscous power
 * (body_forces.c, body_cuda.cu). */
static void @B@_step_sums(sph_body *b, sph_time dt)
{
//@if VISCOSITY
    /* the energy artificial viscosity has dissipated: its power this step times the step */
    SPH_STEP_ONCE({ SPH_STEP_SUM(b, visc_dissipated) += SPH_STEP_SUM(b, visc_rate) * dt; });
//@endif
    (void)b, (void)dt;
}
