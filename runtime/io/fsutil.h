/* fsutil.h — file-system helpers (fsutil.c): folders, files written whole, the files a run
 * leaves in its output folder.  Functions that write return 0 on success, -1 on an I/O error
 * (after printing "sph: error: cannot write PATH: reason" to stderr). */
#ifndef SPHRT_IO_FSUTIL_H
#define SPHRT_IO_FSUTIL_H

#include <stddef.h>
#include <stdio.h>

/* mkdir -p */
int sph_mkdirs(const char *path);

/* A file written whole: sph_open_whole opens PATH.tmp beside it (NULL and errno when it
 * cannot), sph_close_whole closes it and renames it over PATH once complete (0, or the
 * error, the temporary file removed), so that a run killed while writing leaves the
 * previous file or none, never a part of one. */
FILE *sph_open_whole(const char *path);
int sph_close_whole(FILE *f, const char *path);

/* The files a run writes in folder dir (summary.json, the CSV files, the checkpoint, the
 * frames and .pvd lists in particles/, and those cut short while being written), by their
 * names: how many there are, the first one's in first (len bytes; NULL: not wanted), and
 * all of them removed when remove_them (-1 after reporting one that cannot be). */
long sph_run_files(const char *dir, int remove_them, char *first, size_t len);

#endif
