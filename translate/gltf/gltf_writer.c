/* gltf_writer.c: the glTF writer as the driver sees it (writer.h): one
 * binary glTF file STEM.glb per frame, images embedded, nothing else.
 */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "gltfwrite.h"
#include "talloc.h"
#include "writer.h"

/* Stems are at most this long (driver/naming.h, NAME_MAX_STEM + 64). */
#define GLTF_STEM_MAX 192

/* No state: gltf_write keeps nothing between frames. */
static char gltf_run;

static void *gltf_begin(const writer_trace *t, const char **note, char *msg, size_t cap)
{
    (void)msg;
    (void)cap;
    if (t->nincludes)
        *note = "--include: POV-Ray SDL, which a glTF file cannot hold: left out of every frame";
    return &gltf_run;
}

static void gltf_end(void *run) { (void)run; }

static int gltf_frame(void *w, const scene *s, const writer_frame *f, outbuf *ob, const char *dir,
                      char *failed, size_t cap)
{
    (void)w;
    (void)dir;
    (void)failed;
    (void)cap;
    gltf_frame_info gi = {f->trace, f->index, f->frame_name, f->incomplete};
    int rc = gltf_write(ob, s, &gi, NULL);
    if (rc == 0)
        rc = outbuf_flush(ob);
    return rc;
}

static int gltf_publish(void *run, const writer_kept *k, const writer_place_info *p, char *msg,
                        size_t cap)
{
    (void)run;
    (void)k;
    char glb[GLTF_STEM_MAX + 8];
    snprintf(glb, sizeof glb, "%s.glb", p->stem);
    char *fin = writer_join(p->dir, glb);
    int rc = -1;
    if (!fin) {
        msg[0] = '\0'; /* out of memory */
    } else if (writer_place(p->tmp_scene, fin) != 0) {
        snprintf(msg, cap, "%s: cannot write: %s", fin, strerror(errno));
        unlink(p->tmp_scene);
    } else {
        rc = 0;
    }
    tr_free(fin);
    return rc;
}

const writer_def writer_gltf = {
    .name = "gltf",
    .ext = ".glb",
    .engine = "blender",
    .begin = gltf_begin,
    .end = gltf_end,
    .frame = gltf_frame,
    .publish = gltf_publish,
};
