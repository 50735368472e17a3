/* fuzz_xml.c — libFuzzer target: an input as a SoliDualSPHysics case (.xml), through the
 * importer, the checker, the lowering and the printers and emitters (fuzz_run.c). */
#include "fuzz_run.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    return fuzz_run(data, size, "xml");
}
