/* fsutil.c — file-system helpers: folders, files written whole (beside their name, then
 * renamed), and the files a run leaves in its output folder. */

#include <dirent.h>
#include <errno.h>
#include <fnmatch.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>

#include "fsutil.h"
#include "core/message.h"

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

/* ------------------------------------------------------------------ files written whole */

/* PATH.tmp (malloc'd), the name a file is written under until it is complete. */
static char *beside(const char *path)
{
    const size_t len = strlen(path);
    char *tmp = malloc(len + 5);
    if (tmp) {
        memcpy(tmp, path, len);
        memcpy(tmp + len, ".tmp", 5);
    }
    return tmp;
}

FILE *sph_open_whole(const char *path)
{
    char *tmp = beside(path);
    if (!tmp) {
        errno = ENOMEM;
        return NULL;
    }
    FILE *f = fopen(tmp, "wb");
    const int err = errno;
    free(tmp);
    errno = f ? 0 : err;
    return f;
}

int sph_close_whole(FILE *f, const char *path)
{
    int err = ferror(f) ? (errno ? errno : EIO) : 0;
    if (fclose(f) != 0 && !err)
        err = errno ? errno : EIO;
    char *tmp = beside(path);
    if (!tmp)
        return err ? err : ENOMEM;
    if (!err && rename(tmp, path) != 0)
        err = errno ? errno : EIO;
    if (err)
        remove(tmp);
    free(tmp);
    return err;
}

/* ------------------------------------------------------------------ a run's files */

/* The names of the files a run writes (README, "The generated program"), in its folder and
 * in particles/; each also with the suffix of a file cut short while being written. */
static const char *const TOP_FILES[] = {
    "summary.json", "summary.html", "energies.csv", "measure_*.csv", "checkpoint.bin",
    "DeformStruc_Energies.csv", "MeasuringPlData_MK*_PL*.csv", /* (models from XML) */
};
static const char *const PARTIAL[] = {"", ".tmp", ".part"};

/* A frame's name: <body>_<four or more digits>.vtu. */
static int frame_name(const char *name, size_t len)
{
    size_t d = 0;
    if (len < 4 || memcmp(name + len - 4, ".vtu", 4))
        return 0;
    len -= 4;
    while (d < len && name[len - 1 - d] >= '0' && name[len - 1 - d] <= '9')
        d++;
    return d >= 4 && d < len && name[len - 1 - d] == '_';
}

/* Whether name (in the folder, or in particles/) is one of a run's files. */
static int run_file(const char *name, int particles)
{
    for (size_t p = 0; p < sizeof PARTIAL / sizeof *PARTIAL; p++) {
        const size_t len = strlen(name), sl = strlen(PARTIAL[p]);
        if (len <= sl || strcmp(name + len - sl, PARTIAL[p]))
            continue;
        char base[1024];
        if (len - sl >= sizeof base)
            continue;
        memcpy(base, name, len - sl);
        base[len - sl] = '\0';
        if (particles && (frame_name(base, len - sl) || !fnmatch("?*.pvd", base, 0)))
            return 1;
        for (size_t k = 0; !particles && k < sizeof TOP_FILES / sizeof *TOP_FILES; k++)
            if (!fnmatch(TOP_FILES[k], base, 0))
                return 1;
    }
    return 0;
}

/* The run's files in folder dir (particles: its particles/ subfolder), counted and, when
 * remove, removed; first is set to the first one's name.  -1 on a file that cannot be. */
static long scan(const char *dir, int particles, int remove_them, char *first, size_t len)
{
    DIR *d = opendir(dir);
    if (!d)
        return 0; /* (no folder: no files) */
    long n = 0;
    int bad = 0;
    for (struct dirent *e; (e = readdir(d));) {
        if (!run_file(e->d_name, particles))
            continue;
        char path[4096];
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        struct stat st;
        if (lstat(path, &st) || !S_ISREG(st.st_mode))
            continue; /* (only plain files of those names) */
        if (!n++ && first)
            snprintf(first, len, "%s%s", particles ? "particles/" : "", e->d_name);
        if (remove_them && remove(path)) {
            sph_error("cannot remove %s: %s", path, strerror(errno));
            bad = 1;
        }
    }
    closedir(d);
    return bad ? -1 : n;
}

long sph_run_files(const char *dir, int remove_them, char *first, size_t len)
{
    if (first && len)
        first[0] = '\0';
    const size_t dl = strlen(dir);
    char *sub = malloc(dl + 11);
    if (!sub)
        return -1;
    memcpy(sub, dir, dl);
    memcpy(sub + dl, "/particles", 11);
    const long top = scan(dir, 0, remove_them, first, len);
    const long parts = scan(sub, 1, remove_them, first && !first[0] ? first : NULL, len);
    free(sub);
    return top < 0 || parts < 0 ? -1 : top + parts;
}
