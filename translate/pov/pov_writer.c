/* pov_writer.c: the POV-Ray writer as the driver sees it (writer.h):
 * STEM.pov, its texture images in textures/, and at publication the
 * STEM.ini that renders it into STEM.png. The user's include files are
 * copied into the folder once per run (begin) and named by every frame.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "pngout.h"
#include "povwrite.h"
#include "povwrite_look.h"
#include "povwrite_texture.h"
#include "talloc.h"
#include "writer.h"

typedef struct pov_run {
    char **includes; /* the include files' names in the output folder */
    size_t nincludes;
} pov_run;

typedef struct pov_worker {
    const pov_run *run;
    povwriter *w;
} pov_worker;

int povwriter_write_images(const povwriter *w, const char *dir, char *failed, size_t cap)
{
    const povtex_image *im = povwriter_image(w, 0);
    if (!im)
        return 0;
    /* A folder of their own: deleting or re-rendering the frames' PNGs
     * never takes a scene's textures with them. */
    size_t dl = strlen(dir);
    char *sub = tr_realloc(NULL, dl + sizeof "/" POVTEX_DIR);
    if (!sub) {
        errno = ENOMEM;
        return -1;
    }
    snprintf(sub, dl + sizeof "/" POVTEX_DIR, "%s/%s", dir, POVTEX_DIR);
    int rc = mkdir(sub, 0777) == 0 || errno == EEXIST ? 0 : -1;
    if (rc != 0)
        snprintf(failed, cap, "%s", sub);
    for (size_t i = 0; rc == 0 && (im = povwriter_image(w, i)) != NULL; i++) {
        rc = pngout_place(sub, im->name, im->rgba, im->width, im->height, im->alpha);
        if (rc != 0)
            snprintf(failed, cap, "%s/%s", sub, im->name);
    }
    int e = errno;
    tr_free(sub);
    errno = e;
    return rc;
}

static const char *pov_dir_problem(const char *dir)
{
    return pov_ini_path_ok(dir) ? NULL
                                : "a double quote or control character cannot be written into "
                                  "POV-Ray's .ini";
}

/* DIR/POV_FOLDER_CHECK, read first by every .ini (povwrite.h); kept as it
 * is when unchanged, so rendered frames stay up to date. Returns 0, or -1
 * with the message in msg. */
static int write_folder_check(const writer_trace *t, char *msg, size_t cap)
{
    char *tmp = writer_temp_path(t->dir, 0, ".inc"), *fin = writer_join(t->dir, POV_FOLDER_CHECK);
    int rc = -1, e = ENOMEM, fd = -1;
    long id = -1;
    if (tmp && fin) {
        fd = writer_temp_create(tmp, &id);
        e = errno;
    }
    if (fd >= 0) {
        outbuf ob;
        errno = 0;
        rc = outbuf_init(&ob, 4096, writer_fd_flush, &fd);
        if (rc == 0)
            rc = pov_write_folder_check(&ob, t->dir);
        if (rc == 0)
            rc = outbuf_flush(&ob);
        e = errno ? errno : EIO;
        outbuf_finish(&ob);
        if (close(fd) != 0 && rc == 0) {
            rc = -1;
            e = errno;
        }
        if (rc == 0 && writer_place(tmp, fin) != 0) {
            rc = -1;
            e = errno;
        }
        if (rc != 0)
            unlink(tmp);
    }
    if (rc != 0)
        snprintf(msg, cap, "%s: %s: cannot write: %s", t->trace, fin ? fin : t->dir, strerror(e));
    writer_temp_done(id);
    tr_free(tmp);
    tr_free(fin);
    return rc;
}

static void *pov_begin(const writer_trace *t, const char **note, char *msg, size_t cap)
{
    (void)note;
    if (write_folder_check(t, msg, cap) != 0)
        return NULL;
    pov_run *r = tr_realloc(NULL, sizeof *r);
    if (!r) {
        snprintf(msg, cap, "out of memory");
        return NULL;
    }
    memset(r, 0, sizeof *r);
    if (povlook_copy_includes(t->includes, t->nincludes, t->dir, &r->includes, msg, cap) != 0) {
        tr_free(r);
        return NULL;
    }
    r->nincludes = t->nincludes;
    return r;
}

static void pov_end(void *run)
{
    pov_run *r = run;
    if (!r)
        return;
    povlook_free_names(r->includes, r->nincludes);
    tr_free(r);
}

static void *pov_create(void *run)
{
    pov_worker *pw = tr_realloc(NULL, sizeof *pw);
    if (!pw)
        return NULL;
    pw->run = run;
    pw->w = povwriter_create();
    if (!pw->w) {
        tr_free(pw);
        return NULL;
    }
    return pw;
}

static void pov_destroy(void *w)
{
    pov_worker *pw = w;
    if (!pw)
        return;
    povwriter_destroy(pw->w);
    tr_free(pw);
}

static int pov_trim(void *w)
{
    pov_worker *pw = w;
    povwriter_destroy(pw->w);
    pw->w = povwriter_create();
    return pw->w ? 0 : -1;
}

static int pov_frame(void *w, const scene *s, const writer_frame *f, outbuf *ob, const char *dir,
                     char *failed, size_t cap)
{
    pov_worker *pw = w;
    pov_frame_info info = {f->file_name,  f->trace,     f->index, f->stream, f->number,
                           f->frame_name, f->incomplete};
    int rc = povwriter_scene(pw->w, ob, s, &info);
    if (rc == 0) {
        povlook_includes(ob, s, (const char *const *)pw->run->includes, pw->run->nincludes);
        rc = ob->failed ? -1 : 0;
    }
    if (rc == 0)
        rc = outbuf_flush(ob);
    errno = 0;
    if (rc == 0)
        rc = povwriter_write_images(pw->w, dir, failed, cap);
    return rc;
}

/* STEM.ini beside the scene, then both in place. */
static int pov_publish(void *run, const writer_kept *k, const writer_place_info *p, char *msg,
                       size_t cap)
{
    (void)run;
    const char *stem = p->stem;
    size_t sl = strlen(stem);
    char *pov = tr_realloc(NULL, sl + 8), *ini = tr_realloc(NULL, sl + 8),
         *png = tr_realloc(NULL, sl + 8);
    size_t tl = strlen(p->tmp_stem);
    char *tmp_ini = tr_realloc(NULL, tl + sizeof ".ini.tmp");
    char *fin_pov = NULL, *fin_ini = NULL;
    long ini_id = -1;
    int rc = -1;
    if (pov && ini && png && tmp_ini) {
        snprintf(pov, sl + 8, "%s.pov", stem);
        snprintf(ini, sl + 8, "%s.ini", stem);
        snprintf(png, sl + 8, "%s.png", stem);
        snprintf(tmp_ini, tl + sizeof ".ini.tmp", "%s.ini.tmp", p->tmp_stem);
        fin_pov = writer_join(p->dir, pov);
        fin_ini = writer_join(p->dir, ini);
    }
    if (!fin_pov || !fin_ini) {
        msg[0] = '\0'; /* out of memory */
        goto done;
    }
    int fd = writer_temp_create(tmp_ini, &ini_id);
    if (fd < 0) {
        snprintf(msg, cap, "%s: cannot create: %s", tmp_ini, strerror(errno));
        unlink(p->tmp_scene);
        goto done;
    }
    scene dims;
    memset(&dims, 0, sizeof dims);
    dims.camera.width = k->width;
    dims.camera.height = k->height;
    dims.antialias_depth = k->antialias_depth;
    outbuf ob;
    rc = outbuf_init(&ob, 4096, writer_fd_flush, &fd);
    errno = 0;
    if (rc == 0)
        rc = pov_write_ini(&ob, &dims, p->dir, pov, png);
    if (rc == 0) {
        povlook_ini(&ob, &k->options);
        rc = ob.failed ? -1 : 0;
    }
    if (rc == 0)
        rc = outbuf_flush(&ob);
    int e = errno ? errno : EIO;
    outbuf_finish(&ob);
    if (close(fd) != 0 && rc == 0) {
        rc = -1;
        e = errno;
    }
    if (rc != 0 || writer_place(p->tmp_scene, fin_pov) != 0 ||
        writer_place(tmp_ini, fin_ini) != 0) {
        if (rc == 0)
            e = errno;
        snprintf(msg, cap, "%s: cannot write: %s", fin_pov, strerror(e));
        unlink(p->tmp_scene);
        unlink(tmp_ini);
        rc = -1;
    }
done:
    writer_temp_done(ini_id);
    tr_free(pov);
    tr_free(ini);
    tr_free(png);
    tr_free(tmp_ini);
    tr_free(fin_pov);
    tr_free(fin_ini);
    return rc;
}

const writer_def writer_pov = {
    .name = "pov",
    .ext = ".pov",
    .engine = "povray",
    .dir_problem = pov_dir_problem,
    .begin = pov_begin,
    .end = pov_end,
    .create = pov_create,
    .destroy = pov_destroy,
    .trim = pov_trim,
    .frame = pov_frame,
    .publish = pov_publish,
};
