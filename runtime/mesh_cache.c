/* mesh_cache.c — each surface file loaded once per run (mesh.h).
 *
 * Shapes name their surface by file; region.c asks for it at every point it tests, from
 * many threads.  The table is only appended to: a new entry is written completely, under a
 * lock, before the count that makes it visible is published (an atomic store), so readers
 * scan the published entries without locking. */
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "sphrt.h"

enum { MAX_MESHES = 256 };

static struct {
    const char *file;
    sph_mesh mesh;
} table[MAX_MESHES];
static atomic_int published;

static const sph_mesh *find(const char *file, int n)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(table[i].file, file))
            return &table[i].mesh;
    return NULL;
}

const sph_mesh *sph_mesh_get(const char *file)
{
    const sph_mesh *m = find(file, atomic_load(&published));
    if (m)
        return m;
#pragma omp critical(sph_mesh_cache)
    {
        int n = atomic_load(&published);
        m = find(file, n);
        if (!m) {
            char err[1024];
            if (n == MAX_MESHES) {
                sph_error("more than %d surface files", MAX_MESHES);
                exit(SPH_EXIT_SETUP);
            }
            if (sph_mesh_load(file, &table[n].mesh, err, sizeof err)) {
                sph_error("%s", err);
                exit(SPH_EXIT_SETUP);
            }
            sph_mesh_index(&table[n].mesh);
            table[n].file = strdup(file);
            m = &table[n].mesh;
            atomic_store(&published, n + 1);
        }
    }
    return m;
}
