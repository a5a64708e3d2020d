/* test_shapes.c: issue 14's shapes in the interpreter.
 *
 * Quadric state and display lists: GLU quadric calls are client state,
 * done at compile time and never stored in a list, so a quadric state
 * command in a list body (the recorder writes a compiled shape's state
 * there) holds for the body alone; the quadric outside keeps its own.
 *
 * glPolygonOffset: an offset polygon draw moves one pixel along the
 * camera's rays (away for a positive offset), an offset shape is drawn as
 * GL's facets, lines are not moved, and a note says so.
 *
 * User clip planes: glClipPlane's plane in eye space as of its call,
 * triangles and solids carrying the enabled set in their look (written as
 * clipped_by planes after the matrix), lines cut with their colour
 * interpolated, points kept or dropped by their centre.
 *
 * Colour masks: a draw with every colour channel masked is left out (a
 * note when it writes depth); a partial mask is drawn, with a note.
 *
 * Line stipple: dashes cut in window space, the counter restarting per
 * GL_LINES segment, counted from where a line enters the window.
 *
 * The stencil test: a stencil-only pass (colour masked) keeps its
 * triangles as the region and draws nothing; GL_EQUAL keeps a draw inside
 * it, GL_NOTEQUAL outside, a test no value passes hides it; the writer
 * clips by the region's cones of rays; a second value over the region is
 * noted.
 *
 * The teapot mesh: its patches share their seam vertices (no two vertices
 * nearly equal), nothing is left just off the axis, the normals are unit,
 * and the writer declares RGL_Teapot as that mesh.
 */
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "outbuf.h"
#include "povwrite_clip.h"
#include "povwrite_solid.h"
#include "teapot_mesh.h"
#include "tracegen.h"

static void test_quadric_state_in_list(void)
{
    interp *ip = fresh();
    seq_init(&bodies[0]);
    CMD(&bodies[0], QuadricDrawStyle, 1, GLU_LINE);
    CMD(&bodies[0], Disk, 1, 0.25, 1.0, 8, 2);
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 64, 64);
    CMD(&s, NewQuadric, 1);
    CMD(&s, NewList, 1, GL_COMPILE, 1);
    CMD0(&s, EndList);
    CMD(&s, Translatef, 0, 0, -5);
    CMD(&s, CallList, 1);
    run(ip, &s);
    uint64_t lines = interp_frame_segments(ip);
    CHECK(lines > 0);           /* the body's GLU_LINE disk */
    CHECK_EQ_U(sc.nsolids, 0);
    seq_init(&s);
    CMD(&s, Disk, 1, 0.25, 1.0, 8, 2); /* the quadric's own style: GLU_FILL */
    run(ip, &s);
    CHECK_EQ_U(interp_frame_segments(ip), lines);
    CHECK_EQ_U(sc.nsolids, 1); /* a full filled disk is an exact disc */
    interp_destroy(ip);
    seq_free(&bodies[0]);
}

/* The eye-space z of the first vertex of mesh m. */
static double mesh_z(size_t m)
{
    const scene_mesh *me = &sc.meshes[m];
    const scene_vertex *v = &sc.verts[sc.tris[me->first_tri].v[0]];
    double in[4] = {v->pos[0], v->pos[1], v->pos[2], 1}, out[4];
    mat4_apply(&me->to_eye, in, out);
    return out[2];
}

static void test_polygon_offset(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Translatef, 0, 0, -10);
    CMD(&s, Begin, GL_TRIANGLES); /* not offset: the reference */
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, Enable, GL_POLYGON_OFFSET_FILL);
    CMD(&s, PolygonOffset, 1, 1);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, PolygonOffset, -1, -1);
    CMD(&s, Color3f, 0, 1, 0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, Begin, GL_LINES); /* lines: GL offsets polygons only */
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD0(&s, End);
    CMD(&s, NewQuadric, 1);
    CMD(&s, Sphere, 1, 1.0, 8, 4); /* offset: GL's facets, no true sphere */
    run(ip, &s);
    CHECK(sc.nmeshes >= 3);
    if (sc.nmeshes >= 3) {
        /* 10 units away, 100 pixels over a height of 2 at unit distance:
         * one pixel is 0.2 units there. */
        CHECK_NEAR(mesh_z(0), -10, 1e-9);
        CHECK_NEAR(mesh_z(1), -10.2, 1e-9);
        CHECK_NEAR(mesh_z(2), -9.8, 1e-9);
    }
    CHECK(sc.nlines == 1);
    CHECK_EQ_U(sc.nsolids, 0);
    CHECK(sc.ntris > 3);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_POLYGON_OFFSET].count, 1);
    interp_destroy(ip);
}

static int cmp_x(const void *a, const void *b)
{
    float x = (*(const float(*)[3])a)[0], y = (*(const float(*)[3])b)[0];
    return x < y ? -1 : x > y;
}

/* Edge (a, b) with a < b, for counting how many triangles use it. */
static int cmp_edge(const void *a, const void *b)
{
    const uint32_t *x = a, *y = b;
    return x[0] != y[0] ? (x[0] < y[0] ? -1 : 1) : x[1] != y[1] ? (x[1] < y[1] ? -1 : 1) : 0;
}

static void test_teapot_mesh(void)
{
    teapot_mesh m;
    int built = teapot_mesh_build(&m, 32);
    CHECK(built == 0);
    if (built != 0)
        return;
    CHECK(m.nverts > 30000 && m.nverts < 32 * 33 * 33);
    CHECK(m.ntris > 60000 && m.ntris <= 32 * 32 * 32 * 2);
    /* Seams shared: no two vertices within 1e-5 (sorted by x, then the
     * neighbours within that x). */
    float (*v)[3] = malloc(m.nverts * sizeof *v);
    size_t near = 0, off_axis = 0, not_unit = 0;
    CHECK(v != NULL);
    if (v) {
        memcpy(v, m.pos, m.nverts * sizeof *v);
        qsort(v, m.nverts, sizeof *v, cmp_x);
        for (size_t i = 0; i < m.nverts; i++)
            for (size_t j = i + 1; j < m.nverts && v[j][0] - v[i][0] < 1e-5f; j++)
                if (fabsf(v[j][1] - v[i][1]) < 1e-5f && fabsf(v[j][2] - v[i][2]) < 1e-5f)
                    near++;
        free(v);
    }
    for (size_t i = 0; i < m.nverts; i++) {
        double r = hypot(m.pos[i][0], m.pos[i][2]);
        if (r > 0 && r < 0.0025)
            off_axis++;
        double l = sqrt((double)m.normal[i][0] * m.normal[i][0] +
                        (double)m.normal[i][1] * m.normal[i][1] +
                        (double)m.normal[i][2] * m.normal[i][2]);
        if (fabs(l - 1) > 1e-5)
            not_unit++;
    }
    CHECK_EQ_U(near, 0);
    CHECK_EQ_U(off_axis, 0);
    CHECK_EQ_U(not_unit, 0);
    /* Edges used by one triangle only lie on the teapot's open rims (the
     * body's and the lid's, the spout's tip, the handle's ends): with
     * unshared seams each patch's whole border would be open. */
    uint32_t (*e)[2] = malloc(m.ntris * 3 * sizeof *e);
    CHECK(e != NULL);
    if (e) {
        size_t n = 0;
        for (size_t t = 0; t < m.ntris; t++)
            for (int k = 0; k < 3; k++) {
                uint32_t a = m.tri[t][k], b = m.tri[t][(k + 1) % 3];
                e[n][0] = a < b ? a : b;
                e[n][1] = a < b ? b : a;
                n++;
            }
        qsort(e, n, sizeof *e, cmp_edge);
        size_t open = 0;
        for (size_t i = 0; i < n;) {
            size_t j = i + 1;
            while (j < n && cmp_edge(e[i], e[j]) == 0)
                j++;
            open += j - i == 1;
            i = j;
        }
        CHECK(open > 0 && open < 1000);
        printf("teapot mesh: %zu vertices, %zu triangles, %zu open edges\n", m.nverts, m.ntris,
               open);
        free(e);
    }
    teapot_mesh_free(&m);

    scene_reset(&sc);
    scene_solid *so = scene_add_solid(&sc);
    CHECK(so != NULL);
    if (so)
        so->kind = SCENE_SOLID_TEAPOT;
    outbuf ob;
    int ok = outbuf_init(&ob, 1 << 24, NULL, NULL);
    CHECK(ok == 0);
    if (ok == 0) {
        povwrite_solid_declares(&ob, &sc);
        outbuf_putc(&ob, '\0');
        CHECK(ob.len > 0 && strstr(ob.buf, "#declare RGL_Teapot=mesh2{") != NULL);
        CHECK(strstr(ob.buf, "bicubic_patch") == NULL);
        outbuf_finish(&ob);
    }
}

static void test_clip_planes(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Translatef, 1, 0, -10);
    /* x >= 0 in this space: x_eye >= 1 in eye space. */
    CMD(&s, ClipPlane, GL_CLIP_PLANE2, 1, 0, 0, 0);
    CMD(&s, ClipPlane, GL_CLIP_PLANE0 + 8, 1, 0, 0, 0); /* past Mesa's 8 */
    CMD0(&s, LoadIdentity); /* does not move the plane */
    CMD(&s, Translatef, 0, 0, -10);
    CMD(&s, Begin, GL_TRIANGLES); /* not clipped yet */
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, Enable, GL_CLIP_PLANE2);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, Begin, GL_LINES);
    CMD(&s, Color3f, 0, 0, 0);
    CMD(&s, Vertex2f, 0, 0.5);
    CMD(&s, Color3f, 1, 1, 1);
    CMD(&s, Vertex2f, 2, 0.5); /* cut at its middle: colour 0.5 there */
    CMD(&s, Vertex2f, -1, 0);  /* wholly clipped */
    CMD(&s, Vertex2f, 0.5, 0);
    CMD0(&s, End);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex2f, 0.9, 0); /* dropped */
    CMD(&s, Vertex2f, 1.1, 0); /* kept */
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(dlog.e[DIAG_GL_INVALID_ENUM].count, 1);
    CHECK(sc.nmeshes == 2);
    if (sc.nmeshes == 2) {
        CHECK_EQ_U(sc.meshes[0].look.clip, 0);
        uint32_t n = 0;
        const double(*p)[4] = scene_clip_set(&sc, sc.meshes[1].look.clip, &n);
        CHECK(p != NULL && n == 1);
        if (p && n == 1) {
            CHECK_NEAR(p[0][0], 1, 1e-12);
            CHECK_NEAR(p[0][1], 0, 1e-12);
            CHECK_NEAR(p[0][2], 0, 1e-12);
            CHECK_NEAR(p[0][3], -1, 1e-12);
        }
    }
    CHECK(sc.nlines == 1);
    if (sc.nlines == 1) {
        CHECK_NEAR(sc.lines[0].p[0][0], 1, 1e-6);
        CHECK_NEAR(sc.lines[0].p[1][0], 2, 1e-6);
        CHECK_NEAR(sc.lines[0].color[0][0], 0.5, 1e-6);
        CHECK_NEAR(sc.lines[0].color[2][0], 1, 1e-6);
    }
    CHECK(sc.npoints == 1);
    if (sc.npoints == 1)
        CHECK_NEAR(sc.points[0].p[0], 1.1, 1e-6);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_CLIP_PLANE].count, 0);

    outbuf ob;
    int ok = outbuf_init(&ob, 1 << 20, NULL, NULL);
    CHECK(ok == 0);
    if (ok == 0 && sc.nmeshes == 2) {
        povwrite_clip(&ob, &sc, &sc.meshes[1].look);
        outbuf_putc(&ob, '\0');
        CHECK(strcmp(ob.buf, "clipped_by{plane{<-1,0,0>,-1}}\n") == 0);
        if (check_failures)
            printf("%s", ob.buf);
    }
    if (ok == 0)
        outbuf_finish(&ob);
    interp_destroy(ip);
}

static void tri(seq *s)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, 0, 0, -5);
    CMD(s, Vertex3f, 1, 0, -5);
    CMD(s, Vertex3f, 0, 1, -5);
    CMD0(s, End);
}

static void test_color_mask(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, ColorMask, 0, 0, 0, 0);
    CMD(&s, DepthMask, 0);
    tri(&s); /* a stencil-only pass: nothing, no note */
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 0);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_DEPTH_ONLY].count, 0);
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, DepthMask, 1);
    tri(&s); /* a depth-only pass: nothing, and a note */
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 0);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_DEPTH_ONLY].count, 1);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_COLOR_MASK].count, 0);
    seq_init(&s);
    CMD(&s, ColorMask, 1, 0, 1, 1);
    tri(&s); /* drawn whole, noted */
    CMD(&s, ColorMask, 1, 1, 1, 0);
    tri(&s); /* alpha alone masked: drawn */
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 2);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_COLOR_MASK].count, 1);
    interp_destroy(ip);
}

static void test_line_stipple(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Ortho, 0, 100, 0, 100, -1, 1);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_LINE_STIPPLE);
    CMD(&s, LineStipple, 1, 0x00FF); /* 8 on, 8 off */
    CMD(&s, Begin, GL_LINES);
    CMD(&s, Vertex2f, 10, 50.5);
    CMD(&s, Vertex2f, 42, 50.5); /* 32 fragments: dashes 0-8, 16-24 */
    CMD(&s, Vertex2f, 10, 60.5);
    CMD(&s, Vertex2f, 14, 60.5); /* restarts: one dash 0-4 */
    CMD0(&s, End);
    run(ip, &s);
    CHECK(sc.nlines == 3);
    if (sc.nlines == 3) {
        /* eye x = window x under this ortho; each dash spans the pixels
         * it lights (Mesa, measured: 9 to 17, 26 to 33 and 10 to 13: its
         * float puts the first dash's start a hair left of 10, in pixel
         * 9's diamond) */
        CHECK_NEAR(sc.lines[0].p[0][0], 9, 1e-4);
        CHECK_NEAR(sc.lines[0].p[1][0], 18, 1e-4);
        CHECK_NEAR(sc.lines[1].p[0][0], 26, 1e-4);
        CHECK_NEAR(sc.lines[1].p[1][0], 34, 1e-4);
        CHECK_NEAR(sc.lines[2].p[0][0], 10, 1e-4);
        CHECK_NEAR(sc.lines[2].p[1][0], 14, 1e-4);
    }
    size_t before = sc.nlines;
    seq_init(&s);
    CMD(&s, LineStipple, 1000, 0x0001); /* factor clamped to 256: all on */
    CMD(&s, Begin, GL_LINE_STRIP);
    CMD(&s, Vertex2f, 0, 20.5);
    CMD(&s, Vertex2f, 300, 20.5); /* counted from the window: 100 on */
    CMD(&s, Vertex2f, 300, 30.5);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nlines - before, 1);
    if (sc.nlines - before == 1) {
        CHECK_NEAR(sc.lines[before].p[0][0], 0, 1e-4);
        CHECK_NEAR(sc.lines[before].p[1][0], 100, 1e-4);
    }
    /* Dashes as Mesa cuts them: nothing to say (shapes_line_stipple
     * exact); outlined polygons restart the pattern elsewhere: said. */
    CHECK_EQ_U(dlog.e[DIAG_NOTE_STIPPLE].count, 0);
    seq_init(&s);
    CMD(&s, PolygonMode, GL_FRONT_AND_BACK, GL_LINE);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 10, 10);
    CMD(&s, Vertex2f, 40, 10);
    CMD(&s, Vertex2f, 20, 40);
    CMD0(&s, End);
    run(ip, &s);
    CHECK(dlog.e[DIAG_NOTE_STIPPLE].count > 0);
    interp_destroy(ip);
}

static void test_stencil(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Clear, GL_STENCIL_BUFFER_BIT);
    CMD(&s, Enable, GL_STENCIL_TEST);
    CMD(&s, StencilFunc, GL_ALWAYS, 1, 255);
    CMD(&s, StencilOp, GL_KEEP, GL_KEEP, GL_REPLACE);
    CMD(&s, ColorMask, 0, 0, 0, 0);
    tri(&s); /* the region: one triangle, nothing drawn */
    CMD(&s, ColorMask, 1, 1, 1, 1);
    CMD(&s, StencilOp, GL_KEEP, GL_KEEP, GL_KEEP);
    CMD(&s, StencilFunc, GL_EQUAL, 1, 255);
    tri(&s); /* inside */
    CMD(&s, StencilFunc, GL_NOTEQUAL, 1, 255);
    CMD(&s, Color3f, 1, 0, 0);
    tri(&s); /* outside */
    CMD(&s, StencilFunc, GL_EQUAL, 2, 255);
    tri(&s); /* passes nowhere: hidden */
    run(ip, &s);
    CHECK_EQ_U(sc.nstencil, 1);
    CHECK_EQ_U(sc.ntris, 2);
    CHECK_EQ_U(sc.nmeshes, 2);
    if (sc.nmeshes == 2) {
        CHECK_EQ_U(sc.meshes[0].look.stencil_n, 1);
        CHECK_EQ_U(sc.meshes[0].look.stencil_out, 0);
        CHECK_EQ_U(sc.meshes[1].look.stencil_n, 1);
        CHECK_EQ_U(sc.meshes[1].look.stencil_out, 1);
        outbuf ob;
        int ok = outbuf_init(&ob, 1 << 20, NULL, NULL);
        CHECK(ok == 0);
        if (ok == 0) {
            povwrite_stencil(&ob, &sc, &sc.meshes[1].look);
            outbuf_putc(&ob, '\0');
            CHECK(strncmp(ob.buf, "clipped_by{union{intersection{plane{", 36) == 0);
            CHECK(strstr(ob.buf, " inverse}}") != NULL);
            outbuf_finish(&ob);
        }
    }
    CHECK_EQ_U(dlog.e[DIAG_NOTE_STENCIL].count, 0);
    /* Another value written over the region: not followed, noted. */
    seq_init(&s);
    CMD(&s, StencilFunc, GL_ALWAYS, 3, 255);
    CMD(&s, StencilOp, GL_KEEP, GL_KEEP, GL_REPLACE);
    tri(&s);
    run(ip, &s);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_STENCIL].count, 1);
    interp_destroy(ip);
}

/* Issue 22: a list of a tessellated shape called many times and shared
 * holds its facets once; the frame's cap on facets (2^21) counts them so.
 * Before, the 1025th call of a 2048-facet sphere was skipped. */
static void test_shared_facets(void)
{
    interp *ip = fresh();
    seq_init(&bodies[0]);
    CMD(&bodies[0], SolidSphere, 0.5, 64, 32); /* 2048 facets; flat lit: tessellated */
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 64, 64);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Ortho, -20, 20, -20, 20, 1, 100); /* each call faces the camera alike */
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, ShadeModel, GL_FLAT);
    CMD(&s, NewList, 1, GL_COMPILE, 1);
    CMD0(&s, EndList);
    CMD(&s, Translatef, 0, 0, -50);
    for (int i = 0; i < 1100; i++) {
        CMD(&s, Translatef, 0.01, 0, 0);
        CMD(&s, CallList, 1);
    }
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_IGNORED), 0);
    CHECK_EQ_U(sc.nsolids, 0);
    CHECK_EQ_U(sc.ninstances, 1100);
    CHECK(sc.ntris <= 2 * 2048);
    interp_destroy(ip);
    seq_free(&bodies[0]);
}

/* The triangle of tri() wound clockwise: a back face under GL_CCW. */
static void tri_cw(seq *s)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, 0, 0, -5);
    CMD(s, Vertex3f, 0, 1, -5);
    CMD(s, Vertex3f, 1, 0, -5);
    CMD0(s, End);
}

/* glStencil*Separate: a back face that does not write stays out of the
 * region; faces tested differently are exact while one facing is drawn
 * (culling chooses the back state), noted once a back face takes the
 * front's; a bad face is an invalid enum. */
static void test_stencil_two_side(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Clear, GL_STENCIL_BUFFER_BIT);
    CMD(&s, Enable, GL_STENCIL_TEST);
    CMD(&s, StencilFunc, GL_ALWAYS, 1, 255);
    CMD(&s, StencilOp, GL_KEEP, GL_KEEP, GL_REPLACE);
    CMD(&s, StencilOpSeparate, GL_BACK, GL_KEEP, GL_KEEP, GL_KEEP);
    CMD(&s, StencilOpSeparate, GL_LEFT, GL_KEEP, GL_KEEP, GL_KEEP); /* refused */
    CMD(&s, ColorMask, 0, 0, 0, 0);
    tri_cw(&s); /* back: writes nothing */
    tri(&s);    /* front: the region */
    CMD(&s, ColorMask, 1, 1, 1, 1);
    CMD(&s, StencilOp, GL_KEEP, GL_KEEP, GL_KEEP);
    CMD(&s, StencilFuncSeparate, GL_FRONT, GL_EQUAL, 1, 255);
    CMD(&s, StencilFuncSeparate, GL_BACK, GL_NOTEQUAL, 1, 255);
    tri(&s); /* front faces only: inside, exact */
    CMD(&s, Enable, GL_CULL_FACE);
    CMD(&s, CullFace, GL_FRONT);
    tri_cw(&s); /* back faces only: outside, exact */
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK_EQ_U(sc.nstencil, 1);
    CHECK_EQ_U(sc.nmeshes, 2);
    if (sc.nmeshes == 2) {
        CHECK_EQ_U(sc.meshes[0].look.stencil_out, 0);
        CHECK_EQ_U(sc.meshes[1].look.stencil_out, 1);
    }
    CHECK_EQ_U(count(DIAG_NOTE_STENCIL_TWO_SIDE), 0);
    CHECK_EQ_U(count(DIAG_NOTE_STENCIL), 0);
    seq_init(&s);
    CMD(&s, Disable, GL_CULL_FACE);
    tri_cw(&s); /* a back face under the front faces' test: noted */
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_STENCIL_TWO_SIDE), 1);
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_bodies;
    nbodies = 1; /* the one list body, bodies[0] */
    test_quadric_state_in_list();
    test_polygon_offset();
    test_teapot_mesh();
    test_clip_planes();
    test_color_mask();
    test_line_stipple();
    test_stencil();
    test_shared_facets();
    test_stencil_two_side();
    scene_finish(&sc);
    return CHECK_RESULT("test_shapes");
}
