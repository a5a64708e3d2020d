/* test_notes.c: notes said only where their approximation can change a
 * pixel of the frame, held (counted apart, kept marked) where it cannot
 * (translate/base/diag.h; docs/mapping.md "Notes").
 *
 * NOTE_DEPTH over whole frames through the translator (it is decided at
 * the frame's end, interp_zorder.c): draws without a depth test or depth
 * writes that overlap on screen in the order the ray tracer shows, or
 * that do not overlap, or that show one colour, hold it; a later draw
 * farther than an earlier one it covers, parts of one draw that overlap in
 * one plane, and depth functions the ray tracer cannot follow say it.
 * Then the other notes reviewed for noise: render modes, colour-index
 * evaluators, point fade, highlights of the shadowed and the shadowless
 * render.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include <string.h>

#include "check.h"
#include "diag.h"
#include "frame.h"
#include "interp.h"
#include "tracegen.h"

static diag_log dlog;

static uint64_t said(diag_kind k) { return dlog.e[k].count - dlog.e[k].held; }
static uint64_t held(diag_kind k) { return dlog.e[k].held; }

/* Translates the one frame f (freed) into dlog; shadows as asked. */
static void build(seq *f, bool shadows)
{
    trace t;
    trace_init(&t);
    trace_frame(&t, 0, 0, 0, 0, f);
    trace_finish(&t);
    seq_free(f);
    rgl_reader *r;
    CHECK(rgl_reader_open_memory(t.data, t.size, &r, NULL) == RGL_OK);
    translator *tr = translator_create(r, NULL);
    CHECK(tr != NULL);
    diag_clear(&dlog);
    frame_result res;
    if (tr) {
        translator_set_shadows(tr, shadows);
        CHECK(translator_build(tr, 0, &dlog, &res) == RGL_OK);
    }
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
}

static void expect(const char *what, diag_kind k, uint64_t want_said, uint64_t want_held)
{
    if (said(k) != want_said || held(k) != want_held) {
        fprintf(stderr, "%s: %s said %llu held %llu, expected said %llu held %llu\n", what,
                diag_kind_name(k), (unsigned long long)said(k), (unsigned long long)held(k),
                (unsigned long long)want_said, (unsigned long long)want_held);
        check_failures++;
    }
}

static void ortho(seq *s)
{
    CMD(s, Viewport, 0, 0, 64, 64);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Ortho, 0, 1, 0, 1, -1, 1);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
}

static void perspective(seq *s)
{
    CMD(s, Viewport, 0, 0, 64, 64);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Frustum, -1, 1, -1, 1, 1, 100);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
}

/* A quad from (x0, y0) to (x1, y1) at depth z, of one colour. */
static void quad(seq *s, double x0, double y0, double x1, double y1, double z, double r,
                 double g, double b)
{
    CMD(s, Color3f, r, g, b);
    CMD(s, Begin, GL_QUADS);
    CMD(s, Vertex3f, x0, y0, z);
    CMD(s, Vertex3f, x1, y0, z);
    CMD(s, Vertex3f, x1, y1, z);
    CMD(s, Vertex3f, x0, y1, z);
    CMD0(s, End);
}

static void test_depth_order(void)
{
    seq f;
    /* 2D: overlapping quads in one plane without a depth test, drawn in
     * order; the painter's shift shows them as GL does. */
    seq_init(&f);
    ortho(&f);
    quad(&f, 0.1, 0.1, 0.6, 0.6, 0, 1, 0, 0);
    quad(&f, 0.3, 0.3, 0.8, 0.8, 0, 0, 1, 0);
    quad(&f, 0.2, 0.5, 0.9, 0.9, 0, 0, 0, 1);
    build(&f, true);
    expect("2D in order", DIAG_NOTE_DEPTH, 0, 1);
    /* Its text says why. */
    CHECK(dlog.e[DIAG_NOTE_DEPTH].kept == 1 && diag_is_held(&dlog.e[DIAG_NOTE_DEPTH], 0));
    CHECK(strstr(dlog.e[DIAG_NOTE_DEPTH].text[0], DIAG_HELD_MARK) != NULL);
    CHECK(strstr(dlog.e[DIAG_NOTE_DEPTH].text[0], "frame 0, cmd ") != NULL);

    /* Perspective, no depth test: a near quad, then a far one over it. GL
     * shows the far one where they overlap; the ray tracer the near. */
    seq_init(&f);
    perspective(&f);
    quad(&f, -1, -1, 0.5, 0.5, -2, 1, 0, 0);
    quad(&f, -2, -2, 3, 3, -5, 0, 1, 0);
    build(&f, true);
    expect("far after near", DIAG_NOTE_DEPTH, 1, 0);
    /* Said at the later draw: cmd 14 is the second quad's glBegin. */
    CHECK(strstr(dlog.e[DIAG_NOTE_DEPTH].text[0], "cmd 14 (glBegin)") != NULL);

    /* Far first, then near: the ray tracer's order is GL's. */
    seq_init(&f);
    perspective(&f);
    quad(&f, -2, -2, 3, 3, -5, 0, 1, 0);
    quad(&f, -1, -1, 0.5, 0.5, -2, 1, 0, 0);
    build(&f, true);
    expect("near after far", DIAG_NOTE_DEPTH, 0, 1);

    /* Far after near, but side by side on screen. */
    seq_init(&f);
    perspective(&f);
    quad(&f, -1, -1, -0.5, 0.5, -2, 1, 0, 0);
    quad(&f, 0.5, -1, 2, 1, -5, 0, 1, 0);
    build(&f, true);
    expect("apart", DIAG_NOTE_DEPTH, 0, 1);

    /* Far after near, overlapping, of one colour: either shows the same. */
    seq_init(&f);
    perspective(&f);
    quad(&f, -1, -1, 0.5, 0.5, -2, 0.5, 0.5, 0.5);
    quad(&f, -2, -2, 3, 3, -5, 0.5, 0.5, 0.5);
    build(&f, true);
    expect("one colour", DIAG_NOTE_DEPTH, 0, 1);

    /* Depth-tested only: nothing to say or hold. */
    seq_init(&f);
    perspective(&f);
    CMD(&f, Enable, GL_DEPTH_TEST);
    quad(&f, -1, -1, 0.5, 0.5, -2, 1, 0, 0);
    quad(&f, -2, -2, 3, 3, -5, 0, 1, 0);
    build(&f, true);
    expect("depth-tested", DIAG_NOTE_DEPTH, 0, 0);

    /* A depth-tested scene, then a HUD in window pixels without the depth
     * test over it: the HUD lies in front, as GL shows it. */
    seq_init(&f);
    perspective(&f);
    CMD(&f, Enable, GL_DEPTH_TEST);
    quad(&f, -2, -2, 3, 3, -5, 0, 1, 0);
    CMD(&f, Disable, GL_DEPTH_TEST);
    CMD(&f, MatrixMode, GL_PROJECTION);
    CMD0(&f, LoadIdentity);
    CMD(&f, Ortho, 0, 64, 0, 64, -1, 1);
    CMD(&f, MatrixMode, GL_MODELVIEW);
    CMD0(&f, LoadIdentity);
    quad(&f, 4, 4, 40, 20, 0, 1, 1, 1);
    build(&f, true);
    expect("HUD", DIAG_NOTE_DEPTH, 0, 1);

    /* A depth-tested floor reaching behind the eye, then the HUD: the
     * floor is cut where the camera sees it, still under the HUD. */
    seq_init(&f);
    perspective(&f);
    CMD(&f, Enable, GL_DEPTH_TEST);
    CMD(&f, Color3f, 0.3, 0.6, 0.3);
    CMD(&f, Begin, GL_QUADS);
    CMD(&f, Vertex3f, -50, -1, 10);
    CMD(&f, Vertex3f, 50, -1, 10);
    CMD(&f, Vertex3f, 50, -1, -90);
    CMD(&f, Vertex3f, -50, -1, -90);
    CMD0(&f, End);
    CMD(&f, Disable, GL_DEPTH_TEST);
    CMD(&f, MatrixMode, GL_PROJECTION);
    CMD0(&f, LoadIdentity);
    CMD(&f, Ortho, 0, 64, 0, 64, -1, 1);
    CMD(&f, MatrixMode, GL_MODELVIEW);
    CMD0(&f, LoadIdentity);
    quad(&f, 4, 4, 40, 20, 0, 1, 1, 1);
    build(&f, true);
    expect("HUD over a floor behind the eye", DIAG_NOTE_DEPTH, 0, 1);

    /* Depth writes off (translucent faces drawn last): near then far. GL
     * draws the far one over the near, which wrote no depth. */
    seq_init(&f);
    perspective(&f);
    CMD(&f, Enable, GL_DEPTH_TEST);
    CMD(&f, DepthMask, 0);
    quad(&f, -1, -1, 0.5, 0.5, -2, 1, 0, 0);
    quad(&f, -2, -2, 3, 3, -5, 0, 1, 0);
    build(&f, true);
    expect("depth mask, near first", DIAG_NOTE_DEPTH, 1, 0);
    seq_init(&f);
    perspective(&f);
    CMD(&f, Enable, GL_DEPTH_TEST);
    CMD(&f, DepthMask, 0);
    quad(&f, -2, -2, 3, 3, -5, 0, 1, 0);
    quad(&f, -1, -1, 0.5, 0.5, -2, 1, 0, 0);
    build(&f, true);
    expect("depth mask, far first", DIAG_NOTE_DEPTH, 0, 1);

    /* GL_GREATER: drawn in order, where GL keeps the farther. */
    seq_init(&f);
    perspective(&f);
    CMD(&f, Enable, GL_DEPTH_TEST);
    CMD(&f, DepthFunc, GL_GREATER);
    quad(&f, -1, -1, 0.5, 0.5, -2, 1, 0, 0);
    build(&f, true);
    expect("GL_GREATER", DIAG_NOTE_DEPTH, 1, 0);

    /* One draw whose parts overlap in one plane: a star drawn as one
     * polygon (a fan over its own parts), its colours varying. */
    seq_init(&f);
    ortho(&f);
    CMD(&f, Begin, GL_POLYGON);
    const double star[5][2] = {{0.5, 0.95}, {0.8, 0.1}, {0.05, 0.65}, {0.95, 0.65}, {0.2, 0.1}};
    for (int k = 0; k < 5; k++) {
        CMD(&f, Color3f, k * 0.25, 1 - k * 0.25, 0.5);
        CMD(&f, Vertex2f, star[k][0], star[k][1]);
    }
    CMD0(&f, End);
    build(&f, true);
    expect("self-overlapping polygon", DIAG_NOTE_DEPTH, 1, 0);
    /* A convex one: its parts meet at edges only. */
    seq_init(&f);
    ortho(&f);
    CMD(&f, Begin, GL_POLYGON);
    for (int k = 0; k < 8; k++) {
        double a = k * 3.14159265358979 / 4;
        CMD(&f, Color3f, k * 0.125, 1 - k * 0.125, 0.5);
        CMD(&f, Vertex2f, 0.5 + 0.4 * cos(a), 0.5 + 0.4 * sin(a));
    }
    CMD0(&f, End);
    build(&f, true);
    expect("convex polygon", DIAG_NOTE_DEPTH, 0, 1);

    /* A line strip of one colour per segment, 3 pixels wide: at its sharp
     * joints both segments light a few pixels (GL shows the later); each
     * segment is a painter's step nearer than the one before, so the
     * ray tracer shows the later too. */
    for (int masked = 0; masked < 2; masked++) {
        seq_init(&f);
        ortho(&f);
        if (masked) {
            CMD(&f, Enable, GL_DEPTH_TEST);
            CMD(&f, DepthMask, 0);
        }
        CMD(&f, ShadeModel, GL_FLAT);
        CMD(&f, LineWidth, 3);
        CMD(&f, Begin, GL_LINE_STRIP);
        for (int k = 0; k < 6; k++) {
            CMD(&f, Color3f, k & 1, 1 - (k & 1), 0);
            CMD(&f, Vertex2f, 0.1 + 0.15 * k, k & 1 ? 0.8 : 0.2);
        }
        CMD0(&f, End);
        build(&f, true);
        /* Depth-tested with depth writes off, the later segment passes GL's
         * test too, but no painter's step separates the segments: at the
         * joints the two colours lie in one plane, either may show. */
        if (masked)
            expect("line strip, depth writes off", DIAG_NOTE_DEPTH, 1, 0);
        else
            expect("line strip", DIAG_NOTE_DEPTH, 0, 1);
    }
    /* A 1-pixel strip turning by a right angle, depth writes off: its
     * segments share no pixel (the joint's is drawn once, by the second),
     * though their rectangles touch: nothing can differ. */
    seq_init(&f);
    ortho(&f);
    CMD(&f, Enable, GL_DEPTH_TEST);
    CMD(&f, DepthMask, 0);
    CMD(&f, ShadeModel, GL_FLAT);
    CMD(&f, Begin, GL_LINE_STRIP);
    CMD(&f, Color3f, 1, 0, 0);
    CMD(&f, Vertex2f, 8.3 / 64, 8.4 / 64);
    CMD(&f, Vertex2f, 40.3 / 64, 8.4 / 64);
    CMD(&f, Color3f, 0, 0, 1);
    CMD(&f, Vertex2f, 40.3 / 64, 40.4 / 64);
    CMD0(&f, End);
    build(&f, true);
    expect("thin line strip, depth writes off", DIAG_NOTE_DEPTH, 0, 1);
    /* Two crossing lines of one GL_LINES draw, of two colours: GL shows
     * the second at the crossing, a painter's step nearer. */
    seq_init(&f);
    ortho(&f);
    CMD(&f, LineWidth, 3);
    CMD(&f, Begin, GL_LINES);
    CMD(&f, Color3f, 1, 0, 0);
    CMD(&f, Vertex2f, 0.1, 0.1);
    CMD(&f, Vertex2f, 0.9, 0.9);
    CMD(&f, Color3f, 0, 0, 1);
    CMD(&f, Vertex2f, 0.1, 0.9);
    CMD(&f, Vertex2f, 0.9, 0.1);
    CMD0(&f, End);
    build(&f, true);
    expect("crossing lines, one draw", DIAG_NOTE_DEPTH, 0, 1);
    /* Two overlapping points of one draw, of two colours: points share
     * their draw's plane, either may show. */
    seq_init(&f);
    ortho(&f);
    CMD(&f, PointSize, 6);
    CMD(&f, Begin, GL_POINTS);
    CMD(&f, Color3f, 1, 0, 0);
    CMD(&f, Vertex2f, 0.5, 0.5);
    CMD(&f, Color3f, 0, 0, 1);
    CMD(&f, Vertex2f, 0.53, 0.52);
    CMD0(&f, End);
    build(&f, true);
    expect("overlapping points, one draw", DIAG_NOTE_DEPTH, 1, 0);
    /* The same lines in two draws: the later shows, as in GL. */
    seq_init(&f);
    ortho(&f);
    CMD(&f, LineWidth, 3);
    CMD(&f, Color3f, 1, 0, 0);
    CMD(&f, Begin, GL_LINES);
    CMD(&f, Vertex2f, 0.1, 0.1);
    CMD(&f, Vertex2f, 0.9, 0.9);
    CMD0(&f, End);
    CMD(&f, Color3f, 0, 0, 1);
    CMD(&f, Begin, GL_LINES);
    CMD(&f, Vertex2f, 0.1, 0.9);
    CMD(&f, Vertex2f, 0.9, 0.1);
    CMD0(&f, End);
    build(&f, true);
    expect("crossing lines, two draws", DIAG_NOTE_DEPTH, 0, 1);
}

/* glMap1f: the blob of packed little-endian floats. */
static void map1f(seq *s, GLenum target, int stride, int order, const float *pts, size_t n)
{
    uint8_t b[4 * 16];
    for (size_t i = 0; i < n && i < 16; i++) {
        uint32_t u;
        memcpy(&u, &pts[i], 4);
        for (int k = 0; k < 4; k++)
            b[4 * i + k] = (uint8_t)(u >> (8 * k));
    }
    seq_cmd_bytes(s, RGL_OP_Map1f, b, 4 * n, (const double[]){target, 0, 1, stride, order}, 5);
}

static void lit_quad(seq *f)
{
    perspective(f);
    CMD(f, Enable, GL_LIGHTING);
    CMD(f, Enable, GL_LIGHT0);
    CMD(f, Lightfv, GL_LIGHT0, GL_DIFFUSE, 1, 1, 1, 1);
    CMD(f, Lightfv, GL_LIGHT0, GL_SPECULAR, 1, 0, 0, 1); /* no multiple of the diffuse */
    CMD(f, Materialfv, GL_FRONT, GL_SPECULAR, 1, 1, 1, 1);
    CMD(f, Normal3f, 0, 0, 1);
    quad(f, -1, -1, 1, 1, -3, 1, 1, 1);
}

static void fogged_quads(seq *f, GLenum mode, GLenum changed, double v)
{
    ortho(f);
    CMD(f, Enable, GL_FOG);
    CMD(f, Fogi, GL_FOG_MODE, mode);
    quad(f, 0.1, 0.1, 0.4, 0.4, 0, 1, 0, 0);
    CMD(f, Fogf, changed, v);
    quad(f, 0.5, 0.5, 0.9, 0.9, 0, 0, 1, 0);
}

static void test_other_notes(void)
{
    seq f;
    /* Fog that changes between fogged draws: said where the change is one
     * the mode uses, held where it is not (GL_LINEAR has no density). */
    seq_init(&f);
    fogged_quads(&f, GL_LINEAR, GL_FOG_DENSITY, 0.3);
    build(&f, true);
    expect("fog density under GL_LINEAR", DIAG_NOTE_FOG, 0, 1);
    seq_init(&f);
    fogged_quads(&f, GL_LINEAR, GL_FOG_END, 0.5);
    build(&f, true);
    expect("fog end under GL_LINEAR", DIAG_NOTE_FOG, 1, 0);
    seq_init(&f);
    fogged_quads(&f, GL_EXP, GL_FOG_END, 0.5);
    build(&f, true);
    expect("fog end under GL_EXP", DIAG_NOTE_FOG, 0, 1);

    /* Highlights the shadowed render approximates: said with shadows,
     * held without (--no-shadows). */
    seq_init(&f);
    lit_quad(&f);
    build(&f, true);
    expect("highlights, shadows", DIAG_NOTE_SHADOW_HIGHLIGHT, 1, 0);
    seq_init(&f);
    lit_quad(&f);
    build(&f, false);
    expect("highlights, no shadows", DIAG_NOTE_SHADOW_HIGHLIGHT, 0, 1);

    /* A spot whose specular differs from its diffuse: the shadowless
     * render's approximation, the other way round. */
    for (int sh = 0; sh < 2; sh++) {
        seq_init(&f);
        perspective(&f);
        CMD(&f, Enable, GL_LIGHTING);
        CMD(&f, Enable, GL_LIGHT0);
        CMD(&f, Lightfv, GL_LIGHT0, GL_POSITION, 0, 0, 0, 1);
        CMD(&f, Lightf, GL_LIGHT0, GL_SPOT_CUTOFF, 30);
        CMD(&f, Lightfv, GL_LIGHT0, GL_SPECULAR, 0.5, 0.5, 0.5, 1);
        CMD(&f, Normal3f, 0, 0, 1);
        quad(&f, -1, -1, 1, 1, -3, 1, 1, 1);
        build(&f, sh != 0);
        expect(sh ? "spot, shadows" : "spot, no shadows", DIAG_NOTE_SPOT_SPECULAR, !sh, sh);
    }

    /* Geometry in GL_SELECT: GL draws none of it either. */
    seq_init(&f);
    perspective(&f);
    CMD(&f, SelectBuffer, 64, 1);
    CMD(&f, RenderMode, GL_SELECT);
    quad(&f, -1, -1, 1, 1, -3, 1, 1, 1);
    build(&f, true);
    expect("select", DIAG_NOTE_RENDER_MODE, 0, 1);

    /* The point fade threshold: said where points are drawn, nothing
     * where none is. */
    seq_init(&f);
    ortho(&f);
    CMD(&f, PointParameterf, GL_POINT_FADE_THRESHOLD_SIZE, 4);
    quad(&f, 0.1, 0.1, 0.6, 0.6, 0, 1, 0, 0);
    build(&f, true);
    expect("point fade, no points", DIAG_NOTE_POINT_FADE, 0, 0);
    seq_init(&f);
    ortho(&f);
    CMD(&f, PointParameterf, GL_POINT_FADE_THRESHOLD_SIZE, 4);
    CMD(&f, Begin, GL_POINTS);
    CMD(&f, Vertex2f, 0.5, 0.5);
    CMD0(&f, End);
    build(&f, true);
    expect("point fade, a point", DIAG_NOTE_POINT_FADE, 1, 0);

    /* A colour-index evaluator map: its indices go unused in RGBA. */
    seq_init(&f);
    ortho(&f);
    map1f(&f, GL_MAP1_INDEX, 1, 2, (const float[]){0, 1}, 2);
    CMD(&f, Enable, GL_MAP1_INDEX);
    map1f(&f, GL_MAP1_VERTEX_3, 3, 2, (const float[]){0.1f, 0.1f, 0, 0.9f, 0.9f, 0}, 6);
    CMD(&f, Enable, GL_MAP1_VERTEX_3);
    CMD(&f, Begin, GL_LINE_STRIP);
    CMD(&f, EvalCoord1f, 0);
    CMD(&f, EvalCoord1f, 1);
    CMD0(&f, End);
    build(&f, true);
    expect("index evaluator", DIAG_NOTE_EVAL_INDEX, 0, 1);
}

/* A 16 x 16 mipmapped texture (GL_GENERATE_MIPMAP, of resource 1) under
 * a perspective camera, then draw(f). */
static void mip_frame(seq *f, GLenum filter)
{
    perspective(f);
    CMD(f, BindTexture, GL_TEXTURE_2D, 1);
    CMD(f, TexParameteri, GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    CMD(f, TexParameteri, GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    CMD(f, TexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, 1);
    CMD(f, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    CMD(f, Enable, GL_TEXTURE_2D);
}

/* Translates frame f (freed) with the texels of mip_frame as resource 1. */
static void build_mip(seq *f)
{
    static uint8_t px[16 * 16 * 3];
    for (size_t i = 0; i < sizeof px; i++)
        px[i] = (uint8_t)(i * 37 % 251);
    trace t;
    trace_init(&t);
    uint32_t id = 0;
    CHECK(rgl_trace_builder_resource(t.b, RGL_RES_BYTES, px, sizeof px, &id) == RGL_OK);
    CHECK_EQ_U(id, 1);
    trace_frame(&t, 0, 0, 0, 0, f);
    trace_finish(&t);
    seq_free(f);
    rgl_reader *r;
    CHECK(rgl_reader_open_memory(t.data, t.size, &r, NULL) == RGL_OK);
    translator *tr = translator_create(r, NULL);
    CHECK(tr != NULL);
    diag_clear(&dlog);
    frame_result res;
    if (tr)
        CHECK(translator_build(tr, 0, &dlog, &res) == RGL_OK);
    translator_destroy(tr);
    rgl_reader_destroy(r);
    trace_free(&t);
}

/* NOTE_TEX_MIPMAP: not logged on a receding flat quad (the writer's
 * planar run: GL's lambda per pixel) nor on a quad facing the camera
 * (one level); said on a folded strip, each triangle on a plane of its
 * own and drawn with one lambda, and in a display list (the writer draws
 * list copies with the base level). */
static void test_mip_notes(void)
{
    seq f;
    seq_init(&f);
    mip_frame(&f, GL_LINEAR_MIPMAP_LINEAR);
    CMD(&f, Begin, GL_QUADS);
    CMD(&f, TexCoord2f, 0, 0);
    CMD(&f, Vertex3f, -1, -1, -1.5);
    CMD(&f, TexCoord2f, 8, 0);
    CMD(&f, Vertex3f, 1, -1, -1.5);
    CMD(&f, TexCoord2f, 8, 8);
    CMD(&f, Vertex3f, 1, -1, -30);
    CMD(&f, TexCoord2f, 0, 8);
    CMD(&f, Vertex3f, -1, -1, -30);
    CMD0(&f, End);
    build_mip(&f);
    expect("mipmapped floor", DIAG_NOTE_TEX_MIPMAP, 0, 0);

    seq_init(&f);
    mip_frame(&f, GL_NEAREST_MIPMAP_NEAREST);
    CMD(&f, Begin, GL_QUADS);
    CMD(&f, TexCoord2f, 0, 0);
    CMD(&f, Vertex3f, -1, -1, -3);
    CMD(&f, TexCoord2f, 8, 0);
    CMD(&f, Vertex3f, 1, -1, -3);
    CMD(&f, TexCoord2f, 8, 8);
    CMD(&f, Vertex3f, 1, 1, -3);
    CMD(&f, TexCoord2f, 0, 8);
    CMD(&f, Vertex3f, -1, 1, -3);
    CMD0(&f, End);
    build_mip(&f);
    expect("mipmapped quad facing the camera", DIAG_NOTE_TEX_MIPMAP, 0, 0);

    for (int list = 0; list < 2; list++) {
        seq_init(&f);
        mip_frame(&f, GL_LINEAR_MIPMAP_LINEAR);
        if (list)
            CMD(&f, NewList, 1, GL_COMPILE_AND_EXECUTE);
        CMD(&f, Begin, GL_TRIANGLE_STRIP);
        for (int i = 0; i < 8; i++) {
            double x = -1 + 0.25 * i;
            CMD(&f, TexCoord2f, i * 2.0, (i % 2) * 4.0);
            CMD(&f, Vertex3f, x, (i % 2) ? 0.5 : -0.5, -2 - 3.0 * (i % 3) - 0.5 * i);
        }
        CMD0(&f, End);
        if (list)
            CMD0(&f, EndList);
        build_mip(&f);
        expect(list ? "mipmapped strip in a list" : "mipmapped folded strip", DIAG_NOTE_TEX_MIPMAP,
               1, 0);
    }
}

/* Clears that say what differs: a colour clear under a partial colour
 * mask over flat colours recolours them (no note), a scissored one
 * clears every channel (its own note, not the draws' colour mask);
 * a scissored depth clear between overlapping depth-tested quads keeps
 * the earlier in front inside its box (before: the later was put in
 * front everywhere, outside the box too, with no note). */
static void test_clear_notes(void)
{
    seq f;
    for (int scissored = 0; scissored < 2; scissored++) {
        seq_init(&f);
        ortho(&f);
        CMD(&f, Clear, GL_COLOR_BUFFER_BIT);
        quad(&f, 0.1, 0.1, 0.6, 0.6, 0, 1, 0, 0);
        CMD(&f, ColorMask, 1, 0, 1, 1);
        if (scissored) {
            CMD(&f, Enable, GL_SCISSOR_TEST);
            CMD(&f, Scissor, 16, 0, 16, 64);
        }
        CMD(&f, Clear, GL_COLOR_BUFFER_BIT);
        CMD(&f, Disable, GL_SCISSOR_TEST);
        CMD(&f, ColorMask, 1, 1, 1, 1);
        quad(&f, 0.3, 0.3, 0.9, 0.9, 0, 0, 1, 0);
        build(&f, true);
        /* flat colours recoloured exactly; a scissored one is cleared whole */
        expect(scissored ? "scissored partial colour mask clear" : "partial colour mask clear",
               DIAG_NOTE_CLEAR_COLOR_MASK, (uint64_t)scissored, 0);
        expect("partial colour mask clear (draws)", DIAG_NOTE_COLOR_MASK, 0, 0);
    }

    for (int scissored = 0; scissored < 2; scissored++) {
        seq_init(&f);
        ortho(&f);
        CMD(&f, Enable, GL_DEPTH_TEST);
        quad(&f, 0.1, 0.1, 0.9, 0.9, 0.5, 1, 0, 0); /* near (ndc z -0.5) */
        if (scissored) {
            CMD(&f, Enable, GL_SCISSOR_TEST);
            CMD(&f, Scissor, 16, 0, 16, 64);
        }
        CMD(&f, Clear, GL_DEPTH_BUFFER_BIT);
        CMD(&f, Disable, GL_SCISSOR_TEST);
        quad(&f, 0.2, 0.2, 0.8, 0.8, -0.5, 0, 1, 0); /* far, drawn over where cleared */
        build(&f, true);
        expect(scissored ? "scissored depth clear" : "depth clear", DIAG_NOTE_DEPTH_CLEAR,
               scissored ? 1 : 0, 0);
    }
}

int main(void)
{
    test_depth_order();
    test_other_notes();
    test_mip_notes();
    test_clear_notes();
    if (check_failures)
        fprintf(stderr, "test_notes: %d failure(s)\n", check_failures);
    return check_failures != 0;
}
