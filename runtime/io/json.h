/* json.h — the small JSON writer of summary.json (json.c). */
#ifndef SPHRT_IO_JSON_H
#define SPHRT_IO_JSON_H

#include <stdio.h>

/* A small JSON writer (pretty-printed, 2-space indent) for summary.json, written whole
 * (sph_open_whole). */
typedef struct {
    FILE *f;
    char *path;
    int depth;
    int first[32]; /* per depth: no member written yet */
} sph_json;
int sph_json_open(sph_json *j, const char *path);  /* writes "{" */
void sph_json_key_object(sph_json *j, const char *key);  /* "key": {   (key NULL inside arrays) */
void sph_json_key_array(sph_json *j, const char *key);   /* "key": [ */
void sph_json_end_object(sph_json *j);
void sph_json_end_array(sph_json *j);
void sph_json_num(sph_json *j, const char *key, double v);  /* non-finite -> null */
void sph_json_int(sph_json *j, const char *key, long v);
void sph_json_str(sph_json *j, const char *key, const char *s); /* escaped */
void sph_json_bool(sph_json *j, const char *key, int v);
int sph_json_close(sph_json *j);  /* writes the final "}" and closes */

#endif
