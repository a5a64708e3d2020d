/* mkdirs.c: mkdir -p (mkdirs.h). */
#include "mkdirs.h"

#include <errno.h>
#include <limits.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int mkdirs(const char *path, size_t *made)
{
    char p[PATH_MAX];
    size_t n = strlen(path);
    if (made)
        *made = 0;
    if (n == 0 || n >= sizeof p) {
        errno = n ? ENAMETOOLONG : ENOENT;
        return -1;
    }
    memcpy(p, path, n + 1);
    while (n > 1 && p[n - 1] == '/')
        p[--n] = '\0';
    for (size_t i = 1; i <= n; i++) {
        if (p[i] != '/' && p[i] != '\0')
            continue;
        char c = p[i];
        p[i] = '\0';
        if (mkdir(p, 0777) == 0) {
            if (made && *made == 0)
                *made = i;
        } else if (errno != EEXIST) {
            return -1;
        }
        p[i] = c;
    }
    struct stat st;
    if (stat(p, &st) != 0)
        return -1;
    if (!S_ISDIR(st.st_mode)) {
        errno = ENOTDIR;
        return -1;
    }
    return 0;
}

void mkdirs_undo(const char *path, size_t made)
{
    char p[PATH_MAX];
    size_t n = strlen(path);
    if (made == 0 || n >= sizeof p)
        return;
    memcpy(p, path, n + 1);
    while (n > 1 && p[n - 1] == '/')
        p[--n] = '\0';
    while (n >= made) {
        if (rmdir(p) != 0)
            return;
        while (n > 0 && p[n - 1] != '/')
            n--;
        while (n > 0 && p[n - 1] == '/')
            n--;
        p[n] = '\0';
    }
}
