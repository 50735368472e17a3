/* seen_settings.c — a setting given twice in a scene or a body: an error at the second,
 * with a note at the first. */
#include <stdlib.h>
#include <string.h>

#include "seen_settings.h"
#include "util/diag.h"

int setting_once(SeenSettings *seen, const Setting *s, const char *where)
{
    const int k = name_index_get(&seen->keys, s->key);
    if (k >= 0) {
        diag_error(s->loc, "'%s' is given twice in %s", s->key, where);
        diag_note(seen->first[k]->loc, "first given here");
        return -1;
    }
    seen->first = realloc(seen->first, (size_t)(seen->n + 1) * sizeof *seen->first);
    seen->first[seen->n] = s;
    name_index_put(&seen->keys, s->key, seen->n++);
    return 0;
}

void seen_settings_free(SeenSettings *seen)
{
    name_index_free(&seen->keys);
    free(seen->first);
    memset(seen, 0, sizeof *seen);
}
