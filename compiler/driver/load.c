/* load.c — the first stage: a model (.sph, through the parser) or a SoliDualSPHysics case
 * (.xml, through the importer) and every module it imports, as one syntax tree. */
#define _XOPEN_SOURCE 700
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

/* A file of the program: the model, or a module an import found, with the file whose import
 * found it (-1: the model) and its real path, which tells a file found twice. */
typedef struct {
    char *path;     /* as the locations name it */
    char *real;     /* realpath, or the path */
    int importer;
} Loaded;

typedef struct {
    Loaded *files;
    int n;
} LoadedFiles;

static void add_loaded(LoadedFiles *l, const char *path, int importer)
{
    l->files = realloc(l->files, (size_t)(l->n + 1) * sizeof *l->files);
    char *real = realpath(path, NULL);
    l->files[l->n++] = (Loaded){strdup(path), real ? real : strdup(path), importer};
}

static void free_loaded(LoadedFiles *l)
{
    for (int i = 0; i < l->n; i++) {
        free(l->files[i].path);
        free(l->files[i].real);
    }
    free(l->files);
}

/* The loaded file named `path` (by its real path when real is set), or -1. */
static int find_loaded(const LoadedFiles *l, const char *path, int real)
{
    for (int i = 0; i < l->n; i++)
        if (!strcmp(real ? l->files[i].real : l->files[i].path, path))
            return i;
    return -1;
}

/* File `to` (imported by file `from`) is `from` or one of the files whose imports led to it:
 * the chain from `to` down to `from` and back, "a.sph -> b.sph -> a.sph". */
static void cycle_chain(const LoadedFiles *l, int from, int to, char *buf, size_t size)
{
    int chain[64], n = 0;
    for (int k = from; k >= 0 && n < 64; k = l->files[k].importer) {
        chain[n++] = k;
        if (k == to)
            break;
    }
    size_t at = 0;
    buf[0] = 0;
    for (int i = n - 1; i >= 0 && at < size; i--)
        at += (size_t)snprintf(buf + at, size - at, "%s -> ",
                               source_basename(l->files[chain[i]].path));
    if (at < size)
        snprintf(buf + at, size - at, "%s", source_basename(l->files[to].path));
}

/* Whether `to` is `from` or an ancestor of it in the import chain. */
static int imported_above(const LoadedFiles *l, int from, int to)
{
    for (int k = from; k >= 0; k = l->files[k].importer)
        if (k == to)
            return 1;
    return 0;
}

/* The module an import names, in path: beside the model, else in the standard library.
 * Returns 0, or -1 after an error when neither has it. */
static int module_path(const Item *it, const char *model_dir, const Paths *paths,
                       char *path, size_t size)
{
    snprintf(path, size, "%s/%s.sph", model_dir, it->name);
    if (!exists(path))
        snprintf(path, size, "%s/%s.sph", paths->stdlib, it->name);
    if (!exists(path)) {
        diag_error(it->loc, "cannot find module '%s' (looked beside the model and in %s)",
                   it->name, paths->stdlib);
        return -1;
    }
    return 0;
}

/* An import: its module is loaded once; an import that leads back to a file whose imports
 * led to it (the model importing itself, a -> b -> a) is an error at that import. */
static int import_module(const Item *it, const char *model_dir, const Paths *paths,
                         LoadedFiles *l, Program *prog)
{
    char path[8192];
    if (module_path(it, model_dir, paths, path, sizeof path))
        return 1;
    char *real = realpath(path, NULL);
    const int to = find_loaded(l, real ? real : path, 1);
    free(real);
    int from = it->loc.file ? find_loaded(l, it->loc.file, 0) : -1;
    if (from < 0)
        from = 0;
    if (to < 0) {
        add_loaded(l, path, from);
        return parse_file(l->files[l->n - 1].path, prog);
    }
    if (!imported_above(l, from, to))
        return 0; /* loaded already, through another import */
    if (to == from) {
        diag_error(it->loc, to == 0 ? "the model imports itself"
                                    : "module '%s' imports itself", it->name);
        return 1;
    }
    char chain[1024];
    cycle_chain(l, from, to, chain, sizeof chain);
    diag_error(it->loc, "import cycle: %s", chain);
    return 1;
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
    LoadedFiles loaded = {0};
    add_loaded(&loaded, prog->file ? prog->file : path, -1);
    /* Imported files may import more: prog->n grows while we scan.  An XML case imports
     * the material laws it uses, which are found like any module. */
    for (int i = 0; i < prog->n && !errors; i++) {
        if (prog->items[i].kind != IT_IMPORT)
            continue;
        Item copy = prog->items[i]; /* parse_file may move prog->items */
        errors += import_module(&copy, dir, paths, &loaded, prog);
    }
    free_loaded(&loaded);
    free(dir);
    return errors || diag_error_count() ? -1 : 0;
}
