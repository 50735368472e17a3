/* fuzz_sph.c — libFuzzer target: an input as an .sph model, through the parser, the checker,
 * the lowering and the printers and emitters (fuzz_run.c). */
#include "fuzz_run.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_run(data, size, "sph");
}
