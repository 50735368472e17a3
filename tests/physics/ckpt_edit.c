/* ckpt_edit.c — damages a checkpoint (runtime/io/checkpoint.c's format) the way a faulty
 * writer could, and gives it a valid hash again, so that only the checks of its contents can
 * refuse it:
 *
 *     ckpt_edit FILE RECORD TO FROM
 *     ckpt_edit FILE RECORD TO =VALUE
 *
 * copies 8-byte element FROM of record RECORD over its element TO (on a record of global
 * ids, "body.0.piece.0.gid": the particle of id[FROM] held twice, that of id[TO] by none),
 * or writes the 64-bit integer VALUE there (an id no particle has: id[TO] held by none), then
 * writes the hash of the "end" record anew.  Exit 0, or 1 with a message. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static size_t pad(size_t x) { return (8 - x % 8) % 8; }

static uint64_t fnv(const unsigned char *p, size_t n)
{
    uint64_t h = 1469598103934665603ull;
    for (size_t k = 0; k < n; k++)
        h = (h ^ p[k]) * 1099511628211ull;
    return h;
}

static int fail(const char *what, const char *file)
{
    fprintf(stderr, "ckpt_edit: %s: %s\n", file, what);
    return 1;
}

int main(int argc, char **argv)
{
    if (argc != 5)
        return fail("usage: ckpt_edit FILE RECORD TO FROM|=VALUE", "ckpt_edit");
    const char *path = argv[1], *want = argv[2];
    const size_t to = strtoul(argv[3], NULL, 10);
    const int set = argv[4][0] == '=';
    const size_t from = set ? to : strtoul(argv[4], NULL, 10);
    const int64_t value = set ? strtoll(argv[4] + 1, NULL, 10) : 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return fail("cannot read", path);
    fseek(f, 0, SEEK_END);
    const long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *buf = malloc(len > 0 ? (size_t)len : 1);
    if (!buf || len <= 0 || fread(buf, 1, (size_t)len, f) != (size_t)len)
        return fail("cannot read", path);
    fclose(f);
    size_t at = 8 + 4 * sizeof(uint32_t), edited = 0;
    for (;;) {
        uint32_t nl;
        uint64_t nb;
        if ((size_t)len - at < sizeof nl)
            return fail("no end record", path);
        const size_t start = at;
        memcpy(&nl, buf + at, sizeof nl);
        const char *name = (const char *)buf + at + sizeof nl;
        at += sizeof nl + nl + pad(sizeof nl + nl);
        if ((size_t)len - at < sizeof nb)
            return fail("a record cut short", path);
        memcpy(&nb, buf + at, sizeof nb);
        at += sizeof nb;
        if ((size_t)len - at < nb)
            return fail("a record cut short", path);
        unsigned char *data = buf + at;
        if (nl == 3 && !memcmp(name, "end", 3)) {
            if (!edited)
                return fail("no such record, or too short for its elements", path);
            const uint64_t h = fnv(buf, start);
            memcpy(data, &h, sizeof h);
            break;
        }
        if (nl == strlen(want) && !memcmp(name, want, nl) && to * 8 < nb && from * 8 < nb) {
            memcpy(data + to * 8, set ? (const void *)&value : data + from * 8, 8);
            edited = 1;
        }
        at += nb + pad(nb);
    }
    f = fopen(path, "wb");
    if (!f || fwrite(buf, 1, (size_t)len, f) != (size_t)len || fclose(f))
        return fail("cannot write", path);
    free(buf);
    return 0;
}
