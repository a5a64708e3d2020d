/* sibling.c: the other RayGL programs beside this one (sibling.h). */
#include "sibling.h"

#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

char *sibling_path(const char *name, char *buf, size_t cap)
{
    /* The installed layout first; then the build tree's folders. */
    static const char *const dirs[] = {"", "/../translate", "/../compare"};
    char self[4096];
    ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
    if (n <= 0 || !*name)
        return NULL;
    self[n] = '\0';
    char *slash = strrchr(self, '/');
    if (!slash)
        return NULL;
    *slash = '\0';
    for (size_t i = 0; i < sizeof dirs / sizeof dirs[0]; i++) {
        int w = snprintf(buf, cap, "%s%s/%s", self, dirs[i], name);
        struct stat st;
        if (w > 0 && (size_t)w < cap && stat(buf, &st) == 0 && S_ISREG(st.st_mode) &&
            access(buf, X_OK) == 0)
            return buf;
    }
    return NULL;
}
