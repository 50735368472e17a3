/* paths.c — where sphc's templates, stdlib, runtime headers and library are: the installed
 * layout, SPHC_HOME, or the source and build trees sphc was built from. */
#define _XOPEN_SOURCE 700
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "util/diag.h"
#include "driver.h"
static int exists(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0;
}

static int installed_paths(const char *argv0, Paths *p)
{
    char exe[2048];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) {
        if (!realpath(argv0, exe))
            return 0;
    } else {
        exe[n] = 0;
    }
    char *slash = strrchr(exe, '/');
    if (!slash)
        return 0;
    *slash = 0; /* <prefix>/bin */
    char probe[2200];
    snprintf(probe, sizeof probe, "%s/../%s/templates/body_forces.c", exe, SPHC_INSTALL_DATADIR);
    if (!exists(probe))
        return 0;
    snprintf(p->templates, sizeof p->templates, "%s/../%s/templates", exe, SPHC_INSTALL_DATADIR);
    snprintf(p->stdlib, sizeof p->stdlib, "%s/../%s/stdlib", exe, SPHC_INSTALL_DATADIR);
    snprintf(p->include, sizeof p->include, "%s/../%s/include", exe, SPHC_INSTALL_DATADIR);
    snprintf(p->lib, sizeof p->lib, "%s/../%s", exe, SPHC_INSTALL_LIBDIR);
    return 1;
}

int find_paths(const char *argv0, Paths *p)
{
    const char *home = getenv("SPHC_HOME");
    if (home && *home) {
        snprintf(p->templates, sizeof p->templates, "%s/share/sphc/templates", home);
        snprintf(p->stdlib, sizeof p->stdlib, "%s/share/sphc/stdlib", home);
        snprintf(p->include, sizeof p->include, "%s/share/sphc/include", home);
        snprintf(p->lib, sizeof p->lib, "%s/lib", home);
    } else if (!installed_paths(argv0, p)) {
        snprintf(p->templates, sizeof p->templates, "%s/templates", SPHC_SOURCE_DIR);
        snprintf(p->stdlib, sizeof p->stdlib, "%s/stdlib", SPHC_SOURCE_DIR);
        snprintf(p->include, sizeof p->include, "%s/runtime", SPHC_SOURCE_DIR);
        snprintf(p->lib, sizeof p->lib, "%s", SPHC_BUILD_LIBDIR);
    }
    char probe[4200];
    snprintf(probe, sizeof probe, "%s/body_forces.c", p->templates);
    if (!exists(probe)) {
        diag_fatal_noloc("cannot find sphc's templates (looked in %s); set SPHC_HOME to the "
                         "installation prefix",
                         p->templates);
        return -1;
    }
    return 0;
}
