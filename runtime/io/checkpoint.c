/* checkpoint.c — a run's state in one file (the program's --checkpoint), and the state read
 * back from it to resume the run (--restart).
 *
 * The file is a list of named records, each its name, its length in bytes and its bytes, after
 * a header that names the format and this machine's byte order and sizes:
 *
 *     "SPHCKPT\n"  u32 version  u32 0x01020304  u32 sizeof(double)  u32 sizeof(long)
 *     { u32 name length, name, pad, u64 length, bytes, pad } ...  "end" record
 *
 * each pad up to a multiple of 8 bytes, so that a record's bytes read in place as doubles;
 * the "end" record holds the FNV-1a hash of every byte before it, which reading checks (a
 * damaged file is refused rather than resumed from a state it never had),
 * so a checkpoint is read back on a machine of the same kind only, which the header checks.
 * It is written beside its final name and renamed over it once complete: a run stopped while
 * writing keeps its previous checkpoint.  The simulation's part (sph_sim_checkpoint): each
 * body's state arrays (sph_body_state_arrays), its sums of the last step (the next time step
 * comes from them), the time, step and time step, and the contact's sums and the positions
 * its candidate lists were built at, so that the resumed run builds the same lists.  The
 * set-up (particles, neighbours, gradients, tables) is made again from the model; each body's
 * particle count and a hash of its reference positions must match the checkpoint's.  run.c
 * adds the run's own records (output times, time series, the files' lengths). */
#include <errno.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint.h"
#include "contact/contact.h"
#include "core/message.h"
#include "core/regular_file.h"
#include "geom/partition.h"
#include "par/par.h"
#include "scene/body.h"
#include "scene/sim.h"
#include "scene/state_arrays.h"
#include "scene/step_sums.h"

static const char MAGIC[8] = {'S', 'P', 'H', 'C', 'K', 'P', 'T', '\n'};
enum { VERSION = 3 }; /* 3: bodies in pieces by global id; 2: the contact's closeness */

/* FNV-1a, 64 bits, of n more bytes after h (FNV_START at first). */
#define FNV_START 1469598103934665603ull
static uint64_t fnv(uint64_t h, const void *data, size_t n)
{
    const unsigned char *p = data;
    for (size_t k = 0; k < n; k++)
        h = (h ^ p[k]) * 1099511628211ull;
    return h;
}

/* ------------------------------------------------------------------ writing */

static void put_raw(sph_ckpt_writer *w, const void *data, size_t bytes)
{
    if (!bytes)
        return;
    w->hash = fnv(w->hash, data, bytes);
    if (!w->bad && fwrite(data, 1, bytes, w->f) != bytes)
        w->bad = errno ? errno : EIO;
}

static void put_u32(sph_ckpt_writer *w, uint32_t v) { put_raw(w, &v, sizeof v); }

int sph_ckpt_create(sph_ckpt_writer *w, const char *path)
{
    memset(w, 0, sizeof *w);
    const size_t len = strlen(path);
    w->path = malloc(len + 1);
    w->tmp = malloc(len + 8);
    if (!w->path || !w->tmp) {
        free(w->path), free(w->tmp);
        sph_error("cannot write %s: out of memory", path);
        return -1;
    }
    memcpy(w->path, path, len + 1);
    snprintf(w->tmp, len + 8, "%s.part", path);
    w->f = fopen(w->tmp, "wb");
    if (!w->f) {
        sph_error("cannot write %s: %s", w->tmp, strerror(errno));
        free(w->path), free(w->tmp);
        return -1;
    }
    errno = 0;
    w->hash = FNV_START;
    put_raw(w, MAGIC, sizeof MAGIC);
    put_u32(w, VERSION);
    put_u32(w, 0x01020304u);
    put_u32(w, (uint32_t)sizeof(double));
    put_u32(w, (uint32_t)sizeof(long));
    return 0;
}

/* Bytes to the next multiple of 8 after x. */
static size_t pad(size_t x) { return (8 - x % 8) % 8; }

void sph_ckpt_put(sph_ckpt_writer *w, const char *name, const void *data, size_t bytes)
{
    static const char zeros[8] = {0};
    const uint64_t n = bytes;
    const size_t nl = strlen(name);
    put_u32(w, (uint32_t)nl);
    put_raw(w, name, nl);
    put_raw(w, zeros, pad(sizeof(uint32_t) + nl));
    put_raw(w, &n, sizeof n);
    put_raw(w, data, bytes);
    put_raw(w, zeros, pad(bytes));
}

int sph_ckpt_commit(sph_ckpt_writer *w)
{
    const uint64_t hash = w->hash; /* (of every byte before the "end" record) */
    sph_ckpt_put(w, "end", &hash, sizeof hash);
    if (fflush(w->f) && !w->bad)
        w->bad = errno ? errno : EIO;
    if (fclose(w->f) && !w->bad)
        w->bad = errno ? errno : EIO;
    if (!w->bad && rename(w->tmp, w->path))
        w->bad = errno ? errno : EIO;
    if (w->bad) {
        sph_error("cannot write %s: %s", w->tmp, strerror(w->bad));
        remove(w->tmp);
    }
    free(w->path), free(w->tmp);
    return w->bad ? -1 : 0;
}

/* ------------------------------------------------------------------ reading */

static int corrupt(const char *path, const char *why)
{
    sph_error("cannot restart from %s: %s", path, why);
    return -1;
}

/* The record at offset *at (a multiple of 8): its name and bytes, *at moved past it; -1 when
 * it does not fit in the file. */
typedef struct {
    const unsigned char *name, *data;
    size_t nl, bytes;
} record;

static int next_record(const sph_ckpt *c, size_t *at, record *r)
{
    uint32_t nl;
    uint64_t nb;
    if (c->len - *at < sizeof nl)
        return -1;
    memcpy(&nl, c->buf + *at, sizeof nl);
    const size_t head = sizeof nl + (size_t)nl + pad(sizeof nl + (size_t)nl);
    if (c->len - *at < head + sizeof nb)
        return -1;
    r->name = c->buf + *at + sizeof nl, r->nl = nl;
    memcpy(&nb, c->buf + *at + head, sizeof nb);
    *at += head + sizeof nb;
    if (c->len - *at < nb || c->len - *at - nb < pad((size_t)nb))
        return -1;
    r->data = c->buf + *at, r->bytes = (size_t)nb;
    *at += (size_t)nb + pad((size_t)nb);
    return 0;
}

static int is_end(const record *r) { return r->nl == 3 && !memcmp(r->name, "end", 3); }

/* Walks the records: 0 when they are well formed and end with "end" at the file's end, whose
 * hash is that of the bytes before it (with check_hash; reading every byte of the file). */
static int walk(const sph_ckpt *c, int check_hash)
{
    size_t at = sizeof MAGIC + 4 * sizeof(uint32_t), start = at;
    record r;
    while (!next_record(c, &at, &r)) {
        if (!is_end(&r)) {
            start = at;
            continue;
        }
        uint64_t hash;
        if (at != c->len || r.bytes != sizeof hash)
            return -1;
        memcpy(&hash, r.data, sizeof hash);
        return !check_hash || hash == fnv(FNV_START, c->buf, start) ? 0 : -1;
    }
    return -1;
}

int sph_ckpt_read(sph_ckpt *c, const char *path, int check_hash)
{
    memset(c, 0, sizeof *c);
    c->path = path;
    if (sph_not_regular_file(path))
        return corrupt(path, "not a regular file");
    const int fd = open(path, O_RDONLY);
    if (fd < 0)
        return corrupt(path, strerror(errno));
    struct stat st;
    const off_t len = fstat(fd, &st) == 0 ? st.st_size : -1;
    void *map = len > 0 ? mmap(NULL, (size_t)len, PROT_READ, MAP_PRIVATE, fd, 0) : MAP_FAILED;
    close(fd);
    if (map == MAP_FAILED)
        return corrupt(path, len <= 0 ? "the file is empty" : "it could not be read");
    c->buf = map; /* (page-aligned: every record's 8-aligned offset reads as doubles) */
    c->len = (size_t)len;
    uint32_t head[4];
    if (c->len < sizeof MAGIC + sizeof head || memcmp(c->buf, MAGIC, sizeof MAGIC)) {
        sph_ckpt_free(c);
        return corrupt(path, "not a checkpoint of an sphc program");
    }
    memcpy(head, c->buf + sizeof MAGIC, sizeof head);
    const char *why = head[0] != VERSION ? "it was written by another version of sphc"
                      : head[1] != 0x01020304u || head[2] != sizeof(double) ||
                              head[3] != sizeof(long)
                          ? "it was written on a machine of another kind (byte order or sizes)"
                      : walk(c, check_hash) ? "it is cut short or damaged"
                                : NULL;
    if (why) {
        sph_ckpt_free(c);
        return corrupt(path, why);
    }
    return 0;
}

const void *sph_ckpt_find(const sph_ckpt *c, const char *name, size_t *bytes)
{
    size_t at = sizeof MAGIC + 4 * sizeof(uint32_t);
    const size_t want = strlen(name);
    record r;
    while (!next_record(c, &at, &r) && !is_end(&r)) /* (walk has checked them) */
        if (r.nl == want && !memcmp(r.name, name, want)) {
            *bytes = r.bytes;
            return r.data; /* (8-aligned: the mapping is page-aligned, the offset a multiple of 8) */
        }
    return NULL;
}

int sph_ckpt_take(const sph_ckpt *c, const char *name, void *data, size_t bytes)
{
    size_t got;
    const void *p = sph_ckpt_find(c, name, &got);
    if (!p || got != bytes) {
        sph_error("cannot restart from %s: %s '%s'%s (is it a checkpoint of this model?)",
                  c->path, p ? "the size of" : "no record", name, p ? " differs" : "");
        return -1;
    }
    if (bytes)
        memcpy(data, p, bytes);
    return 0;
}

void sph_ckpt_free(sph_ckpt *c)
{
    if (c->buf)
        munmap((void *)c->buf, c->len);
    c->buf = NULL;
    c->len = 0;
}

/* ------------------------------------------------------------------ the simulation */

/* ------------------------------------------------------------------ bodies by global id
 * A body's particles are stored in pieces, one per process of the run that wrote it (one
 * piece on one process): the global ids of the piece's particles (partition.h: from their
 * lattice coordinates, the same on any number of processes) and their state arrays in the
 * same order.  A run resumed on any number of processes takes each of its own particles'
 * state from whichever piece holds its id. */

/* The global ids of body b's own particles (malloc'd): its own on many processes, from the
 * body's lattice on one.  NULL when memory runs out or the body has no lattice. */
static int64_t *own_ids(const sph_body *b)
{
    int64_t *id = malloc(((size_t)b->nown + 1) * sizeof *id);
    if (!id || b->gid) {
        if (id)
            memcpy(id, b->gid, (size_t)b->nown * sizeof *id);
        return id;
    }
    sph_lattice L;
    if (sph_fill_lattice(&b->desc->region, b->dim, b->dx, b->desc->y_plane, &L) != 1) {
        free(id);
        return NULL;
    }
    for (int i = 0; i < b->nown; i++)
        id[i] = sph_lattice_id(&L, b->X + (size_t)i * b->dim);
    return id;
}

/* What identifies body b's particles on all processes: count, dimension, state values, and
 * a hash of the reference positions that does not depend on their order (the XOR of each
 * particle's).  Collective. */
static void body_shape(const sph_body *b, uint64_t shape[4])
{
    uint64_t h = 0;
    for (int i = 0; i < b->nown; i++)
        h ^= fnv(FNV_START, b->X + (size_t)i * b->dim, (size_t)b->dim * sizeof(double));
    const sph_par *par = b->par;
    uint64_t *all = malloc(((size_t)par->size + 1) * sizeof *all);
    if (all) {
        par->allgather(&h, all, sizeof h);
        for (int q = 0; q < par->size; q++)
            h = q ? h ^ all[q] : all[q];
    }
    free(all);
    double n = b->nown;
    par->sum(&n, 1);
    shape[0] = (uint64_t)n;
    shape[1] = (uint64_t)b->dim;
    shape[2] = (uint64_t)b->desc->nstate;
    shape[3] = h;
}

static void key(char *out, size_t len, int body, const char *what)
{
    snprintf(out, len, "body.%d.%s", body, what);
}

static void piece_key(char *out, size_t len, int body, int piece, const char *what)
{
    snprintf(out, len, "body.%d.piece.%d.%s", body, piece, what);
}

/* Where process 0 writes the pieces it gathers. */
typedef struct {
    sph_ckpt_writer *w;
    int body, na;
    const sph_state_array *arr;
    size_t per[SPH_STATE_ARRAYS]; /* bytes per particle of each array */
} piece_writer;

/* A piece as gathered: u64 count, the ids, each array's bytes. */
static void write_piece(void *ctx, int from, const void *data, size_t bytes)
{
    const piece_writer *pw = ctx;
    char name[96];
    uint64_t n;
    memcpy(&n, data, sizeof n);
    const unsigned char *at = (const unsigned char *)data + sizeof n;
    piece_key(name, sizeof name, pw->body, from, "gid");
    sph_ckpt_put(pw->w, name, at, n * sizeof(int64_t));
    at += n * sizeof(int64_t);
    for (int k = 0; k < pw->na; k++) {
        piece_key(name, sizeof name, pw->body, from, pw->arr[k].name);
        sph_ckpt_put(pw->w, name, at, n * pw->per[k]);
        at += n * pw->per[k];
    }
    if ((size_t)(at - (const unsigned char *)data) != bytes && !pw->w->bad)
        pw->w->bad = EIO;
}

/* Body b's saved step sums (scene/step_sums.h) as the scene's, in the table's order: the
 * largest or smallest over the processes, or their total (collective); how many. */
static int saved_sums(const sph_body *b, double sums[SPH_STEP_NSUMS])
{
    double x[SPH_STEP_NSUMS], most[SPH_STEP_NSUMS], add[SPH_STEP_NSUMS];
    int nmost = 0, nadd = 0, n = 0;
    sph_step_sums_get(b, x);
    for (int k = 0; k < SPH_STEP_NSUMS; k++) {
        const int r = sph_step_sum_reduce(k);
        if (!sph_step_sum_saved(k))
            continue;
        if (r == SPH_REDUCE_ADD)
            add[nadd++] = x[k];
        else
            most[nmost++] = r == SPH_REDUCE_MIN ? -x[k] : x[k]; /* (minima as maxima) */
    }
    if (nmost) /* (the same calls on every process: the table decides) */
        b->par->max(most, nmost);
    if (nadd)
        b->par->sum(add, nadd);
    nmost = nadd = 0;
    for (int k = 0; k < SPH_STEP_NSUMS; k++) {
        const int r = sph_step_sum_reduce(k);
        if (!sph_step_sum_saved(k))
            continue;
        sums[n++] = r == SPH_REDUCE_ADD ? add[nadd++]
                    : r == SPH_REDUCE_MIN ? -most[nmost++]
                                          : most[nmost++];
    }
    return n;
}

/* Body i's records: shape, sums, and its pieces (collective; w only on process 0). */
static void checkpoint_body(sph_ckpt_writer *w, sph_body *b, int i)
{
    char name[96];
    const sph_par *par = b->par;
    uint64_t shape[4];
    body_shape(b, shape);
    double sums[SPH_STEP_NSUMS];
    const int nsums = saved_sums(b, sums);
    piece_writer pw = {w, i, 0, NULL, {0}};
    sph_state_array arr[SPH_STATE_ARRAYS];
    pw.na = sph_body_state_arrays(b, b->desc->nstate, arr);
    pw.arr = arr;
    size_t bytes = sizeof(uint64_t) + (size_t)b->nown * sizeof(int64_t);
    for (int k = 0; k < pw.na; k++) {
        pw.per[k] = b->n ? arr[k].bytes / (size_t)b->n : 0;
        bytes += (size_t)b->nown * pw.per[k];
    }
    int64_t *id = own_ids(b);
    unsigned char *block = id ? malloc(bytes) : NULL;
    uint64_t n = block ? (uint64_t)b->nown : 0; /* (out of memory: an empty piece, refused) */
    if (block) {
        unsigned char *at = block;
        memcpy(at, &n, sizeof n), at += sizeof n;
        memcpy(at, id, (size_t)n * sizeof *id), at += (size_t)n * sizeof *id;
        for (int k = 0; k < pw.na; k++) /* (own particles first in every array) */
            memcpy(at, arr[k].data, (size_t)n * pw.per[k]), at += (size_t)n * pw.per[k];
    }
    if (w) {
        key(name, sizeof name, i, "shape");
        sph_ckpt_put(w, name, shape, sizeof shape);
        key(name, sizeof name, i, "sums");
        sph_ckpt_put(w, name, sums, (size_t)nsums * sizeof *sums);
        const uint64_t pieces = (uint64_t)par->size;
        key(name, sizeof name, i, "pieces");
        sph_ckpt_put(w, name, &pieces, sizeof pieces);
    }
    par->gather0(block ? (const void *)block : (const void *)&n, block ? bytes : sizeof n,
                 write_piece, &pw);
    if (w && (!block || !id) && !w->bad)
        w->bad = ENOMEM;
    free(block), free(id);
}

void sph_sim_checkpoint(sph_ckpt_writer *w, const sph_sim *s)
{
    if (w) {
        sph_ckpt_put(w, "model", s->m->name, strlen(s->m->name));
        const double clock[3] = {s->t, s->dt, s->dt_factor};
        sph_ckpt_put(w, "sim.clock", clock, sizeof clock);
        sph_ckpt_put(w, "sim.step", &s->step, sizeof s->step);
    }
    for (int i = 0; i < s->nbodies; i++)
        checkpoint_body(w, &s->bodies[i], i);
    double sums[4];
    const double *x0;
    size_t nx0;
    if (sph_contact_checkpoint(s, sums, &x0, &nx0)) {
        s->par->sum(sums, 2); /* (the energies: each process's share, as totals) */
        if (w) {
            sph_ckpt_put(w, "contact.sums", sums, sizeof sums);
            sph_ckpt_put(w, "contact.x0", x0, nx0 * sizeof *x0);
        }
    }
}

/* Body i's particles against the checkpoint's: 0 when they are the same. */
static int same_particles(const sph_ckpt *c, const sph_body *b, int i)
{
    char name[96];
    uint64_t here[4], there[4];
    size_t bytes;
    key(name, sizeof name, i, "shape");
    const void *p = sph_ckpt_find(c, name, &bytes);
    body_shape(b, here);
    if (!p || bytes != sizeof there) {
        sph_error("cannot restart from %s: it has no body %d ('%s'), or is of another model",
                  c->path, i + 1, b->desc->name);
        return -1;
    }
    memcpy(there, p, sizeof there);
    if (here[0] != there[0] || here[1] != there[1] || here[2] != there[2]) {
        sph_error("cannot restart from %s: body '%s' has %llu particles in %lluD with %llu state "
                  "values there, %llu in %lluD with %llu here (is it a checkpoint of this model?)",
                  c->path, b->desc->name, (unsigned long long)there[0],
                  (unsigned long long)there[1], (unsigned long long)there[2],
                  (unsigned long long)here[0], (unsigned long long)here[1],
                  (unsigned long long)here[2]);
        return -1;
    }
    if (here[3] != there[3]) {
        sph_error("cannot restart from %s: body '%s' has its %llu particles in other places "
                  "there (is it a checkpoint of this model, at this resolution?)",
                  c->path, b->desc->name, (unsigned long long)here[0]);
        return -1;
    }
    return 0;
}

/* A particle of body b held twice by the checkpoint's pieces (the second time in piece q):
 * a damaged checkpoint, refused. */
static int held_twice(const sph_ckpt *c, const sph_body *b, int64_t id, uint64_t q)
{
    sph_error("cannot restart from %s: it holds particle %lld of body '%s' twice (again in "
              "piece %llu): it is damaged", c->path, (long long)id, b->desc->name,
              (unsigned long long)q);
    return -1;
}

/* The state of body b's own particles from the checkpoint's pieces; seen[k] marks own
 * particle k found (each must be found once: a second time is refused). */
static int restore_pieces(const sph_ckpt *c, sph_body *b, int i, const sph_id_index *own,
                          unsigned char *seen)
{
    char name[96];
    size_t bytes;
    uint64_t pieces = 0;
    key(name, sizeof name, i, "pieces");
    if (sph_ckpt_take(c, name, &pieces, sizeof pieces))
        return -1;
    sph_state_array arr[SPH_STATE_ARRAYS];
    const int na = sph_body_state_arrays(b, b->desc->nstate, arr);
    for (uint64_t q = 0; q < pieces; q++) {
        piece_key(name, sizeof name, i, (int)q, "gid");
        const int64_t *gid = sph_ckpt_find(c, name, &bytes);
        const size_t n = bytes / sizeof *gid;
        const unsigned char *data[SPH_STATE_ARRAYS];
        size_t per[SPH_STATE_ARRAYS];
        int bad = !gid;
        for (int k = 0; k < na && !bad; k++) {
            per[k] = b->n ? arr[k].bytes / (size_t)b->n : 0;
            piece_key(name, sizeof name, i, (int)q, arr[k].name);
            data[k] = sph_ckpt_find(c, name, &bytes);
            bad = !data[k] || bytes != n * per[k];
        }
        if (bad) {
            sph_error("cannot restart from %s: piece %llu of body '%s' is missing or damaged "
                      "(is it a checkpoint of this model?)", c->path, (unsigned long long)q,
                      b->desc->name);
            return -1;
        }
        for (size_t j = 0; j < n; j++) {
            const int at = sph_id_find(own, b->nown, gid[j]);
            if (at < 0)
                continue; /* (another process's particle) */
            if (seen[at])
                return held_twice(c, b, gid[j], q);
            seen[at] = 1;
            for (int k = 0; k < na; k++)
                memcpy((unsigned char *)arr[k].data + (size_t)at * per[k],
                       data[k] + j * per[k], per[k]);
        }
    }
    return 0;
}

/* Body i's saved step sums from its record (saved_sums' order): the scene's maxima and minima
 * on every process, the totals of sums on process 0 alone, so that they add up again; the
 * rows not saved keep their initial values.  A record of another length is of a program
 * whose table of step sums differs. */
static int restore_sums(const sph_ckpt *c, sph_body *b, int i)
{
    char name[96];
    double x[SPH_STEP_NSUMS], sums[SPH_STEP_NSUMS];
    size_t bytes;
    int n = 0;
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        n += sph_step_sum_saved(k);
    key(name, sizeof name, i, "sums");
    const void *data = sph_ckpt_find(c, name, &bytes);
    if (data && bytes != (size_t)n * sizeof(double)) {
        sph_error("cannot restart from %s: it holds %zu sums of a step of body '%s' where this "
                  "program keeps %d: it was written by another version of sphc", c->path,
                  bytes / sizeof(double), b->desc->name, n);
        return -1;
    }
    if (sph_ckpt_take(c, name, sums, (size_t)n * sizeof *sums))
        return -1;
    const int first = b->par->rank == 0;
    sph_step_sums_get(b, x);
    n = 0;
    for (int k = 0; k < SPH_STEP_NSUMS; k++)
        if (sph_step_sum_saved(k)) {
            x[k] = sph_step_sum_reduce(k) != SPH_REDUCE_ADD || first ? sums[n] : 0;
            n++;
        }
    sph_step_sums_set(b, x);
    return 0;
}

/* Own particle k of body b (id[k]), the first that no piece of the checkpoint holds: a
 * damaged checkpoint, refused, with how many are missing. */
static int not_held(const sph_ckpt *c, const sph_body *b, const int64_t *id,
                    const unsigned char *seen, int k)
{
    long missing = 0;
    for (int q = k; q < b->nown; q++)
        missing += !seen[q];
    char at[96];
    sph_reference_position(b, k, at, sizeof at);
    sph_error("cannot restart from %s: no piece of it holds particle %lld of body '%s' "
              "(reference position %s; %ld missing in all): it is damaged", c->path,
              (long long)id[k], b->desc->name, at, missing);
    return -1;
}

static int restore_body(const sph_ckpt *c, sph_body *b, int i)
{
    if (same_particles(c, b, i) || restore_sums(c, b, i))
        return -1;
    int64_t *id = own_ids(b);
    sph_id_index *own = id ? sph_id_sort(id, b->nown) : NULL;
    unsigned char *seen = calloc((size_t)b->nown + 1, 1);
    if (!own || !seen) {
        free(id), free(own), free(seen);
        sph_error("out of memory to restart from %s", c->path);
        return -1;
    }
    int bad = restore_pieces(c, b, i, own, seen);
    for (int k = 0; k < b->nown && !bad; k++)
        if (!seen[k])
            bad = not_held(c, b, id, seen, k);
    free(id), free(own), free(seen);
    return bad;
}

int sph_sim_restore(const sph_ckpt *c, sph_sim *s)
{
    size_t bytes;
    const char *model = sph_ckpt_find(c, "model", &bytes);
    if (!model || bytes != strlen(s->m->name) || memcmp(model, s->m->name, bytes)) {
        sph_error("cannot restart from %s: it is a checkpoint of %s%.*s%s, not of '%s'", c->path,
                  model ? "the model '" : "another model", model ? (int)bytes : 0,
                  model ? model : "", model ? "'" : "", s->m->name);
        return -1;
    }
    double clock[3];
    if (sph_ckpt_take(c, "sim.clock", clock, sizeof clock) ||
        sph_ckpt_take(c, "sim.step", &s->step, sizeof s->step))
        return -1;
    s->t = clock[0], s->dt = clock[1], s->dt_factor = clock[2];
    for (int i = 0; i < s->nbodies; i++) /* (a failure of one process's stops all) */
        if (s->par->agree(restore_body(c, &s->bodies[i], i)))
            return -1;
    if (!s->m->contact)
        return 0;
    double sums[4];
    const double *x0 = sph_ckpt_find(c, "contact.x0", &bytes);
    if (sph_ckpt_take(c, "contact.sums", sums, sizeof sums))
        return -1;
    if (s->par->rank != 0) /* (the energies' totals: process 0's share, so they add up) */
        sums[0] = sums[1] = 0;
    return sph_contact_restore(s, sums, x0, bytes / sizeof(double));
}
