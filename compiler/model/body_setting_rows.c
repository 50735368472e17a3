/* body_setting_rows.c — the table of a body's settings (body_settings.h) as rows the stages
 * read, with where each member lies, and a body's settings by row (model.h). */
#include <string.h>

#include "model.h"

#define OFFSET_SET_INT(kw) offsetof(BodyModel, kw)
#define OFFSET_SET_NUMBER(kw) offsetof(BodyModel, kw)
#define OFFSET_SET_POINT(kw) offsetof(BodyModel, kw)
#define OFFSET_SET_OWN(kw) 0
#define HAS_SET_INT(kw) 0
#define HAS_SET_NUMBER(kw) 0
#define HAS_SET_POINT(kw) offsetof(BodyModel, has_##kw)
#define HAS_SET_OWN(kw) 0
#define SETTING_ROW(kw, form, def, rule, sw, pair, what)                                          \
    {#kw, form, def, rule, sw, pair, what, OFFSET_##form(kw), HAS_##form(kw)},
const BodySetting BODY_SETTING_ROWS[BODY_NSETTINGS] = {BODY_SETTINGS(SETTING_ROW)};
#undef SETTING_ROW

const BodySetting *body_setting_find(const char *keyword)
{
    for (int k = 0; k < BODY_NSETTINGS; k++)
        if (!strcmp(BODY_SETTING_ROWS[k].keyword, keyword))
            return &BODY_SETTING_ROWS[k];
    return NULL;
}

int *body_setting_int(BodyModel *b, const BodySetting *s)
{
    return s->form == SET_INT ? (int *)((char *)b + s->offset) : NULL;
}

double *body_setting_number(BodyModel *b, const BodySetting *s)
{
    const int number = s->form == SET_NUMBER || s->form == SET_POINT;
    return number ? (double *)((char *)b + s->offset) : NULL;
}

const double *body_setting_point(const BodyModel *b, const BodySetting *s)
{
    return s->form == SET_POINT ? (const double *)((const char *)b + s->offset) : NULL;
}

int *body_setting_given(BodyModel *b, const BodySetting *s)
{
    return s->form == SET_POINT ? (int *)((char *)b + s->has_offset) : NULL;
}

double body_setting_value(const BodyModel *b, const BodySetting *s)
{
    const char *base = (const char *)b;
    switch (s->form) {
    case SET_INT:
        return *(const int *)(base + s->offset);
    case SET_NUMBER:
        return *(const double *)(base + s->offset);
    case SET_POINT:
        return *(const int *)(base + s->has_offset);
    case SET_OWN:
        break;
    }
    return 0;
}

void body_settings_default(BodyModel *b)
{
    for (int k = 0; k < BODY_NSETTINGS; k++) {
        const BodySetting *s = &BODY_SETTING_ROWS[k];
        if (s->form == SET_INT)
            *body_setting_int(b, s) = (int)s->def;
        else if (s->form == SET_NUMBER)
            *body_setting_number(b, s) = s->def;
    }
}
