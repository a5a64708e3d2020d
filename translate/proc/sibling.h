/* sibling.h: finding the other RayGL programs from where this one is.
 *
 * raygl-compare runs raygl2pov, and raygl2pov's cluster scripts run
 * raygl-render. Each looks beside its own executable (/proc/self/exe): in
 * an installed prefix they share bindir; in the build tree they sit in
 * translate/ and compare/, one folder apart. So a plain run from the
 * build tree works from any folder, with nothing installed.
 */
#ifndef RGL_SIBLING_H
#define RGL_SIBLING_H

#include <stddef.h>

/* Writes into buf (cap bytes) the absolute path of the executable NAME
 * found beside this program (same folder, else ../translate or
 * ../compare, the build tree's layout). Returns buf, or NULL when there
 * is none or the path does not fit. */
char *sibling_path(const char *name, char *buf, size_t cap);

/* Likewise for a data file NAME installed with the programs (the Blender
 * import script): PREFIX/share/raygl/NAME beside PREFIX/bin, else NAME
 * beside this program (the build tree copies it there). Returns buf, or
 * NULL when there is none (a readable regular file) or it does not fit. */
char *sibling_data(const char *name, char *buf, size_t cap);

#endif
