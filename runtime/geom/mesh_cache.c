/* mesh_cache.c — each surface loaded or built once per run (mesh.h).
 *
 * Shapes name their surface by file and the address of the map that moves it (in the
 * generated program; NULL for none), or (prisms and pyramids) by their table of corners;
 * region.c asks for it at every point it tests, from many threads.
 * The table is only appended to: a new entry is written completely, under a lock, before
 * the count that makes it visible is published (an atomic store), so readers scan the
 * published entries without locking. */
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mesh.h"
#include "core/exit_codes.h"
#include "core/message.h"

static struct {
    const char *file;  /* a surface file, or NULL */
    const double *pts; /* a solid's corners, or a file's map (the program's own tables) */
    sph_mesh mesh;
} table[SPH_MESH_MAX];
static atomic_int published;

static const sph_mesh *find(const char *file, const double *pts, int n)
{
    for (int i = 0; i < n; i++)
        if (table[i].pts == pts && (file ? table[i].file && !strcmp(table[i].file, file)
                                         : !table[i].file))
            return &table[i].mesh;
    return NULL;
}

/* The surface of file moved by the map pts, or of the solid of npts corners pts (file
 * NULL). */
static const sph_mesh *get(const char *file, sph_solid_kind kind, const double *pts, int npts)
{
    const sph_mesh *m = find(file, pts, atomic_load(&published));
    if (m)
        return m;
#pragma omp critical(sph_mesh_cache)
    {
        int n = atomic_load(&published);
        m = find(file, pts, n);
        if (!m) {
            char err[1024];
            if (n == SPH_MESH_MAX) {
                sph_error("more than %d surface files and solids", SPH_MESH_MAX);
                exit(SPH_EXIT_SETUP);
            }
            if (file ? sph_mesh_load_moved(file, pts, &table[n].mesh, err, sizeof err)
                     : sph_mesh_solid(kind, pts, npts, &table[n].mesh, err, sizeof err)) {
                sph_error("%s", err);
                exit(SPH_EXIT_SETUP);
            }
            sph_mesh_index(&table[n].mesh);
            table[n].file = file ? strdup(file) : NULL;
            table[n].pts = pts;
            m = &table[n].mesh;
            atomic_store(&published, n + 1);
        }
    }
    return m;
}

const sph_mesh *sph_mesh_get(const char *file, const double *xf)
{
    return get(file, SPH_SOLID_PRISM, xf, 0);
}

const sph_mesh *sph_mesh_get_solid(sph_solid_kind kind, const double *pts, int npts)
{
    return get(NULL, kind, pts, npts);
}
