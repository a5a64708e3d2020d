/* sibling.c: the other RayGL programs beside this one (sibling.h). */
#include "sibling.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The first regular file dir/name, dir taken from dirs relative to this
 * executable's folder, with access mode; buf, or NULL. */
static char *beside_self(const char *const *dirs, size_t ndirs, const char *name, int mode,
                         char *buf, size_t cap)
{
    char self[4096];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0 || !*name)
        return NULL;
    self[n] = '\0';
    char *slash = strrchr(self, '/');
    if (!slash)
        return NULL;
    *slash = '\0';
    for (size_t i = 0; i < ndirs; i++) {
        int w = snprintf(buf, cap, "%s%s/%s", self, dirs[i], name);
        struct stat st;
        if (w > 0 && (size_t)w < cap && stat(buf, &st) == 0 && S_ISREG(st.st_mode) &&
            access(buf, mode) == 0)
            return buf;
    }
    return NULL;
}

char *sibling_path(const char *name, char *buf, size_t cap)
{
    /* The installed layout first; then the build tree's folders. */
    static const char *const dirs[] = {"", "/../translate", "/../compare"};
    return beside_self(dirs, sizeof dirs / sizeof dirs[0], name, X_OK, buf, cap);
}

char *sibling_data(const char *name, char *buf, size_t cap)
{
    static const char *const dirs[] = {"/../share/raygl", "", "/../translate"};
    return beside_self(dirs, sizeof dirs / sizeof dirs[0], name, R_OK, buf, cap);
}
