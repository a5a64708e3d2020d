/* test_proj.c: issue 14's projections, depth and draw order, and notes.
 *
 * Notes kept whole (never cut mid-word, a message too long to keep left
 * out whole and counted); single-buffered frames show the front buffer;
 * the camera of a frame of several projections and the layers of the
 * others.
 */
#include <GL/gl.h>
#include <string.h>

#include "check.h"
#include "diag.h"
#include "frame_front.h"
#include "frame.h"
#include "interp.h"
#include "interp_internal.h"
#include "scenes.h"
#include "tracegen.h"

static scene sc;
static diag_log dlog;

static bool ends_with(const char *s, const char *tail)
{
    size_t a = strlen(s), b = strlen(tail);
    return a >= b && strcmp(s + a - b, tail) == 0;
}

/* Every note, after the longest prefix a frame label allows, is kept whole. */
static void test_notes_whole(void)
{
    scene_reset(&sc);
    diag_clear(&dlog);
    interp *ip = interp_create(&sc, &dlog);
    interp_begin_frame(ip);
    memset(ip->label, 'x', sizeof ip->label - 1);
    ip->label[sizeof ip->label - 1] = '\0';
    ip->frame_index = UINT64_MAX;
    for (int k = DIAG_FIRST_NOTE; k < DIAG_COUNT; k++) {
        interp_note(ip, (diag_kind)k);
        CHECK_EQ_U(dlog.e[k].kept, 1);
        CHECK(ends_with(dlog.e[k].text[0], diag_kind_name((diag_kind)k)));
        CHECK(strstr(dlog.e[k].text[0], ip->label) != NULL);
        CHECK_EQ_U(dlog.e[k].dropped, 0);
    }
    interp_destroy(ip);
}

/* A message longer than DIAG_TEXT (a hostile trace's text) is counted and
 * left out whole, never kept cut; shorter ones are still kept after it. */
static void test_long_message_dropped(void)
{
    static char big[5000];
    memset(big, 'y', sizeof big - 1);
    diag_clear(&dlog);
    diag_add(&dlog, DIAG_IGNORED, "frame 1", "%s", big);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].count, 1);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].kept, 0);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].dropped, 1);
    diag_add(&dlog, DIAG_IGNORED, "frame 1", "%s", "short");
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].kept, 1);
    CHECK(strcmp(dlog.e[DIAG_IGNORED].text[0], "frame 1: short") == 0);

    /* The interpreter's own formatting: the same rule. */
    scene_reset(&sc);
    diag_clear(&dlog);
    interp *ip = interp_create(&sc, &dlog);
    interp_begin_frame(ip);
    interp_diag(ip, DIAG_IGNORED, "%s", big);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].count, 1);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].kept, 0);
    CHECK_EQ_U(dlog.e[DIAG_IGNORED].dropped, 1);
    diag_log sum;
    diag_clear(&sum);
    diag_merge(&sum, &dlog);
    CHECK_EQ_U(sum.e[DIAG_IGNORED].dropped, 1);
    interp_destroy(ip);
}

/* One triangle at x offset dx. */
static void tri(seq *s, double dx)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex2f, dx, 0);
    CMD(s, Vertex2f, dx + 0.2, 0);
    CMD(s, Vertex2f, dx, 0.2);
    CMD0(s, End);
}

static size_t tris_of(translator *tr, size_t i)
{
    frame_result res;
    if (translator_build(tr, i, NULL, &res) != RGL_OK)
        return (size_t)-1;
    return translator_scene(tr)->ntris;
}

/* A frame ended by glFlush shows what the front buffer holds: the drawing
 * of earlier single-buffered frames since the last colour clear. */
static void test_front_buffer(void)
{
    seq f[7];
    for (int k = 0; k < 7; k++)
        seq_init(&f[k]);
    CMD(&f[0], Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    tri(&f[0], 0);
    CMD0(&f[0], Flush);
    tri(&f[1], 0.3);
    CMD0(&f[1], Flush);
    CMD(&f[2], Clear, GL_DEPTH_BUFFER_BIT); /* not the colour: the drawing stays */
    CMD0(&f[2], Finish);
    CMD0(&f[2], FrameEnd);                  /* rayglFrameEnd after it still counts */
    tri(&f[3], -0.3);                       /* a swap-ended frame: no flush */
    CMD0(&f[4], Flush);                     /* after it: only this frame's own */
    CMD(&f[5], Clear, GL_COLOR_BUFFER_BIT);
    tri(&f[5], 0.5);
    CMD0(&f[5], Flush);
    tri(&f[6], 0.6);
    CMD0(&f[6], Flush);
    trace t;
    trace_init(&t);
    /* Frame 2 starts from a snapshot (a live-context recording writes one
     * per frame): that restores the state, not the front buffer. */
    seq snap;
    seq_init(&snap);
    CMD(&snap, ShadeModel, GL_FLAT);
    uint32_t sid = trace_snapshot(&t, &snap);
    for (uint32_t k = 0; k < 7; k++)
        trace_frame(&t, 0, k, k == 2 ? 0 : k ? RGL_FRAME_STATE_CARRIED : 0, k == 2 ? sid : 0,
                    &f[k]);
    seq_free(&snap);
    trace_finish(&t);
    rgl_reader *r;
    CHECK(rgl_reader_open_memory(t.data, t.size, &r, NULL) == RGL_OK);
    translator *tr = translator_create(r, NULL);
    CHECK(tr != NULL);
    static const size_t expect[7] = {1, 2, 2, 1, 0, 1, 2};
    for (size_t i = 0; tr && i < 7; i++)
        CHECK_EQ_U(tris_of(tr, i), expect[i]);
    /* Out of order (a worker asked for an earlier frame): the same. */
    for (size_t i = 7; tr && i-- > 0;)
        CHECK_EQ_U(tris_of(tr, i), expect[i]);
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    for (int k = 0; k < 7; k++)
        seq_free(&f[k]);
}

/* glDrawBuffer (interp_buffers.c): a swap-ended frame of a double-buffered
 * context shows the back buffer, a flushed one the front; GL_NONE draws
 * nowhere; a colour clear of the buffer not shown keeps the scene; a
 * single-buffered context refuses GL_BACK. */
static void test_draw_buffer(void)
{
    seq f[3];
    for (int k = 0; k < 3; k++)
        seq_init(&f[k]);
    CMD(&f[0], Clear, GL_COLOR_BUFFER_BIT);
    CMD(&f[0], DrawBuffer, GL_FRONT, 3);
    tri(&f[0], 0);
    CMD(&f[0], DrawBuffer, GL_BACK, 3);
    tri(&f[0], 0.1);
    CMD(&f[0], DrawBuffer, GL_FRONT_AND_BACK, 3);
    tri(&f[0], 0.2);
    CMD(&f[0], DrawBuffer, GL_NONE, 3);
    tri(&f[0], 0.3);
    CMD(&f[0], DrawBuffer, GL_FRONT, 3);
    CMD(&f[0], Clear, GL_COLOR_BUFFER_BIT); /* the front's alone */
    CMD(&f[1], DrawBuffer, GL_FRONT, 3);
    CMD(&f[1], Clear, GL_COLOR_BUFFER_BIT);
    tri(&f[1], 0);
    CMD(&f[1], DrawBuffer, GL_BACK, 3);
    tri(&f[1], 0.1);
    CMD0(&f[1], Flush); /* shows the front buffer */
    CMD(&f[2], DrawBuffer, GL_BACK, 1); /* single-buffered: refused */
    tri(&f[2], 0);
    CMD(&f[2], DrawBuffer, GL_NONE, 1);
    tri(&f[2], 0.1);
    trace t;
    trace_init(&t);
    for (uint32_t k = 0; k < 3; k++)
        trace_frame(&t, 0, k, 0, 0, &f[k]);
    trace_finish(&t);
    rgl_reader *r;
    CHECK(rgl_reader_open_memory(t.data, t.size, &r, NULL) == RGL_OK);
    translator *tr = translator_create(r, NULL);
    CHECK(tr != NULL);
    static const size_t expect[3] = {2, 1, 1};
    for (size_t i = 0; tr && i < 3; i++)
        CHECK_EQ_U(tris_of(tr, i), expect[i]);
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    for (int k = 0; k < 3; k++)
        seq_free(&f[k]);
}

/* A chain of flushes with no clear replays at most FRONT_MAX_FRAMES
 * earlier frames, with a note. */
static void test_front_buffer_capped(void)
{
    enum { N = FRONT_MAX_FRAMES + 10 };
    seq f;
    seq_init(&f);
    tri(&f, 0);
    CMD0(&f, Flush);
    trace t;
    trace_init(&t);
    for (uint32_t k = 0; k < N; k++)
        trace_frame(&t, 0, k, k ? RGL_FRAME_STATE_CARRIED : 0, 0, &f);
    trace_finish(&t);
    rgl_reader *r;
    CHECK(rgl_reader_open_memory(t.data, t.size, &r, NULL) == RGL_OK);
    translator *tr = translator_create(r, NULL);
    diag_clear(&dlog);
    frame_result res;
    CHECK(tr && translator_build(tr, N - 1, &dlog, &res) == RGL_OK);
    if (tr)
        CHECK_EQ_U(translator_scene(tr)->ntris, FRONT_MAX_FRAMES + 1);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_FRONT_BUFFER].count, 1);
    diag_clear(&dlog);
    CHECK(tr && translator_build(tr, 5, &dlog, &res) == RGL_OK);
    if (tr)
        CHECK_EQ_U(translator_scene(tr)->ntris, 6);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_FRONT_BUFFER].count, 0);
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    seq_free(&f);
}

static const scene *build_one(seq *f, translator **trp, rgl_reader **rp, trace *t)
{
    trace_init(t);
    trace_frame(t, 0, 0, 0, 0, f);
    trace_finish(t);
    CHECK(rgl_reader_open_memory(t->data, t->size, rp, NULL) == RGL_OK);
    *trp = translator_create(*rp, NULL);
    frame_result res;
    diag_clear(&dlog);
    if (!*trp || translator_build(*trp, 0, &dlog, &res) != RGL_OK)
        return NULL;
    return translator_scene(*trp);
}

/* Eye-space z of a mesh's point (x, y, 0) in object space; for a mesh
 * whose vertices are in eye space, of its first vertex. */
static double mesh_z(const scene *s, size_t m, double x, double y)
{
    const scene_mesh *sm = &s->meshes[m];
    if (sm->in_eye)
        return s->verts[s->tris[sm->first_tri].v[0]].pos[2];
    const mat4 *e = &sm->to_eye;
    return (e->m[2] * x + e->m[6] * y + e->m[14]) / (e->m[3] * x + e->m[7] * y + e->m[15]);
}

static void ortho_unit(seq *s)
{
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Ortho, 0, 1, 0, 1, -1, 1);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
}

/* A background in glOrtho (depth test off), the scene in perspective, a
 * HUD in glOrtho last: the camera is the perspective one, the background
 * sits just before the far plane, the HUD just behind the near plane. */
static void test_projection_layers(void)
{
    seq f;
    seq_init(&f);
    CMD(&f, Viewport, 0, 0, 200, 100);
    CMD(&f, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    ortho_unit(&f);
    CMD(&f, Rectf, 0, 0, 1, 1);
    CMD(&f, MatrixMode, GL_PROJECTION);
    CMD0(&f, LoadIdentity);
    CMD(&f, Frustum, -1, 1, -0.5, 0.5, 1, 11);
    CMD(&f, MatrixMode, GL_MODELVIEW);
    CMD0(&f, LoadIdentity);
    CMD(&f, Enable, GL_DEPTH_TEST);
    CMD(&f, Translatef, 0, 0, -5);
    tri(&f, 0);
    CMD(&f, Disable, GL_DEPTH_TEST);
    ortho_unit(&f);
    CMD(&f, Rectf, 0.4, 0.4, 0.6, 0.6);
    translator *tr;
    rgl_reader *r;
    trace t;
    const scene *s = build_one(&f, &tr, &r, &t);
    CHECK(s != NULL);
    if (s) {
        CHECK(s->camera.kind == SCENE_CAMERA_PERSPECTIVE);
        CHECK_EQ_U(s->nmeshes, 3);
    }
    if (s && s->nmeshes == 3) {
        /* near 1, far 11: layers at 0.1% and 99.9% of the way */
        CHECK_NEAR(mesh_z(s, 0, 0.5, 0.5), -(1 + 0.999 * 10), 0.02);
        CHECK_NEAR(mesh_z(s, 1, 0.1, 0.1), -5, 1e-9);
        CHECK_NEAR(mesh_z(s, 2, 0.5, 0.5), -(1 + 0.001 * 10), 0.002);
    }
    /* Only the lit/3D draw's projection is noted nowhere: unlit layers are exact. */
    CHECK_EQ_U(dlog.e[DIAG_NOTE_PROJECTION].count, 0);
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    seq_free(&f);

    /* The background drawn with the depth test, then the depth buffer
     * cleared: a background all the same. Without the clear it keeps
     * its depth (GL's depth buffer hides the scene behind it). */
    for (int clear = 0; clear < 2; clear++) {
        seq b;
        seq_init(&b);
        CMD(&b, Viewport, 0, 0, 200, 100);
        CMD(&b, Enable, GL_DEPTH_TEST);
        ortho_unit(&b);
        CMD(&b, Rectf, 0, 0, 1, 1);
        if (clear)
            CMD(&b, Clear, GL_DEPTH_BUFFER_BIT);
        CMD(&b, MatrixMode, GL_PROJECTION);
        CMD0(&b, LoadIdentity);
        CMD(&b, Frustum, -1, 1, -0.5, 0.5, 1, 11);
        CMD(&b, MatrixMode, GL_MODELVIEW);
        CMD0(&b, LoadIdentity);
        CMD(&b, Translatef, 0, 0, -5);
        tri(&b, 0);
        s = build_one(&b, &tr, &r, &t);
        CHECK(s && s->camera.kind == SCENE_CAMERA_PERSPECTIVE && s->nmeshes == 2);
        if (s && s->nmeshes == 2) {
            double z = mesh_z(s, 0, 0.5, 0.5);
            if (clear)
                CHECK_NEAR(z, -(1 + 0.999 * 10), 0.02);
            else
                CHECK(z > -5 && z < -1.5); /* GL's window depth 0: about 1.83 */
        }
        translator_destroy(tr);
        rgl_reader_destroy(r);
        trace_free(&t);
        seq_free(&b);
    }

    /* Only 2D draws in two projections: the first draw's camera stays. */
    seq g;
    seq_init(&g);
    CMD(&g, Viewport, 0, 0, 200, 100);
    ortho_unit(&g);
    CMD(&g, Rectf, 0, 0, 1, 1);
    CMD(&g, MatrixMode, GL_PROJECTION);
    CMD0(&g, LoadIdentity);
    CMD(&g, Frustum, -1, 1, -0.5, 0.5, 1, 11);
    CMD(&g, MatrixMode, GL_MODELVIEW);
    CMD0(&g, LoadIdentity);
    CMD(&g, Translatef, 0, 0, -5);
    tri(&g, 0);
    s = build_one(&g, &tr, &r, &t);
    CHECK(s && s->camera.kind == SCENE_CAMERA_ORTHOGRAPHIC);
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    seq_free(&g);
}

/* glOrtho with zNear = 0: the camera steps back past the draws moved
 * toward it, and the near plane lets them through. */
static void test_ortho_near_zero(void)
{
    seq f;
    seq_init(&f);
    CMD(&f, Viewport, 0, 0, 200, 100);
    CMD(&f, MatrixMode, GL_PROJECTION);
    CMD(&f, Ortho, 0, 2, 0, 1, 0, 1);
    CMD(&f, MatrixMode, GL_MODELVIEW);
    for (int k = 0; k < 3; k++)
        CMD(&f, Rectf, 0.1 * k, 0.1, 0.5, 0.5);
    translator *tr;
    rgl_reader *r;
    trace t;
    const scene *s = build_one(&f, &tr, &r, &t);
    CHECK(s && s->camera.kind == SCENE_CAMERA_ORTHOGRAPHIC && s->nmeshes == 3);
    if (s && s->nmeshes == 3) {
        double z0 = mesh_z(s, 0, 0.3, 0.3), z2 = mesh_z(s, 2, 0.3, 0.3);
        CHECK(z2 - z0 > 4e-4);                     /* apart more than POV-Ray's tolerance */
        CHECK(s->camera.location[2] > z2);         /* the camera behind them all */
        CHECK(s->camera.clip[0][3] + s->camera.clip[0][2] * z2 >= 0); /* inside the near plane */
    }
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
    seq_free(&f);
}

int main(void)
{
    scene_init(&sc);
    test_notes_whole();
    test_long_message_dropped();
    test_front_buffer();
    test_front_buffer_capped();
    test_draw_buffer();
    test_projection_layers();
    test_ortho_near_zero();
    scene_finish(&sc);
    return CHECK_RESULT("test_proj");
}
