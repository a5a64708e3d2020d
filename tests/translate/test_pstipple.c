/* test_pstipple.c: polygon stipple (translate/gl/interp_pstipple.c,
 * povwrite_pstipple.c).
 *
 * A filled draw with GL_POLYGON_STIPPLE on carries the mask and the
 * viewport's window position (mod 32) in its look, with no note; the
 * stipple off, or a mask of all ones, leaves the look plain; a
 * glPolygonStipple between glBegin and glEnd is refused and leaves the
 * mask; the SDL clips the mesh with the mask's rows as 32-bit numbers
 * (bit i: window x mod 32 = i) and the window origin.
 */
#include <GL/gl.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "interp.h"
#include "interp_internal.h"
#include "outbuf.h"
#include "povwrite.h"
#include "tracegen.h"

static scene sc;
static diag_log dlog;
static uint8_t masks[2][128]; /* 1: a checkerboard; 2: all ones */

static rgl_status fetch(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err)
{
    (void)ctx;
    if (id == 0 || id > 2) {
        err->status = RGL_E_RESOURCE;
        return RGL_E_RESOURCE;
    }
    memset(out, 0, sizeof *out);
    out->id = id;
    out->kind = RGL_RES_BYTES;
    out->data = masks[id - 1];
    out->size = 128;
    return RGL_OK;
}

static interp *fresh(void)
{
    scene_reset(&sc);
    diag_clear(&dlog);
    interp *ip = interp_create(&sc, &dlog);
    interp_set_resources(ip, fetch, NULL);
    interp_begin_frame(ip);
    return ip;
}

static void run(interp *ip, seq *s)
{
    rgl_error err;
    interp_run(ip, s->data, s->len, 0, &err);
    seq_free(s);
}

static char sdl[1 << 16];
static size_t nsdl;

static int keep(void *user, const char *p, size_t n)
{
    (void)user;
    if (nsdl + n >= sizeof sdl)
        return -1;
    memcpy(sdl + nsdl, p, n);
    nsdl += n;
    sdl[nsdl] = 0;
    return 0;
}

static void write_sdl(void)
{
    povwriter *w = povwriter_create();
    outbuf ob;
    nsdl = 0;
    sdl[0] = 0;
    CHECK(w != NULL && outbuf_init(&ob, 1 << 12, keep, NULL) == 0);
    CHECK(povwriter_scene(w, &ob, &sc, NULL) == 0);
    CHECK(outbuf_flush(&ob) == 0);
    outbuf_finish(&ob);
    povwriter_destroy(w);
}

static void tri(seq *s, double z)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, -0.5, -0.5, z);
    CMD(s, Vertex3f, 0.5, -0.5, z);
    CMD(s, Vertex3f, 0, 0.5, z);
    CMD0(s, End);
}

static void test_look(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 45, 70, 200, 100);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Enable, GL_POLYGON_STIPPLE);
    tri(&s, 0); /* GL's default mask: all ones, nothing cut */
    CMD(&s, PolygonStipple, 1);
    CMD(&s, Color3f, 0, 1, 0);
    tri(&s, 0.1);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, PolygonStipple, 2); /* refused: the mask stays */
    CMD0(&s, End);
    CMD(&s, Color3f, 0, 0, 1);
    tri(&s, 0.2);
    CMD(&s, Disable, GL_POLYGON_STIPPLE);
    CMD(&s, Color3f, 1, 1, 0);
    tri(&s, 0.3);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nmeshes, 4);
    if (sc.nmeshes == 4) {
        CHECK(!sc.meshes[0].look.pstipple);
        for (int m = 1; m <= 2; m++) {
            const scene_look *lk = &sc.meshes[m].look;
            CHECK(lk->pstipple);
            CHECK(memcmp(scene_pstipple_mask(&sc, lk->pstipple), masks[0], 128) == 0);
            CHECK(lk->pstipple_org[0] == 45 % 32 && lk->pstipple_org[1] == 70 % 32);
        }
        CHECK(!sc.meshes[3].look.pstipple);
    }
    CHECK_EQ_U(dlog.e[DIAG_NOTE_STIPPLE].count, 0);
    CHECK(dlog.e[DIAG_GL_INVALID_OPERATION].count >= 1);
    write_sdl();
    /* Rows 0xAA (pixels 0, 2, ...) and 0x55 (1, 3, ...), as numbers. */
    CHECK(strstr(sdl, "1431655765") != NULL && strstr(sdl, "2863311530") != NULL);
    const char *clip = strstr(sdl, "clipped_by{isosurface{function{rgl_pst");
    CHECK(clip != NULL);
    if (clip) /* declared once, used by both stippled meshes */
        CHECK(strstr(clip + 1, "clipped_by{isosurface{function{rgl_pst") != NULL);
    size_t ndecl = 0;
    for (const char *p = strstr(sdl, "_row=function(J)"); p; p = strstr(p + 1, "_row=function(J)"))
        ndecl++;
    CHECK_EQ_U(ndecl, 2); /* under #ifndef: one per mesh, parsed once */
    CHECK(strstr(sdl, ")+13,") != NULL && strstr(sdl, ")+6)") != NULL); /* 45, 70 mod 32 */
    interp_destroy(ip);

    /* An all-ones mask is no stipple. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, Enable, GL_POLYGON_STIPPLE);
    CMD(&s, PolygonStipple, 2);
    tri(&s, 0);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK(sc.nmeshes == 1 && !sc.meshes[0].look.pstipple);
    interp_destroy(ip);
}

/* The mask is GL_POLYGON_STIPPLE_BIT's (GL 2.1 table 6.16), not
 * GL_POLYGON_BIT's. */
static void test_attrib(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_POLYGON_STIPPLE);
    CMD(&s, PolygonStipple, 1);
    CMD(&s, PushAttrib, GL_POLYGON_BIT);
    CMD(&s, PolygonStipple, 2);
    CMD0(&s, PopAttrib); /* the all-ones mask stays */
    tri(&s, 0);
    CMD(&s, PushAttrib, GL_POLYGON_STIPPLE_BIT);
    CMD(&s, PolygonStipple, 1);
    CMD0(&s, PopAttrib); /* back to all ones */
    tri(&s, 0.1);
    CMD(&s, PolygonStipple, 1);
    CMD(&s, PushAttrib, GL_POLYGON_STIPPLE_BIT);
    CMD(&s, PolygonStipple, 2);
    CMD0(&s, PopAttrib); /* back to the checkerboard */
    tri(&s, 0.2);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nmeshes, 3); /* one per draw: no depth test */
    if (sc.nmeshes == 3) {
        CHECK(!sc.meshes[0].look.pstipple && !sc.meshes[1].look.pstipple);
        CHECK(sc.meshes[2].look.pstipple &&
              memcmp(scene_pstipple_mask(&sc, sc.meshes[2].look.pstipple), masks[0], 128) == 0);
    }
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    for (int r = 0; r < 32; r++)
        for (int b = 0; b < 4; b++)
            masks[0][r * 4 + b] = (r % 2) ? 0x55 : 0xAA;
    memset(masks[1], 0xff, 128);
    test_look();
    test_attrib();
    scene_finish(&sc);
    return CHECK_RESULT("test_pstipple");
}
