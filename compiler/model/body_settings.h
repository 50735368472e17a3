/* body_settings.h — the settings of a body (docs/language.md, "Body settings"), one row each:
 *
 *   X(keyword, form, default, rule, switch, pair, what)
 *
 *   keyword  as a model writes it (`hourglass 0.1`), and the member of BodyModel it sets;
 *   form     SET_INT      a whole number from 1 to SETTING_INT_MAX (an int member);
 *            SET_NUMBER   a number admissible as `rule` (a double member);
 *            SET_POINT    a point [x, y, z] (double keyword[3], and int has_keyword);
 *            SET_OWN      members of its own (model.h), checked by check_body.c's
 *                         OWN_SETTINGS and printed by model_dump.c;
 *   default  its value where a body does not give it;
 *   rule     the Quantity (admissible.h) a SET_NUMBER must be admissible as;
 *   switch   a number that switches a term of the body's code on where nonzero: the template
 *            switch (//@if SWITCH) and key (@SWITCH@, its value), shown by --dump=plan as
 *            keyword=0|1; NULL: none;
 *   pair     1 (with a switch): that term is a pair term, called by B_pair_terms (templates/body_particle.c)
 *            in both targets' momentum passes (lower/layouts.c chooses the layouts that call it);
 *   what     the value in words, for errors ("the hourglass coefficient must lie in ...").
 *
 * The checker, the model's dump, the plan and the templates' switches and keys read the
 * table: a new setting is a row here (and, with a switch, its term in a template). */
#ifndef SPHC_BODY_SETTINGS_H
#define SPHC_BODY_SETTINGS_H

#include <stddef.h>

#include "admissible.h"

#define BODY_SETTINGS(X)                                                                           \
    X(refine, SET_INT, 1, Q_COUNT, NULL, 0, "the refinement of the scene's spacing dp")           \
    X(nbsrange, SET_INT, 0, Q_COUNT, NULL, 0, "the neighbour range in spacings (0: the kernel's)") \
    X(viscosity, SET_OWN, 0, Q_VISCOSITY, NULL, 0, "beta1 and optionally beta2 (eq. 58)")          \
    X(hourglass, SET_NUMBER, 0, Q_HOURGLASS, "HOURGLASS", 1, "the hourglass coefficient")          \
    X(lattice, SET_POINT, 0, Q_COUNT, NULL, 0, "a corner of the lattice's cells")                 \
    X(restitution, SET_NUMBER, 1, Q_RESTITUTION, NULL, 0, "the coefficient of restitution")       \
    X(friction, SET_NUMBER, 0, Q_FRICTION, NULL, 0, "the friction coefficient")                   \
    X(soundspeed, SET_NUMBER, 0, Q_SPEED, NULL, 0, "the sound speed") /* 0: eq. 59's */            \
    X(plane, SET_OWN, 0, Q_COUNT, NULL, 0, "the y of the plane a 2D body's shapes are cut in")  \
    X(clamp, SET_OWN, 0, Q_COUNT, NULL, 0, "a point of the clamped plane and its normal")

typedef enum { SET_INT, SET_NUMBER, SET_POINT, SET_OWN } SettingForm;

/* BodyModel's members for the table's rows (model.h expands BODY_SETTINGS(SETTING_MEMBER)). */
#define SETTING_MEMBER(kw, form, def, rule, sw, pair, what) SETTING_MEMBER_##form(kw)
#define SETTING_MEMBER_SET_INT(kw) int kw;
#define SETTING_MEMBER_SET_NUMBER(kw) double kw;
#define SETTING_MEMBER_SET_POINT(kw) double kw[3]; int has_##kw;
#define SETTING_MEMBER_SET_OWN(kw)

/* A row of the table, as the compiler's stages read it. */
typedef struct {
    const char *keyword;
    SettingForm form;
    double def;
    Quantity rule;
    const char *sw;     /* template switch and key, or NULL */
    int pair;
    const char *what;
    size_t offset;      /* of its member in BodyModel (SET_OWN: 0) */
    size_t has_offset;  /* SET_POINT: of has_<keyword> */
} BodySetting;

#define SETTING_COUNT(kw, form, def, rule, sw, pair, what) +1
enum { BODY_NSETTINGS = 0 BODY_SETTINGS(SETTING_COUNT) };
#undef SETTING_COUNT

/* The rows, with where each member lies (body_setting_rows.c); model.h reads and writes a
 * body's settings by row. */
extern const BodySetting BODY_SETTING_ROWS[BODY_NSETTINGS];

#endif
