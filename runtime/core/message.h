/* message.h — the runtime's messages on stderr, "NAME: error: ..." (a line each), NAME the
 * program's model once sph_main or sph_sim_init has set it (message.c). */
#ifndef SPHRT_CORE_MESSAGE_H
#define SPHRT_CORE_MESSAGE_H

#include "defs.h"

SPH_C_BEGIN

void sph_message_program(const char *name);
#if defined(__GNUC__)
#define SPH_PRINTF __attribute__((format(printf, 1, 2)))
#else
#define SPH_PRINTF
#endif
void sph_error(const char *fmt, ...) SPH_PRINTF;
void sph_warning(const char *fmt, ...) SPH_PRINTF;
void sph_note(const char *fmt, ...) SPH_PRINTF;
/* On the processes other than the first of a run on many processes: messages are not printed,
 * the first error is kept (sph_message_kept; "" when none). */
void sph_message_keep(int keep);
const char *sph_message_kept(void);

SPH_C_END

#endif
