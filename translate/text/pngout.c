/* pngout.c: texture images as PNG files (pngout.h). */
#include "pngout.h"

#include <errno.h>
#include <fcntl.h>
#include <png.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cleanup.h"
#include "talloc.h"

static atomic_uint tmp_serial;

static int write_png(FILE *f, const uint8_t *rgba, int w, int h, bool alpha)
{
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    if (!png)
        return -1;
    png_infop info = png_create_info_struct(png);
    uint8_t *row = NULL;
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, info ? &info : NULL);
        tr_free(row);
        return -1;
    }
    size_t ch = alpha ? 4 : 3;
    row = tr_realloc(NULL, (size_t)w * ch);
    if (!row)
        png_error(png, "out of memory");
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)w, (png_uint_32)h, 8,
                 alpha ? PNG_COLOR_TYPE_RGBA : PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_set_gAMA(png, info, 1.0 / 2.2);
    /* Large images stored, not compressed: deflate was 5% of a large
     * frame's translation for 0.6 MB a frame saved beside 16 MB of SDL
     * (vertex-colour grids hardly compress), and POV-Ray reads a stored
     * PNG faster. A texture is written once however many frames use it.
     * Small ones (a HUD's text, a frame's overlay) compressed: they cost
     * little time and are written again each frame they change. */
    size_t raw = (size_t)w * (size_t)h * ch;
    if (raw <= PNGOUT_COMPRESS_MAX) {
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_ALL_FILTERS);
        png_set_compression_level(png, raw <= PNGOUT_COMPRESS_MAX / 4 ? 6 : 1);
    } else {
        png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
        png_set_compression_level(png, 0);
    }
    png_write_info(png, info);
    for (int y = h - 1; y >= 0; y--) { /* GL's bottom row is the file's last */
        const uint8_t *s = rgba + (size_t)y * (size_t)w * 4;
        if (alpha) {
            memcpy(row, s, (size_t)w * 4);
        } else { /* three bytes of four, without a call per pixel */
            for (size_t x = 0; x < (size_t)w; x++) {
                row[3 * x] = s[4 * x];
                row[3 * x + 1] = s[4 * x + 1];
                row[3 * x + 2] = s[4 * x + 2];
            }
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    tr_free(row);
    return 0;
}

int pngout_place(const char *dir, const char *name, const uint8_t *rgba, int w, int h,
                 bool alpha)
{
    if (!name[0] || strchr(name, '/') || name[0] == '.' || w <= 0 || h <= 0) {
        errno = EINVAL;
        return -1;
    }
    size_t dl = strlen(dir), nl = strlen(name);
    char *fin = tr_realloc(NULL, dl + nl + 2), *tmp = tr_realloc(NULL, dl + 80);
    if (!fin || !tmp) {
        tr_free(fin);
        tr_free(tmp);
        errno = ENOMEM;
        return -1;
    }
    snprintf(fin, dl + nl + 2, "%s/%s", dir, name);
    int rc = 0;
    struct stat st;
    if (stat(fin, &st) == 0 && S_ISREG(st.st_mode))
        goto done; /* already there: the same content */
    snprintf(tmp, dl + 80, "%s/.raygl2pov-%ld-tex%u.png.tmp", dir, (long)getpid(),
             atomic_fetch_add(&tmp_serial, 1));
    /* Registered before it exists, so a stop removes it (cleanup.h). */
    cleanup_lock();
    long id = cleanup_file(tmp);
    int fd = id >= 0 ? open(tmp, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666) : -1;
    int open_errno = id >= 0 ? errno : ENOMEM;
    cleanup_unlock();
    if (fd < 0) {
        cleanup_drop(id);
        errno = open_errno;
        rc = -1;
        goto done;
    }
    FILE *f = fdopen(fd, "wb");
    if (!f) {
        int e = errno;
        close(fd);
        unlink(tmp);
        cleanup_drop(id);
        errno = e;
        rc = -1;
        goto done;
    }
    errno = 0;
    rc = write_png(f, rgba, w, h, alpha);
    int e = errno ? errno : EIO;
    if (fclose(f) != 0 && rc == 0) {
        rc = -1;
        e = errno;
    }
    if (rc == 0 && rename(tmp, fin) != 0) {
        rc = -1;
        e = errno;
    }
    if (rc != 0)
        unlink(tmp);
    cleanup_drop(id);
    if (rc != 0)
        errno = e;
done:
    tr_free(fin);
    tr_free(tmp);
    return rc;
}

int pngout_encode(const uint8_t *rgba, int w, int h, bool alpha, uint8_t **out, size_t *n)
{
    *out = NULL;
    *n = 0;
    if (w <= 0 || h <= 0) {
        errno = EINVAL;
        return -1;
    }
    char *buf = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&buf, &len);
    if (!f)
        return -1;
    int rc = write_png(f, rgba, w, h, alpha);
    if (fclose(f) != 0)
        rc = -1;
    if (rc != 0) {
        free(buf); /* open_memstream's own malloc */
        errno = ENOMEM;
        return -1;
    }
    *out = (uint8_t *)buf;
    *n = len;
    return 0;
}
