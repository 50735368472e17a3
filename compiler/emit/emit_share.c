/* emit_share.c — bodies that run the same code.  Two bodies of one material, kernel and
 * features (the flyer plates, a projectile and a target of one steel) differ only in their
 * boundary conditions and particles: their law, pair terms and passes would be the same
 * functions twice under two names.  A body whose code pieces (piece_is_code), written under
 * an earlier body's name, are that body's text character for character runs that body's
 * functions instead; only its boundary conditions are written for it.  The same text is
 * the same program, so nothing the code reads can differ between them (what differs between
 * the bodies, their particles, density and counts, the passes read from the sph_body at run
 * time).  The generated file gets each piece of physics once however many bodies use it,
 * and its compile time no longer grows with such bodies. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "emit_internal.h"

/* Body i's code pieces written under the name `as` (NULL where they could not be written:
 * *failed set where a template reported an error). */
static char *code_text(const Emitter *E, int i, char *as, int *failed)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return NULL;
    Emitter R = *E;
    R.out = f;
    R.code = NULL;
    BodyModel b = E->m->bodies[i];
    b.name = as;
    int rc = 0;
    for (const BodyPiece *piece = E->target->body; piece->kind != PIECE_END && !rc; piece++)
        if (piece_is_code(piece->kind))
            rc = emit_body_piece(&R, piece, &b, &E->plans[i]);
    fclose(f);
    if (rc) {
        *failed = 1;
        free(text);
        return NULL;
    }
    return text;
}

int emit_share_code(Emitter *E, int *code)
{
    const int n = E->m->nbodies;
    for (int i = 0; i < n; i++)
        code[i] = i;
    if (n < 2 || !E->target->share_code)
        return 0;
    char **own = calloc((size_t)n, sizeof *own); /* the text of each body that runs its own */
    if (!own)
        return 0; /* (each body its own code: what the program does is the same) */
    int failed = 0;
    for (int i = 0; i < n && !failed; i++) {
        for (int j = 0; j < i && code[i] == i && !failed; j++) {
            if (code[j] != j || !own[j])
                continue;
            char *mine = code_text(E, i, E->m->bodies[j].name, &failed);
            if (mine && !strcmp(mine, own[j]))
                code[i] = j;
            free(mine);
        }
        if (code[i] == i && !failed)
            own[i] = code_text(E, i, E->m->bodies[i].name, &failed);
    }
    for (int i = 0; i < n; i++)
        free(own[i]);
    free(own);
    return failed ? -1 : 0;
}
