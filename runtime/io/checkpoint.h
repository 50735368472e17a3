/* checkpoint.h — a run's state in one file, and read back (checkpoint.c). */
#ifndef SPHRT_CHECKPOINT_H
#define SPHRT_CHECKPOINT_H

#include <stdint.h>
#include <stdio.h>

#include "scene/sim.h"

/* Writing: records (a name and bytes) into PATH.part, renamed to PATH at the commit.  An I/O
 * error is reported at the commit, which then returns -1 and leaves the previous PATH. */
typedef struct {
    FILE *f;
    char *path, *tmp;
    int bad;       /* errno of the first failed write */
    uint64_t hash; /* of the bytes written so far */
} sph_ckpt_writer;
int sph_ckpt_create(sph_ckpt_writer *w, const char *path);
void sph_ckpt_put(sph_ckpt_writer *w, const char *name, const void *data, size_t bytes);
int sph_ckpt_commit(sph_ckpt_writer *w);

/* Reading: the whole file, checked (format, machine, complete, and with check_hash the hash
 * of every byte); -1 after reporting.  The file is mapped, not copied: the processes of a run
 * on many processes that read the same checkpoint on one machine share its pages (each takes
 * only its own particles' records), and one of them checks the hash for all (run.c). */
typedef struct {
    const char *path;
    const unsigned char *buf;
    size_t len;
} sph_ckpt;
int sph_ckpt_read(sph_ckpt *c, const char *path, int check_hash);
/* The record called name (*bytes long), or NULL. */
const void *sph_ckpt_find(const sph_ckpt *c, const char *name, size_t *bytes);
/* The record called name into data, which it must fill exactly; -1 after reporting. */
int sph_ckpt_take(const sph_ckpt *c, const char *name, void *data, size_t bytes);
void sph_ckpt_free(sph_ckpt *c);

/* The simulation's records: its clock, every body's state and sums, the contact's.  A device
 * target copies its state to the host first (sph_model.copy_state). */
void sph_sim_checkpoint(sph_ckpt_writer *w, const sph_sim *s);
/* The same into s, set up from the same model: -1 after reporting when the checkpoint is of
 * another model or resolution.  A device target then copies the state to the device. */
int sph_sim_restore(const sph_ckpt *c, sph_sim *s);

#endif
