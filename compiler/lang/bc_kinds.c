/* bc_kinds.c — the kinds of boundary condition (bc_kinds.h's table) and their look-ups. */
#include <stdio.h>
#include <string.h>

#include "bc_kinds.h"

const BcKindRow BC_KIND[NBC_KINDS] = {
#define X(id, written, pass, xml, scale2, scale3, what) {written, pass, xml, {scale2, scale3}, what},
    BC_KINDS(X)
#undef X
};

/* The word after `keyword ` in kind k's written words: "" for the keyword alone, NULL when
 * k is written with another keyword. */
static const char *word_after(int k, const char *keyword)
{
    const char *w = BC_KIND[k].written;
    size_t n = strlen(keyword);
    if (strncmp(w, keyword, n) || (w[n] && w[n] != ' '))
        return NULL;
    return w[n] ? w + n + 1 : w + n;
}

int bc_kind_find(const char *keyword, const char *word)
{
    for (int k = 0; k < NBC_KINDS; k++) {
        const char *w = word_after(k, keyword);
        if (w && !strcmp(w, word ? word : ""))
            return k;
    }
    return -1;
}

void bc_kind_words(const char *keyword, char *buf, size_t size)
{
    int n = 0, len = 0;
    for (int k = 0; k < NBC_KINDS; k++)
        n += word_after(k, keyword) != NULL;
    buf[0] = 0;
    for (int k = 0, i = 0; k < NBC_KINDS && len >= 0 && (size_t)len < size; k++) {
        const char *w = word_after(k, keyword);
        if (!w)
            continue;
        i++;
        len += snprintf(buf + len, size - (size_t)len, "%s%s",
                        i == 1 ? "" : i == n ? " or " : ", ", w);
    }
}

int bc_kind_of_xml(int type)
{
    for (int k = 0; k < NBC_KINDS; k++)
        if (type > 0 && BC_KIND[k].xml == type)
            return k;
    return -1;
}

int bc_kind_xml_max(void)
{
    int max = 0;
    for (int k = 0; k < NBC_KINDS; k++)
        if (BC_KIND[k].xml > max)
            max = BC_KIND[k].xml;
    return max;
}
