/* writer.c: the helpers every writer and the driver share (writer.h). */
#include "writer.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cleanup.h"
#include "talloc.h"

void writer_keep(const scene *s, writer_kept *k)
{
    memset(k, 0, sizeof *k);
    k->width = s->camera.width;
    k->height = s->camera.height;
    k->antialias_depth = s->antialias_depth;
    k->options = s->options;
}

char *writer_join(const char *dir, const char *file)
{
    size_t dl = strlen(dir), fl = strlen(file);
    bool slash = dl > 0 && dir[dl - 1] == '/';
    char *p = tr_realloc(NULL, dl + fl + 2);
    if (!p)
        return NULL;
    memcpy(p, dir, dl);
    if (!slash)
        p[dl++] = '/';
    memcpy(p + dl, file, fl + 1);
    return p;
}

char *writer_temp_path(const char *dir, size_t slot, const char *ext)
{
    char name[96];
    snprintf(name, sizeof name, ".raygl2pov-%ld-%zu%s%s", (long)getpid(), slot, ext ? ext : "",
             ext ? ".tmp" : "");
    return writer_join(dir, name);
}

int writer_temp_create(const char *path, long *id)
{
    /* Registered before it exists, so a stop removes it (cleanup.h). */
    cleanup_lock();
    *id = cleanup_file(path);
    int fd = *id >= 0 ? open(path, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666) : -1;
    int e = *id >= 0 ? errno : ENOMEM;
    cleanup_unlock();
    if (fd < 0) {
        cleanup_drop(*id);
        *id = -1;
        errno = e;
    }
    return fd;
}

void writer_temp_done(long id) { cleanup_drop(id); }

bool writer_files_same(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fa ? fopen(b, "rb") : NULL;
    bool same = fa && fb;
    char ba[65536], bb[65536];
    while (same) {
        size_t na = fread(ba, 1, sizeof ba, fa), nb = fread(bb, 1, sizeof bb, fb);
        same = na == nb && memcmp(ba, bb, na) == 0 && !ferror(fa) && !ferror(fb);
        if (na == 0)
            break;
    }
    if (fa)
        fclose(fa);
    if (fb)
        fclose(fb);
    return same;
}

int writer_place(const char *tmp, const char *fin)
{
    if (writer_files_same(tmp, fin))
        return unlink(tmp);
    return rename(tmp, fin);
}

int writer_fd_flush(void *user, const char *data, size_t n)
{
    int fd = *(int *)user;
    while (n > 0) {
        ssize_t w = write(fd, data, n);
        if (w < 0) {
            if (errno == EINTR)
                continue;
            return -1;
        }
        data += w;
        n -= (size_t)w;
    }
    return 0;
}
