/* mkdirs.h: mkdir -p, for the output folders of raygl2pov and
 * raygl-compare (-o NEW/SUB/DIR makes NEW, NEW/SUB and DIR). */
#ifndef RGL_MKDIRS_H
#define RGL_MKDIRS_H

#include <stddef.h>

/* Makes path and every missing folder above it (mode 0777, the umask
 * applies). *made (may be NULL) is the length of the shortest leading part
 * of path this call created (path[0..*made) is that folder), 0 when it
 * created none. Returns 0, or -1 with errno (ENOTDIR when path or a part
 * of it is not a folder); what it made stays then. */
int mkdirs(const char *path, size_t *made);

/* Removes the folders mkdirs made (while they are empty), deepest
 * first. */
void mkdirs_undo(const char *path, size_t made);

#endif
