/* fsutil.c — file-system helpers. */
#include "output.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

/* Creates one directory; an existing directory is fine. */
static int mkdir_one(const char *dir)
{
    struct stat st;
    if (mkdir(dir, 0777) == 0)
        return 0;
    if (errno == EEXIST && stat(dir, &st) == 0 && S_ISDIR(st.st_mode))
        return 0;
    if (errno == EEXIST)
        errno = ENOTDIR;
    return -1;
}

/* mkdir -p: creates path and every missing parent. */
int sph_mkdirs(const char *path)
{
    size_t len = strlen(path);
    char *dir = len ? malloc(len + 1) : NULL;
    if (!dir) {
        sph_error("cannot create %s: %s", path,
                  strerror(len ? ENOMEM : ENOENT));
        return -1;
    }
    memcpy(dir, path, len + 1);
    int rc = 0;
    for (char *p = dir + 1; rc == 0 && p <= dir + len; p++) {
        if (*p != '/' && *p != '\0')
            continue;
        if (p[-1] == '/')
            continue; /* repeated or trailing slash */
        char c = *p;
        *p = '\0';
        rc = mkdir_one(dir);
        *p = c;
    }
    if (rc != 0)
        sph_error("cannot create %s: %s", dir, strerror(errno));
    free(dir);
    return rc;
}
