/* fuzz_alloc.h — included first in every compiler source of the fuzz targets (-include): the
 * compiler's allocations go through fuzz_alloc.c, which frees what one input left allocated
 * before the next (the syntax tree is never freed by design: sphc is short-lived).  Nothing
 * here includes a system header, so that each source's own feature macros still count. */
#ifndef SPHC_FUZZ_ALLOC_H
#define SPHC_FUZZ_ALLOC_H

void *sphc_fuzz_malloc(__SIZE_TYPE__ size);
void *sphc_fuzz_calloc(__SIZE_TYPE__ n, __SIZE_TYPE__ size);
void *sphc_fuzz_realloc(void *p, __SIZE_TYPE__ size);
void sphc_fuzz_free(void *p);
char *sphc_fuzz_strdup(const char *s);
char *sphc_fuzz_strndup(const char *s, __SIZE_TYPE__ n);

#define malloc sphc_fuzz_malloc
#define calloc sphc_fuzz_calloc
#define realloc sphc_fuzz_realloc
#define free sphc_fuzz_free
#define strdup sphc_fuzz_strdup
#define strndup sphc_fuzz_strndup

/* Free every block allocated through the functions above and not freed since the last call
 * (fuzz_alloc.c).  Returns their number. */
__SIZE_TYPE__ sphc_fuzz_release(void);

#endif
