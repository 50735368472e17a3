/* compat.c — the output files of SoliDualSPHysics (DSPartVTK) beside the run's own, for
 * models imported from XML case files.  Same names, tab-separated columns and header
 * lines; the values are those of energies.csv and measure_*.csv (%.10g):
 *
 *   DeformStruc_Energies.csv           Time, mkbound_<mk>_STRAIN_ENERGY,
 *                                      mkbound_<mk>_KINETIC_ENERGY for every body
 *   MeasuringPlData_MK<mk>_PL<k>.csv   Time, Av.Disp.x, [Av.Disp.y,] Av.Disp.z,
 *                                      Av.Force.x, [Av.Force.y,] Av.Force.z
 *
 * k counts the planes of a body from 1; in 2D the y columns are left out.  Av.Force holds
 * the run's measured force (the total force on the plane's particles, sum m a). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "compat.h"
#include "csv.h"
#include "scene/model.h"

int sph_compat_mk(const sph_model *m, int i)
{
    const char *name = m->bodies[i].name;
    int mk, used = 0;
    if (sscanf(name, "mk%d%n", &mk, &used) == 1 && name[used] == '\0' && mk >= 0)
        return mk;
    return i + 1;
}

static int open_energies(sph_compat *c, const sph_model *m, const char *dir)
{
    int ncol = 1 + 3 * m->nbodies, q = 1;
    char **cols = calloc((size_t)ncol, sizeof *cols), path[4096];
    cols[0] = strdup("Time");
    for (int i = 0; i < m->nbodies; i++) {
        static const char *const kinds[] = {"STRAIN", "KINETIC", "FRACTURE"};
        for (int k = 0; k < (c->fracture[i] ? 3 : 2); k++) {
            char col[96];
            snprintf(col, sizeof col, "mkbound_%d_%s_ENERGY", sph_compat_mk(m, i), kinds[k]);
            cols[q++] = strdup(col);
        }
    }
    ncol = q;
    snprintf(path, sizeof path, "%s/DeformStruc_Energies.csv", dir);
    int bad = sph_csv_open_sep(&c->energies, path, (const char *const *)cols, ncol, '\t');
    for (int k = 0; k < ncol; k++)
        free(cols[k]);
    free(cols);
    return bad;
}

static int open_plane(sph_compat *c, const char *dir, int mk, int k, int q)
{
    static const char *const cols3[] = {"Time",       "Av.Disp.x",  "Av.Disp.y", "Av.Disp.z",
                                        "Av.Force.x", "Av.Force.y", "Av.Force.z"};
    static const char *const cols2[] = {"Time", "Av.Disp.x", "Av.Disp.z", "Av.Force.x",
                                        "Av.Force.z"};
    char path[4096];
    snprintf(path, sizeof path, "%s/MeasuringPlData_MK%d_PL%d.csv", dir, mk, k + 1);
    return c->dim == 2 ? sph_csv_open_sep(&c->planes[q], path, cols2, 5, '\t')
                       : sph_csv_open_sep(&c->planes[q], path, cols3, 7, '\t');
}

int sph_compat_open(sph_compat *c, const sph_model *m, const char *dir)
{
    memset(c, 0, sizeof *c);
    c->dim = m->dim;
    c->nbodies = m->nbodies;
    c->fracture = calloc((size_t)m->nbodies + 1, 1);
    for (int i = 0; i < m->nbodies; i++) {
        c->nplanes += m->bodies[i].nmeasures;
        c->fracture[i] = m->bodies[i].fracture != NULL;
    }
    c->planes = calloc((size_t)c->nplanes + 1, sizeof *c->planes);
    int bad = open_energies(c, m, dir) != 0, q = 0;
    for (int i = 0; i < m->nbodies; i++)
        for (int k = 0; k < m->bodies[i].nmeasures; k++)
            bad |= open_plane(c, dir, sph_compat_mk(m, i), k, q++) != 0;
    return bad ? -1 : 0;
}

int sph_compat_energies(sph_compat *c, const double *e)
{
    double *row = calloc(1 + 3 * (size_t)c->nbodies, sizeof(double));
    int q = 0, f = 1 + 2 * c->nbodies;
    row[q++] = e[0];
    for (int i = 0; i < c->nbodies; i++) {
        row[q++] = e[1 + 2 * i];
        row[q++] = e[2 + 2 * i];
        if (c->fracture[i])
            row[q++] = e[f++];
    }
    int bad = sph_csv_row(&c->energies, row);
    free(row);
    return bad;
}

int sph_compat_plane(sph_compat *c, int q, const double r[7])
{
    double row[7];
    int n = 0;
    row[n++] = r[0];
    for (int a = 0; a < 6; a++) /* ux uy uz fx fy fz; 2D: without the y components */
        if (c->dim == 3 || a % 3 != 1)
            row[n++] = r[1 + a];
    return sph_csv_row(&c->planes[q], row);
}

void sph_compat_close(sph_compat *c)
{
    sph_csv_close(&c->energies);
    for (int q = 0; q < c->nplanes; q++)
        sph_csv_close(&c->planes[q]);
    free(c->planes);
    free(c->fracture);
    c->fracture = NULL;
    c->planes = NULL;
    c->nplanes = 0;
}
