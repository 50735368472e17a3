/* regular_file.h — whether a file to read is something other than a regular file (a
 * device, a named pipe, a folder), looked at before it is opened: opening a pipe waits for a
 * writer, and a device such as /dev/zero never ends.  A path that does not exist is not
 * refused here (opening it then says so).  For the runtime and the compiler alike. */
#ifndef SPHRT_REGULAR_FILE_H
#define SPHRT_REGULAR_FILE_H

#include <sys/stat.h>

static inline int sph_not_regular_file(const char *path)
{
    struct stat st;
    return stat(path, &st) == 0 && !S_ISREG(st.st_mode);
}

#endif
