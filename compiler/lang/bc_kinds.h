/* bc_kinds.h — the kinds of boundary condition a body may have (`velocity x = ...`,
 * `force point z = ...`), one table that both front ends, the checker, the printers and the
 * emitter read. */
#ifndef SPHC_BC_KINDS_H
#define SPHC_BC_KINDS_H

#include <stddef.h>

/* The pass of a body's step that applies a kind (the templates' VELOCITY_BCS, FORCE_BCS):
 * the velocity pass sets the listed velocity components to the value and holds them through
 * the step; the force pass adds value * scale to the listed components of the acceleration. */
typedef enum { BC_VELOCITY, BC_FORCE } BcPass;

/* The kinds, one row each: X(id, written, pass, xml, scale2, scale3, what) with
 *   written  the statement's words as the user writes them: its keyword (`velocity`,
 *            `force`), then for a force its kind, the word the parser looks up after `force`
 *            (the printers and dumps print these words);
 *   pass     its BcPass;
 *   xml      the SoliDualSPHysics <bcforce type="N"> the XML importer reads as this kind
 *            (0: none);
 *   scale2   (force pass) the factor of the value in a 2D and a 3D body, a C expression of
 *   scale3   the generated force pass's `sph_body *b` (NULL for the velocity pass): a force
 *            on a particle is divided by its mass, a traction is times its face dx^(dim-1)
 *            (dx times 1 m in 2D) over its mass;
 *   what     what the value is, for messages.
 * A new kind applied by one of the two passes is one row (and its lines in
 * docs/language.md). */
#define BC_KINDS(X)                                                                            \
    X(velocity, "velocity", BC_VELOCITY, 0, NULL, NULL, "velocity")                            \
    X(point, "force point", BC_FORCE, 1, "1.0 / b->mass", "1.0 / b->mass", "point force")      \
    X(surface, "force surface", BC_FORCE, 2, "b->dx / b->mass", "b->dx * b->dx / b->mass",     \
      "surface traction")                                                                      \
    X(accel, "force accel", BC_FORCE, 3, "1.0", "1.0", "acceleration")                         \
    X(volume, "force volume", BC_FORCE, 0, "1.0 / b->rho0", "1.0 / b->rho0", "force per volume")

/* Their indices: BC_KIND_velocity, BC_KIND_point, ... */
typedef enum {
#define X(id, written, pass, xml, scale2, scale3, what) BC_KIND_##id,
    BC_KINDS(X)
#undef X
    NBC_KINDS
} BcKind;

typedef struct {
    const char *written;
    BcPass pass;
    int xml;
    const char *scale[2]; /* [0] 2D, [1] 3D */
    const char *what;
} BcKindRow;

extern const BcKindRow BC_KIND[NBC_KINDS];

/* The kind written as `keyword` alone (word NULL) or `keyword word`, or -1. */
int bc_kind_find(const char *keyword, const char *word);
/* The words that may follow `keyword`, "point, surface or accel", into buf. */
void bc_kind_words(const char *keyword, char *buf, size_t size);
/* The kind a SoliDualSPHysics <bcforce type> reads as, or -1; the largest such type. */
int bc_kind_of_xml(int type);
int bc_kind_xml_max(void);

#endif
