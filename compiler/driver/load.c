/* load.c — the first stage: a model (.sph, through the parser) or a SoliDualSPHysics case
 * (.xml, through the importer) and every module it imports, as one syntax tree. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "util/diag.h"
#include "driver.h"
#include "xml/xml.h"

static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static int already_loaded(char **loaded, int n, const char *name)
{
    for (int i = 0; i < n; i++)
        if (!strcmp(loaded[i], name))
            return 1;
    return 0;
}

static int import_module(const Item *it, const char *model_dir, const Paths *paths, Program *prog)
{
    char path[8192];
    snprintf(path, sizeof path, "%s/%s.sph", model_dir, it->name);
    if (!exists(path))
        snprintf(path, sizeof path, "%s/%s.sph", paths->stdlib, it->name);
    if (!exists(path)) {
        diag_error(it->loc, "cannot find module '%s' (looked beside the model and in %s)",
                   it->name, paths->stdlib);
        return 1;
    }
    return parse_file(strdup(path), prog);
}

int load_program(const char *path, const Paths *paths, const XmlOptions *xml, Program *prog)
{
    prog->file = path;
    int errors = xml_is_case_file(path) ? xml_import(path, xml, prog) : parse_file(path, prog);
    char *dir = strdup(path);
    char *slash = strrchr(dir, '/');
    if (slash)
        *slash = 0;
    else
        strcpy(dir, ".");
    char **loaded = NULL;
    int nloaded = 0;
    /* Imported files may import more: prog->n grows while we scan.  An XML case imports
     * the material laws it uses, which are found like any module. */
    for (int i = 0; i < prog->n && !errors; i++) {
        const Item *it = &prog->items[i];
        if (it->kind != IT_IMPORT || already_loaded(loaded, nloaded, it->name))
            continue;
        loaded = realloc(loaded, (size_t)(nloaded + 1) * sizeof *loaded);
        loaded[nloaded++] = it->name;
        Item copy = *it; /* parse_file may move prog->items */
        errors += import_module(&copy, dir, paths, prog);
    }
    free(loaded);
    free(dir);
    return errors || diag_error_count() ? -1 : 0;
}
