/* seen_settings.h — the settings of a scene or a body seen so far, to refuse one given
 * twice (seen_settings.c). */
#ifndef SPHC_SEEN_SETTINGS_H
#define SPHC_SEEN_SETTINGS_H

#include "front/ast.h"
#include "util/name_index.h"

typedef struct {
    NameIndex keys;           /* key -> its setting in first[] */
    const Setting **first;
    int n;
} SeenSettings;

/* 0 the first time s's key is seen; -1 after reporting it as given twice (with a note at
 * the first).  `where` names the scene or the body for the message. */
int setting_once(SeenSettings *seen, const Setting *s, const char *where);
void seen_settings_free(SeenSettings *seen);

#endif
