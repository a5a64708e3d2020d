/* relink.h: rebinding another library's imports of gl* names (relink.c). */
#ifndef RGL_RELINK_H
#define RGL_RELINK_H

#include <stddef.h>

/* In the loaded object that contains the address in_object (NULL: the
 * program itself), points each
 * GOT slot for an imported name names[i] at fns[i] (count names). Returns
 * 0, or -1 when the object's tables cannot be read or the target is not
 * supported (nothing changed then). Not thread-safe against itself. */
int rgl_relink(void *in_object, const char *const *names, void (*const *fns)(void), size_t count);

#endif
