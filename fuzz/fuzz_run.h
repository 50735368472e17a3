/* fuzz_run.h — what the fuzz targets share (fuzz_run.c): an input written to a model file in a
 * private temporary folder and run through sphc's stages in-process, as `sphc --check` would,
 * with the state the stages keep between models reset after each. */
#ifndef SPHC_FUZZ_RUN_H
#define SPHC_FUZZ_RUN_H

#include <stddef.h>
#include <stdint.h>

/* The input as a model file named input.<ext> ("sph" or "xml"): loaded with its imports,
 * checked, lowered and, when that succeeds, printed by every dump, as .sph and emitted for
 * both targets (to /dev/null).  An XML case that imports without an error is imported again
 * with the other readings of docs/xml.md (--xml-elastic2d=sdsph --xml-fill=gencase).
 * Returns 0 (libFuzzer's convention). */
int fuzz_run(const uint8_t *data, size_t size, const char *ext);

#endif
