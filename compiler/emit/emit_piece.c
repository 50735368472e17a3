/* emit_piece.c — one piece of a body's code (the kinds of emit_internal.h's BodyPiece, in the
 * order the target's table lists them): each kind to the emitter that writes it. */
#include "emit_fracture.h"
#include "emit_internal.h"

int emit_body_piece(Emitter *E, const BodyPiece *piece, const BodyModel *b, const BodyPlan *p)
{
    switch (piece->kind) {
    case PIECE_LAW: emit_material(E, b, p); return 0;
    case PIECE_GRAVITY: emit_gravity(E, b, p); return 0;
    case PIECE_TEMPLATE: return emit_template(E, piece->file, b, p);
    case PIECE_LANES: return emit_template_lanes(E, piece->file, b, p);
    case PIECE_BCS: emit_bc_passes(E, b, p); return 0;
    case PIECE_RESTRICT: emit_fracture_restrict(E, b); return 0;
    case PIECE_END: return 0;
    }
    return 0;
}
