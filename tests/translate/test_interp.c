/* test_interp.c: the GL state machine, against hand-computed values.
 *
 * Matrices (the paper's modelview, every transform call, GLU's helpers,
 * @Matrix), stack limits, calls GL rejects, primitive assembly of all ten
 * glBegin modes with winding and provoking vertex, culling, polygon mode
 * and edge flags, attribute conversion, attribute stack, mesh runs, and
 * glClear erasing earlier draws.
 */
#include <GL/gl.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "frame.h"
#include "povwrite.h"
#include "interp.h"
#include "interp_internal.h"
#include "talloc.h"
#include "scenes.h"
#include "tracegen.h"

static void check_matrix(const mat4 *m, const double *expect, double eps)
{
    for (int i = 0; i < 16; i++)
        CHECK_NEAR(m->m[i], expect[i], eps);
}

/* ---- Matrices ------------------------------------------------------------------ */

static void test_paper_modelview(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, Translatef, 45, 45, 45);
    CMD(&s, Rotatef, 45, 1, -1, 0);
    run(ip, &s);
    /* The matrix the paper printed, column by column. */
    const double paper[16] = {0.853553, -0.146447, 0.5,      0, -0.146447, 0.853553, 0.5, 0,
                              -0.5,     -0.5,      0.707107, 0, 45,        45,       45,  1};
    check_matrix(interp_matrix(ip, INTERP_MV), paper, 1e-6);
    interp_destroy(ip);
}

static void test_transforms(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Scaled, 2, 3, 4);
    CMD(&s, Rotated, 90, 0, 0, 1);
    run(ip, &s);
    const double sr[16] = {0, 3, 0, 0, -2, 0, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1};
    check_matrix(interp_matrix(ip, INTERP_MV), sr, 1e-12);

    /* Load/Mult and their transposes. */
    seq_init(&s);
    CMD(&s, LoadMatrixf, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    run(ip, &s);
    const double ld[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
    check_matrix(interp_matrix(ip, INTERP_MV), ld, 0);
    seq_init(&s);
    CMD(&s, LoadTransposeMatrixd, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16);
    run(ip, &s);
    const double lt[16] = {1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 4, 8, 12, 16};
    check_matrix(interp_matrix(ip, INTERP_MV), lt, 0);
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, MultTransposeMatrixf, 1, 0, 0, 7, 0, 1, 0, 8, 0, 0, 1, 9, 0, 0, 0, 1);
    CMD(&s, MultMatrixd, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 1, 1, 1);
    run(ip, &s);
    const double tm[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 8, 9, 10, 1};
    check_matrix(interp_matrix(ip, INTERP_MV), tm, 1e-12);

    /* glFrustum(-1, 1, -1, 1, 1, 3): the GL 1.x formula by hand. */
    seq_init(&s);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -2, 1, -1, 1, 1, 3);
    run(ip, &s);
    const double fr[16] = {2.0 / 3, 0, 0, 0, 0, 1, 0, 0, -1.0 / 3, 0, -2, -1, 0, 0, -3, 0};
    check_matrix(interp_matrix(ip, INTERP_PROJ), fr, 1e-12);
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, Ortho, 0, 4, 0, 2, -1, 3);
    run(ip, &s);
    const double orth[16] = {0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -0.5, 0, -1, -1, -0.5, 1};
    check_matrix(interp_matrix(ip, INTERP_PROJ), orth, 1e-12);
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, Ortho2D, 0, 320, 0, 240);
    run(ip, &s);
    const double o2[16] = {2.0 / 320, 0, 0, 0, 0, 2.0 / 240, 0, 0, 0, 0, -1, 0, -1, -1, 0, 1};
    check_matrix(interp_matrix(ip, INTERP_PROJ), o2, 1e-12);

    /* gluPerspective(90, 2, 1, 3) as GLU computes it: cot(45) = 1. */
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, Perspective, 90, 2, 1, 3);
    run(ip, &s);
    const double pe[16] = {0.5, 0, 0, 0, 0, 1, 0, 0, 0, 0, -2, -1, 0, 0, -3, 0};
    check_matrix(interp_matrix(ip, INTERP_PROJ), pe, 1e-12);
    /* gluPerspective with a zero depth range: GLU does nothing. */
    seq_init(&s);
    CMD(&s, Perspective, 60, 1, 2, 2);
    run(ip, &s);
    check_matrix(interp_matrix(ip, INTERP_PROJ), pe, 1e-12);

    /* gluLookAt from (1, 2, 5) at (1, 2, 0), up y: a translation by -eye. */
    seq_init(&s);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD0(&s, LoadIdentity);
    CMD(&s, LookAt, 1, 2, 5, 1, 2, 0, 0, 1, 0);
    run(ip, &s);
    const double la[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -1, -2, -5, 1};
    check_matrix(interp_matrix(ip, INTERP_MV), la, 1e-7);
    /* Looking down -x from the origin: side = +z... GLU's rows. */
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, LookAt, 0, 0, 0, -1, 0, 0, 0, 1, 0);
    run(ip, &s);
    const double lx[16] = {0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 0, 1};
    check_matrix(interp_matrix(ip, INTERP_MV), lx, 1e-7);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 0);

    /* @Matrix replaces the top of its stack, whatever the mode. */
    seq_init(&s);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Matrix, GL_PROJECTION, 9, 0, 0, 0, 0, 9, 0, 0, 0, 0, 9, 0, 0, 0, 0, 1);
    run(ip, &s);
    CHECK_NEAR(interp_matrix(ip, INTERP_PROJ)->m[0], 9, 0);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[0], 0, 1e-7);
    CHECK(interp_state(ip)->a.transform.matrix_mode == GL_MODELVIEW);
    interp_destroy(ip);
}

static void test_stacks(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    for (int i = 0; i < INTERP_MODELVIEW_DEPTH - 1; i++)
        CMD0(&s, PushMatrix);
    run(ip, &s);
    CHECK_EQ_U(interp_state(ip)->depth[INTERP_MV], INTERP_MODELVIEW_DEPTH - 1);
    CHECK_EQ_U(count(DIAG_GL_STACK_OVERFLOW), 0);
    seq_init(&s);
    CMD(&s, Translatef, 1, 2, 3);
    CMD0(&s, PushMatrix); /* the 33rd entry: GL_STACK_OVERFLOW */
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_STACK_OVERFLOW), 1);
    CHECK_EQ_U(interp_state(ip)->depth[INTERP_MV], INTERP_MODELVIEW_DEPTH - 1);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 1, 0);
    seq_init(&s);
    for (int i = 0; i < INTERP_MODELVIEW_DEPTH; i++)
        CMD0(&s, PopMatrix);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_STACK_UNDERFLOW), 1);
    CHECK_EQ_U(interp_state(ip)->depth[INTERP_MV], 0);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 0, 0);

    /* Projection and texture stacks hold two. */
    seq_init(&s);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD0(&s, PushMatrix);
    CMD0(&s, PushMatrix);
    CMD(&s, MatrixMode, GL_TEXTURE);
    CMD0(&s, PushMatrix);
    CMD0(&s, PushMatrix);
    CMD0(&s, PopMatrix);
    CMD0(&s, PopMatrix);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_STACK_OVERFLOW), 3);
    CHECK_EQ_U(count(DIAG_GL_STACK_UNDERFLOW), 2);
    CHECK_EQ_U(interp_state(ip)->depth[INTERP_PROJ], 1);

    /* Attribute stack: depth 16, and what it restores. */
    seq_init(&s);
    CMD(&s, LineWidth, 3);
    CMD(&s, Enable, GL_CULL_FACE);
    CMD(&s, PushAttrib, GL_LINE_BIT | GL_ENABLE_BIT);
    CMD(&s, LineWidth, 7);
    CMD(&s, PointSize, 5);
    CMD(&s, Disable, GL_CULL_FACE);
    CMD0(&s, PopAttrib);
    run(ip, &s);
    CHECK_NEAR(interp_state(ip)->a.line.width, 3, 0);
    CHECK_NEAR(interp_state(ip)->a.point.size, 5, 0);
    CHECK(interp_state(ip)->a.caps[INTERP_CAP_CULL_FACE]);
    seq_init(&s);
    for (int i = 0; i <= INTERP_ATTRIB_DEPTH; i++)
        CMD(&s, PushAttrib, GL_ALL_ATTRIB_BITS);
    for (int i = 0; i <= INTERP_ATTRIB_DEPTH; i++)
        CMD0(&s, PopAttrib);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_STACK_OVERFLOW), 4);
    CHECK_EQ_U(count(DIAG_GL_STACK_UNDERFLOW), 3);
    interp_destroy(ip);
}

static void test_rejected(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, MatrixMode, 0x1234);          /* invalid enum */
    CMD(&s, Enable, 0x9999);              /* invalid enum */
    CMD(&s, Frustum, -1, 1, -1, 1, 0, 5); /* near 0: invalid value */
    CMD(&s, Ortho, 1, 1, -1, 1, 0, 5);    /* empty range: invalid value */
    CMD(&s, LineWidth, 0);                /* invalid value */
    CMD(&s, Viewport, 0, 0, -5, 10);      /* invalid value */
    CMD0(&s, End);                        /* without Begin: invalid operation */
    CMD(&s, Begin, 77);                   /* invalid enum */
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Translatef, 5, 5, 5);         /* inside Begin: invalid operation */
    CMD(&s, Begin, GL_LINES);             /* nested: invalid operation */
    CMD(&s, Color3f, 0.5, 0.5, 0.5);      /* allowed */
    CMD(&s, Vertex3f, 0, 0, 0);
    CMD0(&s, End);
    CMD(&s, ShadeModel, GL_LINE);         /* invalid enum */
    CMD(&s, PolygonMode, GL_FRONT, GL_FRONT); /* invalid enum */
    CMD(&s, Lightfv, GL_LIGHT0 + 9, GL_POSITION, 0, 0, 1, 0); /* invalid enum */
    CMD(&s, Lightfv, GL_LIGHT0, 0x1299, 0, 0, 1, 0);         /* invalid enum */
    CMD(&s, Materialf, GL_FRONT, GL_SHININESS, 200);         /* invalid value */
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 7);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 5);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 3);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 0, 0);
    CHECK(interp_state(ip)->a.transform.matrix_mode == GL_MODELVIEW);
    CHECK_NEAR(interp_state(ip)->a.line.width, 1, 0);
    /* The message names frame, command, call and offset. */
    CHECK(strstr(dlog.e[DIAG_GL_INVALID_ENUM].text[0], "frame 0, cmd 0 (glMatrixMode) @0x") ==
          dlog.e[DIAG_GL_INVALID_ENUM].text[0]);
    CHECK(strstr(dlog.e[DIAG_GL_INVALID_ENUM].text[0], "invalid matrix mode 0x1234") != NULL);
    interp_destroy(ip);
}

/* ---- Assembly ------------------------------------------------------------------- */

typedef struct tri3 {
    uint32_t a, b, c, p;
} tri3;

/* Draws n vertices (x = i, y = i*i % 7, distinct colours) in `mode` and
 * returns the triangles relative to the first vertex. */
static size_t draw(interp *ip, GLenum mode, int n, tri3 *out)
{
    seq s;
    seq_init(&s);
    size_t base = sc.nverts, t0 = sc.ntris;
    CMD(&s, Begin, mode);
    for (int i = 0; i < n; i++) {
        CMD(&s, Color3ub, (double)(i * 20), 0, 0);
        CMD(&s, Vertex3f, i, (i * i) % 7, 0);
    }
    CMD0(&s, End);
    run(ip, &s);
    size_t k = 0;
    for (size_t t = t0; t < sc.ntris; t++, k++) {
        out[k].a = sc.tris[t].v[0] - (uint32_t)base;
        out[k].b = sc.tris[t].v[1] - (uint32_t)base;
        out[k].c = sc.tris[t].v[2] - (uint32_t)base;
        out[k].p = sc.tris[t].provoking - (uint32_t)base;
    }
    return k;
}

static void expect_tris(interp *ip, GLenum mode, int n, const tri3 *want, size_t nwant)
{
    tri3 got[64];
    size_t k = draw(ip, mode, n, got);
    CHECK_EQ_U(k, nwant);
    for (size_t i = 0; i < k && i < nwant; i++) {
        if (memcmp(&got[i], &want[i], sizeof got[i]) != 0) {
            fprintf(stderr, "mode 0x%x, n %d, tri %zu: got (%u %u %u p%u), want (%u %u %u p%u)\n",
                    mode, n, i, got[i].a, got[i].b, got[i].c, got[i].p, want[i].a, want[i].b,
                    want[i].c, want[i].p);
            check_failures++;
        }
    }
}

static void test_assembly(void)
{
    interp *ip = fresh();
    static const tri3 tris[] = {{0, 1, 2, 2}, {3, 4, 5, 5}};
    expect_tris(ip, GL_TRIANGLES, 7, tris, 2); /* the 7th vertex is dropped */
    static const tri3 strip[] = {{0, 1, 2, 2}, {2, 1, 3, 3}, {2, 3, 4, 4}};
    expect_tris(ip, GL_TRIANGLE_STRIP, 5, strip, 3);
    static const tri3 fan[] = {{0, 1, 2, 2}, {0, 2, 3, 3}, {0, 3, 4, 4}};
    expect_tris(ip, GL_TRIANGLE_FAN, 5, fan, 3);
    /* Some of these vertices lie outside the view volume: Mesa's clipper
     * then splits quads along v1-v3 (docs/mapping.md). */
    static const tri3 quads[] = {{0, 1, 3, 3}, {1, 2, 3, 3}, {4, 5, 7, 7}, {5, 6, 7, 7}};
    expect_tris(ip, GL_QUADS, 9, quads, 4);
    static const tri3 qstrip[] = {{0, 1, 3, 3}, {0, 3, 2, 3}, {2, 3, 5, 5}, {2, 5, 4, 5}};
    expect_tris(ip, GL_QUAD_STRIP, 7, qstrip, 4);
    static const tri3 poly[] = {{0, 1, 2, 0}, {0, 2, 3, 0}, {0, 3, 4, 0}};
    expect_tris(ip, GL_POLYGON, 5, poly, 3);
    /* Incomplete primitives draw nothing. */
    expect_tris(ip, GL_TRIANGLES, 2, NULL, 0);
    expect_tris(ip, GL_TRIANGLE_STRIP, 2, NULL, 0);
    expect_tris(ip, GL_TRIANGLE_FAN, 2, NULL, 0);
    expect_tris(ip, GL_QUADS, 3, NULL, 0);
    expect_tris(ip, GL_QUAD_STRIP, 3, NULL, 0);
    expect_tris(ip, GL_POLYGON, 2, NULL, 0);

    /* Points and lines leave the vertex pool and become items: the
     * segments GL assembles (2, 3 more, 4 more), of which only what falls
     * in the view volume lights pixels. Here (identity projection, x = i,
     * y = i * i % 7) that is the segment from (0, 0) to (1, 1) each time
     * and a loop's closing segment from (3, 2) to (0, 0), in from x = 1. */
    tri3 none[4];
    size_t v0 = sc.nverts;
    draw(ip, GL_POINTS, 3, none);
    CHECK_EQ_U(sc.npoints, 2); /* (2, 4) is outside the view volume: GL drops it */
    draw(ip, GL_LINES, 5, none);
    CHECK_EQ_U(interp_frame_segments(ip), 2);
    CHECK_EQ_U(sc.nlines, 1);
    draw(ip, GL_LINE_STRIP, 4, none);
    CHECK_EQ_U(interp_frame_segments(ip), 5);
    CHECK_EQ_U(sc.nlines, 2);
    draw(ip, GL_LINE_LOOP, 4, none);
    CHECK_EQ_U(interp_frame_segments(ip), 9);
    CHECK_EQ_U(sc.nlines, 4);
    draw(ip, GL_LINE_LOOP, 1, none);
    CHECK_EQ_U(interp_frame_segments(ip), 9);
    CHECK_EQ_U(sc.nverts, v0);

    /* glFrontFace(GL_CW): stored front-first counter-clockwise. */
    seq s;
    seq_init(&s);
    CMD(&s, FrontFace, GL_CW);
    run(ip, &s);
    static const tri3 cw[] = {{0, 2, 1, 2}};
    expect_tris(ip, GL_TRIANGLES, 3, cw, 1);
    interp_destroy(ip);
}

static void test_flat_lines(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, ShadeModel, GL_FLAT);
    CMD(&s, Begin, GL_LINE_LOOP);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Color3f, 0, 1, 0);
    CMD(&s, Vertex2f, 0.5, 0);
    CMD(&s, Color3f, 0, 0, 1);
    CMD(&s, Vertex2f, 0.5, 0.5);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nlines, 3);
    if (sc.nlines == 3) {
        /* Each segment takes its last vertex's colour; the closing one the
         * first vertex's (GL 1.x table 2.2). */
        CHECK(sc.lines[0].color[0][1] == 1 && sc.lines[0].color[2][1] == 1);
        CHECK(sc.lines[1].color[0][2] == 1 && sc.lines[1].color[2][2] == 1);
        CHECK(sc.lines[2].color[0][0] == 1 && sc.lines[2].color[2][0] == 1);
    }
    interp_destroy(ip);
}

static void test_culling(void)
{
    interp *ip = fresh();
    tri3 t[8];
    seq s;
    /* Vertex i is (i, i*i % 7): (0,0) (1,1) (2,4) turns left: CCW. */
    seq_init(&s);
    CMD(&s, Enable, GL_CULL_FACE);
    run(ip, &s);
    CHECK_EQ_U(draw(ip, GL_TRIANGLES, 3, t), 1); /* CCW front kept */
    seq_init(&s);
    CMD(&s, FrontFace, GL_CW);
    run(ip, &s);
    CHECK_EQ_U(draw(ip, GL_TRIANGLES, 3, t), 0); /* now a back face */
    seq_init(&s);
    CMD(&s, CullFace, GL_FRONT);
    run(ip, &s);
    CHECK_EQ_U(draw(ip, GL_TRIANGLES, 3, t), 1);
    seq_init(&s);
    CMD(&s, CullFace, GL_FRONT_AND_BACK);
    run(ip, &s);
    CHECK_EQ_U(draw(ip, GL_QUADS, 4, t), 0);
    CHECK_EQ_U(draw(ip, GL_POINTS, 2, t), 0);
    CHECK_EQ_U(sc.npoints, 2); /* culling spares points and lines */
    seq_init(&s);
    CMD(&s, FrontFace, GL_CCW);
    CMD(&s, CullFace, GL_BACK);
    run(ip, &s);
    /* A strip: its second triangle is taken (2, 1, 3), which faces the same
     * way as the first here: both are kept. */
    CHECK_EQ_U(draw(ip, GL_TRIANGLE_STRIP, 4, t), 2);
    /* With (4,2) the third triangle (2,3,4) turns left as well: 3 kept. A
     * fan (0,0) (1,1) (2,4) (3,2): (0,2,3) turns right and is culled. */
    CHECK_EQ_U(draw(ip, GL_TRIANGLE_STRIP, 5, t), 3);
    CHECK_EQ_U(draw(ip, GL_TRIANGLE_FAN, 4, t), 1);
    interp_destroy(ip);
}

static void test_polygon_mode(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, PolygonMode, GL_FRONT_AND_BACK, GL_LINE);
    CMD(&s, Begin, GL_QUADS);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 0.5, 0);
    CMD(&s, Vertex2f, 0.5, 0.5);
    CMD(&s, Vertex2f, 0, 0.5);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 0);
    CHECK_EQ_U(sc.nlines, 4); /* the outline, not the diagonal */
    seq_init(&s);
    CMD(&s, Begin, GL_POLYGON);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, EdgeFlag, 0);
    CMD(&s, Vertex2f, 0.5, 0); /* the edge from here is not a boundary */
    CMD(&s, EdgeFlag, 1);
    CMD(&s, Vertex2f, 0.5, 0.5);
    CMD(&s, Vertex2f, 0, 0.5);
    CMD0(&s, End);
    CMD(&s, PolygonMode, GL_FRONT, GL_POINT);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 0.5, 0);
    CMD(&s, Vertex2f, 0.5, 0.5);
    CMD(&s, Vertex2f, 0, 0); /* clockwise: a back face, still lines */
    CMD(&s, Vertex2f, 0.5, 0.5);
    CMD(&s, Vertex2f, 0.5, 0);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nlines, 4 + 3 + 3);
    CHECK_EQ_U(sc.npoints, 3);
    interp_destroy(ip);
}

/* ---- Attributes ------------------------------------------------------------------ */

static void test_attributes(void)
{
    interp *ip = fresh();
    const float *c = interp_state(ip)->a.current.color;
    seq s;
    seq_init(&s);
    CMD(&s, Color3ub, 255, 0, 51);
    run(ip, &s);
    CHECK_NEAR(c[0], 1, 0);
    CHECK_NEAR(c[2], 0.2, 1e-7);
    CHECK_NEAR(c[3], 1, 0);
    seq_init(&s);
    CMD(&s, Color4b, 127, -128, 0, 63);
    run(ip, &s);
    CHECK_NEAR(c[0], 1, 1e-7);
    CHECK_NEAR(c[1], -1, 1e-7);
    CHECK_NEAR(c[2], 1.0 / 255, 1e-7);
    CHECK_NEAR(c[3], 127.0 / 255, 1e-7);
    seq_init(&s);
    CMD(&s, Color3us, 65535, 0, 32768);
    CMD(&s, Normal3s, -32768, 32767, 0);
    CMD(&s, TexCoord1i, 3);
    run(ip, &s);
    CHECK_NEAR(c[0], 1, 0);
    CHECK_NEAR(c[2], 32768.0 / 65535, 1e-7);
    CHECK_NEAR(interp_state(ip)->a.current.normal[0], -1, 1e-7);
    CHECK_NEAR(interp_state(ip)->a.current.normal[1], 1, 1e-7);
    CHECK_NEAR(interp_state(ip)->a.current.texcoord[0], 3, 0);
    CHECK_NEAR(interp_state(ip)->a.current.texcoord[3], 1, 0);
    seq_init(&s);
    CMD(&s, Color4ui, 4294967295.0, 0, 0, 0);
    run(ip, &s);
    CHECK_NEAR(c[0], 1, 0);

    /* Vertices carry the current attributes; w divides; colours clamp. */
    seq_init(&s);
    CMD(&s, Color4f, 2, -1, 0.5, 1);
    CMD(&s, Normal3f, 0, 1, 0);
    CMD(&s, TexCoord4f, 1, 2, 0, 2);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex4f, 2, 4, 6, 2);
    CMD(&s, Vertex2i, 1, 0);
    CMD(&s, Vertex3d, 0, 1, 0);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nverts, 3);
    if (sc.nverts == 3) {
        const scene_vertex *v = &sc.verts[0];
        CHECK(v->pos[0] == 1 && v->pos[1] == 2 && v->pos[2] == 3);
        CHECK(v->color[0] == 1 && v->color[1] == 0 && v->color[2] == 0.5f);
        CHECK(v->normal[1] == 1);
        CHECK(v->tex[0] == 0.5f && v->tex[1] == 1);
    }

    /* Lit points take GL's lit colour (GL 1.x 2.13.1): LIGHT0 shines
     * along -z onto the default normal (0, 0, 1): e + a Ga + d (N.L), with
     * Ga = 0.2, a = 0.2, no specular. Colour material feeds glColor into
     * the ambient and diffuse terms. */
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    CMD(&s, Normal3f, 0, 0, 1);
    CMD(&s, Materialfv, GL_FRONT, GL_DIFFUSE, 0.25, 0.5, 0.75, 1);
    CMD(&s, Color3f, 1, 1, 1);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex3f, 0, 0, 0);
    CMD0(&s, End);
    CMD(&s, Enable, GL_COLOR_MATERIAL);
    CMD(&s, Color3f, 0.1, 0.2, 0.3);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex3f, 0, 0, 0);
    CMD0(&s, End);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, 0, 0, 0);
    CMD(&s, Vertex3f, 1, 0, 0);
    CMD(&s, Vertex3f, 0, 1, 0);
    CMD0(&s, End);
    CMD(&s, Disable, GL_LIGHT0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, 0, 0, 0);
    CMD(&s, Vertex3f, 1, 0, 0);
    CMD(&s, Vertex3f, 0, 1, 0);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.npoints, 2);
    if (sc.npoints == 2) {
        CHECK(fabsf(sc.points[0].color[1] - 0.54f) < 1e-6f);
        CHECK(fabsf(sc.points[1].color[1] - 0.24f) < 1e-6f);
    }
    /* The lit triangles: colour material's terms are left out of the
     * material; the second draw, with GL_LIGHT0 off, has a light set of
     * its own (no lights), so a material of its own, and no note. */
    CHECK_EQ_U(sc.nmaterials, 2);
    if (sc.nmaterials == 2) {
        CHECK(sc.materials[0].color_material[0] == (SCENE_CM_AMBIENT | SCENE_CM_DIFFUSE));
        CHECK(sc.materials[0].diffuse[0][1] == 0);
        CHECK(sc.materials[0].specular[0][3] == 1);
        CHECK(sc.materials[0].lightset == 0 && sc.materials[1].lightset == 1);
    }
    CHECK_EQ_U(sc.nlightsets, 2);
    CHECK_EQ_U(sc.nlights, 1);
    if (sc.nlights == 1)
        CHECK(sc.lights[0].kind == SCENE_LIGHT_PARALLEL && sc.lights[0].direction[2] == 1 &&
              sc.lights[0].specular[0] == 1 && sc.lights[0].set == 0);
    CHECK_EQ_U(count(DIAG_NOTE_LIGHTING), 0);
    interp_destroy(ip);
}

/* ---- Approximation notes ----------------------------------------------------------- */

static void lit_triangle(seq *s)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, 0, 0, -2);
    CMD(s, Vertex3f, 1, 0, -2);
    CMD(s, Vertex3f, 0, 1, -2);
    CMD0(s, End);
}

/* Blend functions (GL 1.x 4.1.7) as transmit: GL shows ws c + wd behind,
 * POV-Ray (1 - t) k + t behind. SRC_ALPHA, ONE_MINUS_SRC_ALPHA, ONE, ZERO
 * (opaque) and ZERO, ONE (invisible) need nothing; other functions of the
 * source alpha take t = wd, k = ws c / (1 - wd) in the vertex colour,
 * exact but for additive blending (wd = 1: t = 127/128, noted); the
 * multiplying GL_DST_COLOR, GL_ZERO is a filter of the colour (alpha 0,
 * test_blend.c), the framebuffer alpha unknown without a clear (noted as
 * reading the destination), lit surfaces are drawn as SRC_ALPHA,
 * ONE_MINUS_SRC_ALPHA, noted. The triangle's colour is (1, 0.5, 0) with
 * alpha 0.5. */
static void test_blend(void)
{
    static const struct {
        GLenum src, dst;
        bool lit;
        float k0, alpha; /* the vertex colour's red and alpha */
        uint64_t note, note_add;
    } cases[] = {
        {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, false, 1, 0.5f, 0, 0},
        {GL_ONE, GL_ZERO, false, 1, 1, 0, 0},
        {GL_ZERO, GL_ONE, false, 1, 0, 0, 0},
        {GL_ONE, GL_ONE_MINUS_SRC_ALPHA, false, 2, 0.5f, 0, 0},     /* premultiplied */
        {GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, false, 1, 0.5f, 0, 0},
        {GL_SRC_ALPHA, GL_ZERO, false, 0.5f, 1, 0, 0},
        {GL_ZERO, GL_ONE_MINUS_SRC_ALPHA, false, 0, 0.5f, 0, 0},
        {GL_SRC_ALPHA, GL_ONE, false, 64, 1.0f / 128, 0, 1},        /* additive */
        {GL_ONE, GL_ONE, false, 128, 1.0f / 128, 0, 1},
        {GL_DST_COLOR, GL_ZERO, false, 1, 0, 0, 0},                 /* colour factor */
        {GL_ONE, GL_DST_ALPHA, false, 1, 0.5f, 0, 0},               /* framebuffer alpha */
        {GL_ONE, GL_ONE, true, 0, 0, 1, 0},                         /* lit surface */
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        if (cases[i].lit) {
            CMD(&s, Enable, GL_LIGHTING);
            CMD(&s, Enable, GL_LIGHT0);
        }
        CMD(&s, Enable, GL_BLEND);
        CMD(&s, BlendFunc, cases[i].src, cases[i].dst);
        CMD(&s, Color4f, 1, 0.5, 0, 0.5);
        lit_triangle(&s);
        run(ip, &s);
        if (count(DIAG_NOTE_BLEND) != cases[i].note || count(DIAG_NOTE_BLEND_ADD) != cases[i].note_add)
            fprintf(stderr, "blend case %zu\n", i);
        CHECK_EQ_U(count(DIAG_NOTE_BLEND), cases[i].note);
        CHECK_EQ_U(count(DIAG_NOTE_BLEND_ADD), cases[i].note_add);
        CHECK_EQ_U(count(DIAG_NOTE_BLEND_DEST), cases[i].dst == GL_DST_ALPHA);
        CHECK_EQ_U(sc.nverts, 3);
        if (!cases[i].lit && sc.nverts == 3) {
            CHECK_NEAR(sc.verts[0].color[0], cases[i].k0, 1e-5);
            CHECK_NEAR(sc.verts[0].color[1], cases[i].k0 / 2, 1e-5);
            CHECK_NEAR(sc.verts[0].color[3], cases[i].alpha, 1e-6);
        }
        interp_destroy(ip);
    }
    /* Blending off: the function does not matter. */
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, BlendFunc, GL_ONE, GL_ONE);
    CMD(&s, Color4f, 1, 0.5, 0, 0.5);
    lit_triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_BLEND) + count(DIAG_NOTE_BLEND_ADD), 0);
    if (sc.nverts == 3)
        CHECK_NEAR(sc.verts[0].color[3], 1, 0);
    interp_destroy(ip);
}

/* Lit normals that GL uses at another length than 1 (POV-Ray always
 * normalises) get a note; GL_NORMALIZE, and GL_RESCALE_NORMAL under a
 * uniform scale, make them unit length and say nothing. */
static void test_normal_notes(void)
{
    struct {
        bool normalize, rescale;
        double scale[3], len;
        uint64_t notes;
    } cases[] = {
        {false, false, {1, 1, 1}, 1, 0},       /* unit as given */
        {false, false, {1, 1, 1}, 2.5, 1},     /* long as given */
        {true, false, {1, 1, 1}, 2.5, 0},      /* GL_NORMALIZE */
        {false, false, {2, 2, 2}, 1, 1},       /* shrunk by the scale */
        {false, true, {2, 2, 2}, 1, 0},        /* GL_RESCALE_NORMAL undoes it */
        {false, true, {2, 1, 1}, 1, 1},        /* not for a non-uniform scale */
        {true, false, {2, 0.5, 1}, 1, 0},      /* GL_NORMALIZE does */
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, Enable, GL_LIGHTING);
        CMD(&s, Enable, GL_LIGHT0);
        if (cases[i].normalize)
            CMD(&s, Enable, GL_NORMALIZE);
        if (cases[i].rescale)
            CMD(&s, Enable, GL_RESCALE_NORMAL);
        CMD(&s, Scalef, cases[i].scale[0], cases[i].scale[1], cases[i].scale[2]);
        /* (0.6, 0, 0.8) has length 1 */
        CMD(&s, Normal3f, 0.6 * cases[i].len, 0, 0.8 * cases[i].len);
        lit_triangle(&s);
        run(ip, &s);
        if (count(DIAG_NOTE_NORMALS) != cases[i].notes)
            fprintf(stderr, "normal case %zu\n", i);
        CHECK_EQ_U(count(DIAG_NOTE_NORMALS), cases[i].notes);
        interp_destroy(ip);
    }
}

/* ---- Runs and clears ------------------------------------------------------------- */

static void quad(seq *s)
{
    CMD(s, Begin, GL_QUADS);
    CMD(s, Vertex2f, 0, 0);
    CMD(s, Vertex2f, 0.5, 0);
    CMD(s, Vertex2f, 0.5, 0.5);
    CMD(s, Vertex2f, 0, 0.5);
    CMD0(s, End);
}

static void test_runs(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    quad(&s);
    CMD(&s, Color3f, 1, 0, 0); /* colours are per vertex: same run */
    quad(&s);
    CMD(&s, Translatef, 0.1, 0, 0);
    quad(&s); /* another transform: another run */
    CMD(&s, ShadeModel, GL_FLAT);
    quad(&s); /* another look: another run */
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 3);
    CHECK_EQ_U(sc.ntris, 8);

    /* glClear erases what came before and sets the background. */
    seq_init(&s);
    CMD(&s, ClearColor, 0.25, 0.5, 0.75, 1);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    quad(&s);
    CMD(&s, ClearColor, 0, 0, 0, 1);
    CMD(&s, Clear, GL_DEPTH_BUFFER_BIT); /* depth only: nothing erased */
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 2);
    CHECK(sc.background[0] == 0.25f && sc.background[2] == 0.75f);
    interp_end_frame(ip);
    CHECK(sc.background[0] == 0.25f); /* the cleared colour stays */
    interp_destroy(ip);
}

/* Without a depth test, each draw comes a little closer to the camera than
 * the one before, so that coplanar draws show in draw order; images are
 * unchanged (same window positions). */
static void test_painter(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 10);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Translatef, 0, 0, -5);
    quad(&s);
    quad(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    quad(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 3);
    if (sc.nmeshes == 3) {
        double z0 = sc.meshes[0].to_eye.m[14], z1 = sc.meshes[1].to_eye.m[14],
               z2 = sc.meshes[2].to_eye.m[14];
        /* nearer, by more than POV-Ray's ~2e-4 tolerance, still close */
        CHECK(z0 > -5 && z1 - z0 > 2e-4 && z1 - z0 < 1e-3);
        CHECK(z2 == -5);                               /* depth-tested: as is */
        /* Scaled about the eye: x/z (the image position) is unchanged. */
        double x0 = sc.meshes[0].to_eye.m[0] * 0.5 + sc.meshes[0].to_eye.m[12];
        double x1 = sc.meshes[1].to_eye.m[0] * 0.5 + sc.meshes[1].to_eye.m[12];
        CHECK_NEAR(x0 / z0, x1 / z1, 1e-12);
    }
    interp_destroy(ip);
}

static void test_alloc_failure(void)
{
    /* Every allocation failing in turn: reported, never a crash. */
    for (unsigned long n = 1; n < 40; n++) {
        scene s2;
        scene_init(&s2);
        tr_fail_alloc(n);
        interp *ip = interp_create(&s2, NULL);
        if (ip) {
            seq s;
            seq_init(&s);
            tr_fail_alloc(0);
            for (int i = 0; i < 40; i++)
                quad(&s);
            tr_fail_alloc(n);
            rgl_error err;
            interp_begin_frame(ip);
            interp_run(ip, s.data, s.len, 0, &err);
            interp_end_frame(ip);
            tr_fail_alloc(0);
            seq_free(&s);
            CHECK(s2.failed || s2.ntris == 80);
        }
        tr_fail_alloc(0);
        interp_destroy(ip);
        scene_finish(&s2);
    }
}

/* The whole translation with the n-th allocation failing, for every n that
 * matters: an error comes back, never a crash or a leak (ASan build). */
static void test_alloc_translation(void)
{
    seq s;
    seq_init(&s);
    scene_smooth(&s);
    scene_lines_points(&s);
    trace t;
    trace_init(&t);
    trace_frame(&t, 0, 0, 0, 0, &s);
    trace_frame(&t, 0, 1, RGL_FRAME_STATE_CARRIED, 0, &s);
    trace_finish(&t);
    rgl_reader *r;
    CHECK(rgl_reader_open_memory(t.data, t.size, &r, NULL) == RGL_OK);
    int ok = 0;
    for (unsigned long n = 1; n < 120; n++) {
        tr_fail_alloc(n);
        translator *tr = translator_create(r, NULL);
        povwriter *pw = povwriter_create();
        outbuf ob;
        int oi = outbuf_init(&ob, 256, NULL, NULL);
        for (size_t i = 0; tr && pw && oi == 0 && i < 2; i++) {
            frame_result res;
            if (translator_build(tr, i, NULL, &res) == RGL_OK) {
                pov_frame_info info = {"f.pov", "t.raygl", i, 0, (uint32_t)i, NULL, NULL};
                ob.len = 0;
                ok += povwriter_scene(pw, &ob, translator_scene(tr), &info) == 0 && !ob.failed;
            }
        }
        tr_fail_alloc(0);
        if (oi == 0)
            outbuf_finish(&ob);
        povwriter_destroy(pw);
        translator_destroy(tr);
    }
    CHECK(ok > 0); /* late failures leave whole frames */
    rgl_reader_destroy(r);
    trace_free(&t);
    seq_free(&s);
}

/* The fast run loop (a, ia) left the very scene and state the general
 * decoder (c, ic) left. */
static void check_same_run(const scene *a, const scene *c, interp *ia, interp *ic)
{
    CHECK(a->nverts == c->nverts && a->ntris == c->ntris && a->nlines == c->nlines &&
          a->npoints == c->npoints && a->nmeshes == c->nmeshes);
    if (a->nverts == c->nverts && a->nverts)
        CHECK(memcmp(a->verts, c->verts, a->nverts * sizeof *a->verts) == 0);
    if (a->ntris == c->ntris && a->ntris)
        CHECK(memcmp(a->tris, c->tris, a->ntris * sizeof *a->tris) == 0);
    if (a->nlines == c->nlines && a->nlines)
        CHECK(memcmp(a->lines, c->lines, a->nlines * sizeof *a->lines) == 0);
    CHECK(memcmp(&interp_state(ia)->a, &interp_state(ic)->a, sizeof(gl_attribs)) == 0);
}

/* The run loop's fast path for per-vertex commands gives the very scene
 * the general decoder gives. */
static void test_fast_path(void)
{
    void (*const builders[])(seq *) = {scene_paper_box, scene_smooth, scene_lines_points,
                                       scene_faces, scene_awkward};
    for (size_t b = 0; b < sizeof builders / sizeof builders[0]; b++) {
        seq s;
        seq_init(&s);
        CMD(&s, Enable, GL_COLOR_MATERIAL);
        CMD(&s, Color4ub, 10, 20, 30, 40);
        CMD(&s, Color4f, 0.1, 0.2, 0.3, 0.4);
        CMD(&s, TexCoord2f, 0.5, 0.25);
        builders[b](&s);
        scene a, c;
        scene_init(&a);
        scene_init(&c);
        interp *ia = interp_create(&a, NULL), *ic = interp_create(&c, NULL);
        rgl_error err;
        interp_begin_frame(ia);
        interp_begin_frame(ic);
        interp_run(ia, s.data, s.len, 0, &err);
        interp_run_slow(ic, s.data, s.len, 0, &err);
        interp_end_frame(ia);
        interp_end_frame(ic);
        check_same_run(&a, &c, ia, ic);
        interp_destroy(ia);
        interp_destroy(ic);
        scene_finish(&a);
        scene_finish(&c);
        seq_free(&s);
    }
}

/* A torus-like strip of glNormal3f, glColor3f, glVertex3f, lit or not
 * (the run loop takes such calls three at a time), after `pre` attribute
 * calls: with the command budget at 1024, the cut falls on each of the
 * three calls in turn as pre goes 0, 1, 2, and on the last vertices. */
static void strip_triplets(seq *s, bool lit, int pre)
{
    scene_smooth(s);
    if (lit) {
        CMD(s, Enable, GL_LIGHTING);
        CMD(s, Enable, GL_LIGHT0);
        CMD(s, Enable, GL_COLOR_MATERIAL);
    }
    for (int i = 0; i < pre; i++)
        CMD(s, Normal3f, 0, 0, 1);
    CMD(s, Begin, GL_TRIANGLE_STRIP);
    for (int i = 0; i < 80; i++) {
        double u = 0.3 * i, side = i % 2 ? 0.5 : -0.5;
        CMD(s, Normal3f, cos(u), sin(u), side);
        CMD(s, Color3f, 0.5 + 0.4 * cos(u), 0.5, 0.5 + 0.4 * sin(u));
        CMD(s, Vertex3f, cos(u), sin(u), side);
    }
    CMD0(s, End);
}

/* The run loop's three-call path stops where the general decoder stops,
 * at each of the three calls, and leaves the same scene and state. */
static void test_fast_path_cuts(void)
{
    int cuts = 0;
    for (int lit = 0; lit < 2; lit++)
        for (int pre = 900; pre < 903; pre++) {
            seq s;
            seq_init(&s);
            strip_triplets(&s, lit, pre);
            scene a, c;
            scene_init(&a);
            scene_init(&c);
            interp *ia = interp_create(&a, NULL), *ic = interp_create(&c, NULL);
            interp_set_budget_shift(ia, 16); /* 1024 commands */
            interp_set_budget_shift(ic, 16);
            rgl_error err;
            interp_begin_frame(ia);
            interp_begin_frame(ic);
            interp_run(ia, s.data, s.len, 0, &err);
            interp_run_slow(ic, s.data, s.len, 0, &err);
            const char *ca = interp_frame_cut(ia), *cc = interp_frame_cut(ic);
            CHECK(ca && cc && strcmp(ca, cc) == 0);
            cuts += ca && strstr(ca, "commands run") != NULL;
            interp_end_frame(ia);
            interp_end_frame(ic);
            check_same_run(&a, &c, ia, ic);
            interp_destroy(ia);
            interp_destroy(ic);
            scene_finish(&a);
            scene_finish(&c);
            seq_free(&s);
        }
    CHECK_EQ_U(cuts, 6);
}

/* Shapes' tessellation is bounded per shape and per frame: a few bytes of
 * trace asking for 10^10 facets are skipped with a note, up to the bounds
 * they are drawn. */
static void test_shape_budget(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, WireTorus, 0.2, 1, 100000, 100000);
    CMD(&s, SolidSphere, 1, 2000000, 2000000); /* exact solid: no tessellation needed */
    CMD(&s, NewQuadric, 1);
    CMD(&s, QuadricDrawStyle, 1, 100011 /* GLU_LINE */);
    CMD(&s, Cylinder, 1, 1, 1, 1, 10, 1 << 30); /* GLU caps slices, not stacks */
    CMD(&s, Disk, 1, 0.5, 1, 10, 1 << 30);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_IGNORED), 3);
    CHECK_EQ_U(sc.nverts + sc.nlines, 0);
    CHECK_EQ_U(sc.nsolids, 1);
    CHECK(strstr(dlog.e[DIAG_IGNORED].text[0], "glutWireTorus with 100000 x 100000 facets") != NULL);
    /* 512 x 512 is the bound itself: drawn. Each draws 2^19 segments,
     * n scene lines for the pixels they light: the torus that takes the
     * lines over the frame budget (INTERP_BUDGET_LINES) cuts the frame
     * after it; later commands are not run. */
    size_t n = 0;
    int over = -1;
    for (int i = 0; i < 9; i++) {
        seq_init(&s);
        CMD(&s, WireTorus, 0.2, 1, 512, 512);
        run(ip, &s);
        if (i == 0) {
            n = sc.nlines;
            CHECK(n > 0 && n < INTERP_BUDGET_LINES);
            over = n > 0 ? (int)(INTERP_BUDGET_LINES / n) : 0;
        }
        CHECK_EQ_U(count(DIAG_IGNORED), 3);
        CHECK_EQ_U(sc.nlines, (size_t)(i < over ? i + 1 : over + 1) * n);
        CHECK((interp_frame_cut(ip) != NULL) == (i >= over));
    }
    CHECK(strstr(interp_frame_cut(ip), "over the frame budget of 1048576 lines and points") != NULL);
    /* A new frame has a new budget. */
    interp_begin_frame(ip);
    CHECK(interp_frame_cut(ip) == NULL);
    seq_init(&s);
    CMD(&s, WireTorus, 0.2, 1, 512, 512);
    run(ip, &s);
    CHECK_EQ_U(interp_frame_segments(ip), 2u * 512 * 512);
    CHECK_EQ_U(sc.nlines, n);
    interp_destroy(ip);
}

/* @Skipped: a call the recorder passed to GL unrecorded is said, by name
 * and reason, and changes nothing. */
static void test_skipped(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Skipped, RGL_OP_TexImage2D, RGL_SKIP_NO_DATA);
    CMD(&s, Skipped, RGL_OP_DrawArrays, RGL_SKIP_UNKNOWN_ENUM);
    CMD(&s, Skipped, 0x7fff, 99);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_IGNORED), 3);
    CHECK(strstr(dlog.e[DIAG_IGNORED].text[0],
                 "glTexImage2D was not recorded: its data could not be read") != NULL);
    CHECK(strstr(dlog.e[DIAG_IGNORED].text[1],
                 "glDrawArrays was not recorded: an enum the recorder does not know") != NULL);
    CHECK(strstr(dlog.e[DIAG_IGNORED].text[2], "a call was not recorded: unknown reason") != NULL);
    CHECK_EQ_U(sc.nverts + sc.nlines, 0);
    interp_destroy(ip);
}

/* Texture units: state calls change the active unit's, glMultiTexCoord
 * one unit's coordinates (glTexCoord unit 0's), a bad unit changes
 * nothing, client arrays of texture coordinates belong to the client
 * unit, and a draw gives vertices both enabled units' coordinates. */
static void test_multitex(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    CMD(&s, ActiveTexture, GL_TEXTURE1);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, Enable, GL_TEXTURE_GEN_S);
    CMD(&s, TexGeni, GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    CMD(&s, MatrixMode, GL_TEXTURE);
    CMD(&s, Translatef, 0.5, 0, 0);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, ActiveTexture, GL_TEXTURE0 + 40); /* refused: unit 1 stays active */
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK_EQ_U(ip->st.active_unit, 1);
    CHECK_EQ_U(ip->st.a.texture.env_mode, GL_ADD);
    seq_init(&s);
    CMD(&s, ActiveTextureARB, GL_TEXTURE0);
    CMD(&s, MultiTexCoord2f, GL_TEXTURE1, 0.25, 0.75);
    CMD(&s, MultiTexCoord3dvARB, GL_TEXTURE0, 1, 2, 3);
    run(ip, &s);
    CHECK_EQ_U(ip->st.active_unit, 0);
    CHECK_EQ_U(ip->st.a.texture.env_mode, GL_REPLACE);
    CHECK(!ip->st.a.caps[INTERP_CAP_TEXTURE_2D] && !ip->st.a.caps[INTERP_CAP_TEXTURE_GEN_S]);
    CHECK_NEAR(interp_matrix(ip, INTERP_TEX)->m[12], 0, 0);
    CHECK_EQ_U(ip->st.units[1].texture.env_mode, GL_ADD);
    CHECK_EQ_U(ip->st.units[1].texture.gen_mode[0], GL_OBJECT_LINEAR);
    CHECK_NEAR(ip->st.units[1].matrix[0].m[12], 0.5, 0);
    CHECK_NEAR(ip->st.unit_texcoord[1][0], 0.25, 0);
    CHECK_NEAR(ip->st.unit_texcoord[1][1], 0.75, 0);
    CHECK_NEAR(ip->st.unit_texcoord[1][3], 1, 0);
    CHECK_NEAR(ip->st.a.current.texcoord[2], 3, 0);

    /* A draw: unit 1 (enabled, texgen s = x, then + 0.5) gives tex1 even
     * with no texture bound (the look then has none). */
    seq_init(&s);
    CMD(&s, Enable, GL_TEXTURE_2D);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, MultiTexCoord2f, GL_TEXTURE0, 0.1, 0.2);
    CMD(&s, MultiTexCoord2f, GL_TEXTURE1, 0, 0.3);
    CMD(&s, Vertex2f, 2, 0);
    CMD(&s, Vertex2f, 3, 0);
    CMD(&s, Vertex2f, 2, 1);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nverts, 3);
    if (sc.nverts == 3) {
        CHECK_NEAR(sc.verts[0].tex[0], 0.1, 1e-6);
        CHECK_NEAR(sc.verts[0].tex[1], 0.2, 1e-6);
        CHECK_NEAR(sc.verts[1].tex1[0], 3.5, 1e-6); /* object x, then the unit's matrix */
        CHECK_NEAR(sc.verts[1].tex1[1], 0.3, 1e-6);
    }

    /* Arrays: the @ArrayData after glClientActiveTexture(GL_TEXTURE1) is
     * unit 1's; unit 0 keeps its own. */
    seq_init(&s);
    static const float st1[6] = {5, 6, 7, 8, 9, 10}, st0[6] = {1, 1, 2, 2, 3, 3};
    static const float xy[6] = {0, 0, 1, 0, 0, 1};
    CMD(&s, ActiveTexture, GL_TEXTURE1);
    CMD(&s, Disable, GL_TEXTURE_GEN_S);
    CMD(&s, ActiveTexture, GL_TEXTURE0);
    CMD(&s, ClientActiveTexture, GL_TEXTURE1);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, st1, sizeof st1,
                  (const double[]){GL_TEXTURE_COORD_ARRAY, 0, 2, GL_FLOAT}, 4);
    CMD(&s, ClientActiveTextureARB, GL_TEXTURE0);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, st0, sizeof st0,
                  (const double[]){GL_TEXTURE_COORD_ARRAY, 0, 2, GL_FLOAT}, 4);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, xy, sizeof xy,
                  (const double[]){GL_VERTEX_ARRAY, 0, 2, GL_FLOAT}, 4);
    CMD(&s, DrawArrays, GL_TRIANGLES, 0, 3);
    run(ip, &s);
    CHECK_EQ_U(sc.nverts, 6);
    if (sc.nverts == 6) {
        CHECK_NEAR(sc.verts[5].tex[0], 3, 0);
        CHECK_NEAR(sc.verts[5].tex1[0], 9.5, 1e-6);
        CHECK_NEAR(sc.verts[5].tex1[1], 10, 0);
    }

    /* A third enabled unit is not drawn, and said so. */
    CHECK_EQ_U(count(DIAG_NOTE_MULTITEX), 0);
    seq_init(&s);
    CMD(&s, ActiveTexture, GL_TEXTURE5);
    CMD(&s, Enable, GL_TEXTURE_1D);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex2f, 0, 0);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_MULTITEX), 1);
    CHECK(ip->draw_unit[0] == 0 && ip->draw_unit[1] == 1);
    interp_destroy(ip);
}

/* The teapot: the exact patches when unlit, freeglut's 3,136 triangles
 * (32 patches of 7 x 7 cells) when the exact form does not apply, and its
 * 5,760 wire segments (32 patches, 10 lines of 9 segments each way), 36 of
 * them of no length, the counts measured from freeglut 3.4
 * (docs/mapping.md section 10). */
static void test_teapot(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, SolidTeapot, 1.5);
    run(ip, &s);
    CHECK_EQ_U(sc.nsolids, 1);
    CHECK(sc.nsolids == 1 && sc.solids[0].kind == SCENE_SOLID_TEAPOT &&
          sc.solids[0].params[0] == 1.5);
    CHECK_EQ_U(sc.ntris + sc.nlines, 0);
    interp_destroy(ip);

    ip = fresh();
    seq_init(&s);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, ShadeModel, GL_FLAT); /* faceted: GL's own triangles */
    CMD(&s, SolidTeapot, 1);
    run(ip, &s);
    CHECK_EQ_U(sc.nsolids, 0);
    CHECK_EQ_U(sc.ntris, 3136);
    interp_destroy(ip);

    ip = fresh();
    seq_init(&s);
    CMD(&s, Rotatef, 30, 1, 0.5, 0.2); /* no segment along the view */
    CMD(&s, WireTeapot, 1);
    run(ip, &s);
    CHECK_EQ_U(sc.nsolids + sc.ntris, 0);
    /* every segment of GLUT's wire teapot (the bottom's centre row, 4 x 9
     * of them, has both ends in one point and lights nothing) */
    CHECK_EQ_U(interp_frame_segments(ip), 5760);
    CHECK(sc.nlines > 0);
    interp_destroy(ip);
}

/* ---- Evaluators ------------------------------------------------------------------ */

/* The Bernstein maths of interp_eval.c against values worked by hand. */
static void test_eval_maths(void)
{
    /* Cubic (0,0) (1,2) (3,2) (4,0): at 1/2 the weights are 1/8 3/8 3/8 1/8,
     * at 1/4 27/64 27/64 9/64 1/64. */
    static const double cubic[4][3] = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};
    double out[4];
    interp_eval_curve(&cubic[0][0], 4, 3, 0.5, out);
    CHECK_NEAR(out[0], 2.0, 1e-12);
    CHECK_NEAR(out[1], 1.5, 1e-12);
    interp_eval_curve(&cubic[0][0], 4, 3, 0.25, out);
    CHECK_NEAR(out[0], 58.0 / 64, 1e-12);
    CHECK_NEAR(out[1], 72.0 / 64, 1e-12);
    interp_eval_curve(&cubic[0][0], 4, 3, 1.0, out);
    CHECK_NEAR(out[0], 4.0, 1e-12);
    /* One point: a constant. */
    static const double one[4] = {0.1, 0.2, 0.3, 0.4};
    interp_eval_curve(one, 1, 4, 0.7, out);
    CHECK_NEAR(out[3], 0.4, 0);
    /* Bilinear patch, u major: p(u, v) = (u, v, u v); the partials at
     * (1/2, 1/2) are (1, 0, 1/2) and (0, 1, 1/2). */
    static const double bil[2][2][3] = {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 1}}};
    double du[4], dv[4];
    interp_eval_surface(&bil[0][0][0], 2, 2, 3, 0.5, 0.5, out, du, dv);
    CHECK_NEAR(out[0], 0.5, 1e-12);
    CHECK_NEAR(out[1], 0.5, 1e-12);
    CHECK_NEAR(out[2], 0.25, 1e-12);
    CHECK_NEAR(du[0], 1, 1e-12);
    CHECK_NEAR(du[1], 0, 1e-12);
    CHECK_NEAR(du[2], 0.5, 1e-12);
    CHECK_NEAR(dv[0], 0, 1e-12);
    CHECK_NEAR(dv[1], 1, 1e-12);
    CHECK_NEAR(dv[2], 0.5, 1e-12);
    /* Biquadratic, 2 x 3 in u x v: the v curve of each row, then along u. */
    static const double bq[2][3][1] = {{{0}, {4}, {0}}, {{2}, {2}, {2}}};
    interp_eval_surface(&bq[0][0][0], 2, 3, 1, 0.25, 0.5, out, NULL, NULL);
    CHECK_NEAR(out[0], 0.75 * 2 + 0.25 * 2, 1e-12); /* row 0 at v 1/2: 2; row 1: 2 */
}

/* glMap1f's blob: the packed little-endian floats. */
static void put_floats(uint8_t *b, const float *f, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        uint32_t u;
        memcpy(&u, &f[i], 4);
        for (int k = 0; k < 4; k++)
            b[4 * i + k] = (uint8_t)(u >> (8 * k));
    }
}

static void map1f(seq *s, GLenum target, double u1, double u2, int stride, int order,
                  const float *pts, size_t n)
{
    uint8_t b[4 * 4 * 30];
    put_floats(b, pts, n);
    seq_cmd_bytes(s, RGL_OP_Map1f, b, 4 * n, (const double[]){target, u1, u2, stride, order}, 5);
}

static void map2f(seq *s, GLenum target, int uorder, int vorder, const float *pts, size_t n)
{
    uint8_t b[4 * 4 * 64];
    put_floats(b, pts, n);
    uint32_t k = rgl_map_components(target, NULL);
    seq_cmd_bytes(s, RGL_OP_Map2f, b, 4 * n,
                  (const double[]){target, 0, 1, (double)(k * (uint32_t)vorder), uorder, 0, 1, k,
                                   vorder},
                  9);
}

/* Evaluated vertices reach the scene with the evaluated attributes, and the
 * current ones stay. */
static void test_eval_draw(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    static const float cubic[4][3] = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}};
    static const float cols[2][4] = {{1, 0, 0, 1}, {0, 0, 1, 1}};
    CMD(&s, Ortho, -10, 10, -10, 10, -10, 10);
    map1f(&s, GL_MAP1_VERTEX_3, 2, 4, 3, 4, &cubic[0][0], 12); /* domain [2, 4] */
    map1f(&s, GL_MAP1_COLOR_4, 2, 4, 4, 2, &cols[0][0], 8);
    CMD(&s, Enable, GL_MAP1_VERTEX_3);
    CMD(&s, Enable, GL_MAP1_COLOR_4);
    CMD(&s, Color3f, 0, 1, 0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, EvalCoord1f, 2);
    CMD(&s, EvalCoord1f, 3);   /* u' = 1/2 */
    CMD(&s, EvalCoord1d, 2.5); /* u' = 1/4 */
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK_EQ_U(sc.nverts, 3);
    if (sc.nverts == 3) {
        CHECK_NEAR(sc.verts[1].pos[0], 2.0, 1e-6);
        CHECK_NEAR(sc.verts[1].pos[1], 1.5, 1e-6);
        CHECK_NEAR(sc.verts[2].pos[0], 58.0 / 64, 1e-6);
        CHECK_NEAR(sc.verts[0].color[0], 1, 1e-6);
        CHECK_NEAR(sc.verts[1].color[0], 0.5, 1e-6);
        CHECK_NEAR(sc.verts[1].color[2], 0.5, 1e-6);
    }
    /* The current colour is still glColor's. */
    CHECK_NEAR(interp_state(ip)->a.current.color[1], 1, 0);
    CHECK_NEAR(interp_state(ip)->a.current.color[0], 0, 0);

    /* glEvalMesh2(GL_FILL) over a 2 x 2 grid: two quad strips of two quads;
     * GL_AUTO_NORMAL on a patch in the xy plane gives (0, 0, 1). */
    static const float flat[2][2][3] = {{{0, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}}};
    seq_init(&s);
    map2f(&s, GL_MAP2_VERTEX_3, 2, 2, &flat[0][0][0], 12);
    CMD(&s, Enable, GL_MAP2_VERTEX_3);
    CMD(&s, Enable, GL_AUTO_NORMAL);
    CMD(&s, MapGrid2f, 2, 0, 1, 2, 0, 1);
    CMD(&s, EvalMesh2, GL_FILL, 0, 2, 0, 2);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1 + 8);
    CHECK_EQ_U(sc.nverts, 3 + 12);
    for (size_t i = 3; i < sc.nverts; i++)
        CHECK_NEAR(sc.verts[i].normal[2], 1, 1e-6);
    /* The first strip: (u, 0) and (u, 1/2) for u = 0, 1/2, 1. */
    if (sc.nverts >= 9) {
        CHECK_NEAR(sc.verts[4].pos[1], 0.5, 1e-6);
        CHECK_NEAR(sc.verts[5].pos[0], 0.5, 1e-6);
        CHECK_NEAR(sc.verts[8].pos[0], 1, 1e-6);
    }
    CHECK_NEAR(interp_state(ip)->a.current.normal[2], 1, 0); /* GL's initial normal */

    /* GL_LINE: 3 row strips and 3 column strips of 2 segments; GL_POINT: 9. */
    CHECK_EQ_U(sc.nlines, 0);
    seq_init(&s);
    CMD(&s, EvalMesh2, GL_LINE, 0, 2, 0, 2);
    CMD(&s, EvalMesh2, GL_POINT, 0, 2, 0, 2);
    CMD(&s, Disable, GL_MAP1_VERTEX_3);
    CMD(&s, EvalMesh1, GL_LINE, 0, 2); /* no MAP1 vertex map on: nothing */
    run(ip, &s);
    CHECK_EQ_U(sc.nlines, 12);
    CHECK_EQ_U(sc.npoints, 9);

    /* glEvalPoint1 on the grid: i * (u2 - u1) / n + u1. */
    seq_init(&s);
    CMD(&s, Enable, GL_MAP1_VERTEX_3);
    CMD(&s, Disable, GL_MAP1_COLOR_4);
    CMD(&s, MapGrid1f, 4, 2, 4);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, EvalPoint1, 2); /* u = 3 */
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.npoints, 10);

    /* The grids are GL_EVAL_BIT attributes, with the map enables. */
    seq_init(&s);
    CMD(&s, PushAttrib, GL_EVAL_BIT);
    CMD(&s, MapGrid1f, 7, -1, 1);
    CMD(&s, Disable, GL_MAP1_VERTEX_3);
    CMD0(&s, PopAttrib);
    run(ip, &s);
    CHECK_EQ_U(interp_state(ip)->a.eval.grid_n[0][0], 4);
    CHECK_NEAR(interp_state(ip)->a.eval.grid[0][0][0], 2, 0);
    CHECK(interp_state(ip)->a.caps[INTERP_CAP_MAP1_VERTEX_3]);
    interp_destroy(ip);
}

/* Calls GL rejects leave the map as it was; hostile blobs too. */
static void test_eval_rejected(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    static const float pts[4][4] = {{1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}, {1, 1, 1, 1}};
    static const float good[2][3] = {{0, 0, 0}, {2, 0, 0}};
    CMD(&s, Ortho, -10, 10, -10, 10, -10, 10);
    map1f(&s, GL_MAP1_VERTEX_3, 0, 1, 3, 2, &good[0][0], 6);
    map1f(&s, 0x0D99, 0, 1, 3, 2, &pts[0][0], 6);             /* invalid enum: no target */
    map1f(&s, GL_MAP2_VERTEX_3, 0, 1, 3, 2, &pts[0][0], 6);   /* invalid enum: a MAP2 */
    map1f(&s, GL_MAP1_VERTEX_3, 0, 1, 3, 0, &pts[0][0], 0);   /* invalid value: order 0 */
    map1f(&s, GL_MAP1_VERTEX_3, 0, 1, 3, 31, &pts[0][0], 0);  /* invalid value: order 31 */
    map1f(&s, GL_MAP1_VERTEX_3, 1, 1, 3, 2, &pts[0][0], 6);   /* invalid value: u1 == u2 */
    map1f(&s, GL_MAP1_VERTEX_3, 0, 1, 2, 2, &pts[0][0], 6);   /* invalid value: stride < 3 */
    map1f(&s, GL_MAP1_VERTEX_3, 0, 1, 3, 2, &pts[0][0], 5);   /* invalid value: short blob */
    map1f(&s, GL_MAP1_VERTEX_3, 0, 1, 3, 2, &pts[0][0], 7);   /* invalid value: long blob */
    CMD(&s, MapGrid1f, 0, 0, 1);                              /* invalid value */
    CMD(&s, MapGrid2f, 2, 0, 1, -1, 0, 1);                    /* invalid value */
    CMD(&s, EvalMesh1, GL_FILL, 0, 1);                        /* invalid enum */
    CMD(&s, EvalMesh2, GL_LINE_STRIP, 0, 1, 0, 1);            /* invalid enum */
    CMD(&s, Begin, GL_POINTS);
    map1f(&s, GL_MAP1_VERTEX_3, 0, 1, 3, 2, &pts[0][0], 6);   /* invalid operation */
    CMD(&s, EvalMesh1, GL_POINT, 0, 1);                       /* invalid operation */
    CMD(&s, Enable, GL_MAP1_VERTEX_3);                        /* invalid operation */
    CMD0(&s, End);
    CMD(&s, Enable, GL_MAP1_VERTEX_3);
    CMD(&s, Enable, GL_MAP1_INDEX); /* not translated: a note */
    CMD(&s, MapGrid1f, 1, 0, 1);
    CMD(&s, EvalMesh1, GL_POINT, 1, 1); /* u = 1: the first map's (2, 0, 0) */
    CMD(&s, EvalMesh1, GL_LINE, 0, 2000000000); /* past the mesh limit */
    CMD(&s, EvalPoint1, 1); /* outside glBegin: ignored */
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex3f, 2, 0, 0); /* where the evaluated point must be */
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 4);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 8);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 3);
    CHECK_EQ_U(count(DIAG_NOTE_EVAL_INDEX), 1);
    CHECK_EQ_U(count(DIAG_LIMIT), 1);
    CHECK_EQ_U(count(DIAG_IGNORED), 1);
    CHECK_EQ_U(sc.npoints, 2);
    if (sc.npoints == 2)
        CHECK_NEAR(sc.points[0].p[0], sc.points[1].p[0], 1e-6);
    interp_destroy(ip);
}

/* ---- Raster positions and pixel rectangles ------------------------------------------ */

static const uint8_t *px_bytes[4];
static size_t px_sizes[4];

static rgl_status px_fetch(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err)
{
    (void)ctx;
    if (id == 0 || id > 4 || !px_bytes[id - 1]) {
        err->status = RGL_E_RESOURCE;
        return RGL_E_RESOURCE;
    }
    memset(out, 0, sizeof *out);
    out->id = id;
    out->kind = RGL_RES_BYTES;
    out->data = px_bytes[id - 1];
    out->size = px_sizes[id - 1];
    return RGL_OK;
}

static const uint8_t *overlay_px(int x, int y)
{
    return sc.overlay + ((size_t)y * (size_t)sc.overlay_w + (size_t)x) * 4;
}

static void test_raster_pos(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 10, 20, 200, 100);
    CMD(&s, Ortho, -1, 1, -1, 1, -1, 1);
    CMD(&s, Color3f, 0.25, 0.5, 1);
    CMD(&s, RasterPos3f, 0.5, -0.5, 0.5);
    run(ip, &s);
    const gl_attribs *a = &interp_state(ip)->a;
    CHECK(a->current.raster_valid);
    CHECK_NEAR(a->current.raster_pos[0], 10 + 150, 1e-9);
    CHECK_NEAR(a->current.raster_pos[1], 20 + 25, 1e-9);
    CHECK_NEAR(a->current.raster_pos[2], 0.25, 1e-9); /* glOrtho's z is negated */
    CHECK_NEAR(a->current.raster_color[1], 0.5, 0);
    /* Outside the view volume: invalid; the raster colour stays. */
    seq_init(&s);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, RasterPos2i, 2, 0);
    run(ip, &s);
    CHECK(!a->current.raster_valid);
    CHECK_NEAR(a->current.raster_color[0], 0.25, 0);
    /* glWindowPos: window coordinates as they are, valid, depth by the
     * depth range; GL_CURRENT_BIT saves the raster position. */
    seq_init(&s);
    CMD(&s, PushAttrib, GL_CURRENT_BIT);
    CMD(&s, DepthRange, 0.5, 1);
    CMD(&s, WindowPos3f, 3.5, 4, 0.5);
    run(ip, &s);
    CHECK(a->current.raster_valid);
    CHECK_NEAR(a->current.raster_pos[0], 3.5, 0);
    CHECK_NEAR(a->current.raster_pos[2], 0.75, 1e-9);
    CHECK_NEAR(a->current.raster_color[0], 1, 0);
    seq_init(&s);
    CMD0(&s, PopAttrib);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, RasterPos2i, 0, 0); /* not between glBegin and glEnd */
    CMD0(&s, End);
    run(ip, &s);
    CHECK(!a->current.raster_valid);
    CHECK(count(DIAG_GL_INVALID_OPERATION) == 1);
    interp_destroy(ip);
}

static void test_bitmap(void)
{
    interp *ip = fresh();
    interp_set_resources(ip, px_fetch, NULL);
    static const uint8_t bits[2] = {0xa0, 0x40}; /* 3 x 2: row 0 X.X, row 1 .X. */
    px_bytes[0] = bits;
    px_sizes[0] = 2;
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 40, 30);
    CMD(&s, Color3f, 0, 1, 0);
    CMD(&s, WindowPos2f, 5.7, 3.2);
    CMD(&s, Bitmap, 3, 2, 1, 0, 10, 1, 1); /* corner floor(4.7), floor(3.2) */
    run(ip, &s);
    CHECK(sc.overlay != NULL && sc.overlay_w == 40 && sc.overlay_h == 30);
    if (sc.overlay) {
        CHECK(overlay_px(4, 3)[1] == 255 && overlay_px(4, 3)[3] == 255);
        CHECK(overlay_px(5, 3)[3] == 0);
        CHECK(overlay_px(6, 3)[1] == 255);
        CHECK(overlay_px(5, 4)[3] == 255 && overlay_px(4, 4)[3] == 0);
    }
    const gl_attribs *a = &interp_state(ip)->a;
    CHECK_NEAR(a->current.raster_pos[0], 15.7, 1e-6); /* moved */
    CHECK_NEAR(a->current.raster_pos[1], 4.2, 1e-6);
    /* An invalid position: nothing drawn, no move. glClear erases. */
    seq_init(&s);
    CMD(&s, RasterPos2i, 5, 5);
    CMD(&s, Bitmap, 0, 0, 0, 0, 10, 0, 0);
    run(ip, &s);
    CHECK(!a->current.raster_valid);
    CHECK_NEAR(a->current.raster_pos[0], 15.7, 1e-6);
    seq_init(&s);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(&s, Bitmap, -1, 2, 0, 0, 0, 0, 1);
    run(ip, &s);
    CHECK(sc.overlay == NULL);
    CHECK(count(DIAG_GL_INVALID_VALUE) == 1);
    interp_destroy(ip);
}

static void test_draw_pixels(void)
{
    interp *ip = fresh();
    interp_set_resources(ip, px_fetch, NULL);
    /* 2 x 1 RGB: red, blue. */
    static const uint8_t rgb[6] = {255, 0, 0, 0, 0, 255};
    px_bytes[1] = rgb;
    px_sizes[1] = 6;
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 20, 10);
    CMD(&s, WindowPos2i, 10, 2);
    CMD(&s, PixelZoom, -2, 3);
    CMD(&s, PixelTransferf, GL_RED_SCALE, 0.5);
    CMD(&s, PixelTransferf, GL_GREEN_BIAS, 0.25);
    CMD(&s, DrawPixels, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, 2);
    run(ip, &s);
    CHECK(sc.overlay != NULL);
    if (sc.overlay) {
        /* Zoom -2: pixel 0 covers x 8..9, pixel 1 x 6..7; rows 2..4. */
        CHECK(overlay_px(9, 2)[0] == 128 && overlay_px(9, 2)[1] == 64);
        CHECK(overlay_px(8, 4)[0] == 128 && overlay_px(8, 4)[3] == 255);
        CHECK(overlay_px(7, 3)[2] == 255 && overlay_px(6, 3)[0] == 0);
        CHECK(overlay_px(10, 3)[3] == 0 && overlay_px(5, 3)[3] == 0);
        CHECK(overlay_px(8, 5)[3] == 0 && overlay_px(8, 1)[3] == 0);
    }
    /* Hostile positions and zooms: nothing drawn, nothing undefined. */
    seq_init(&s);
    CMD(&s, WindowPos2f, -3e38, 3e38);
    CMD(&s, PixelZoom, 1e-30, -1e30);
    CMD(&s, DrawPixels, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, 2);
    CMD(&s, PixelZoom, 3e38, 3e38);
    CMD(&s, WindowPos2f, 1, 1);
    CMD(&s, DrawPixels, 2, 1, GL_RGB, GL_UNSIGNED_BYTE, 2);
    CMD(&s, WindowPos2f, 3e38, -3e38);
    CMD(&s, Bitmap, 1, 1, 0, 0, 3e38, 3e38, 0);
    CMD(&s, Bitmap, 2, 1, -3e38, 3e38, 0, 0, 2);
    run(ip, &s);
    if (sc.overlay)
        CHECK(overlay_px(1, 1)[0] == 128 && overlay_px(19, 9)[0] == 128);
    /* Colour-index pixels and a copy of depth: noted, not drawn. */
    seq_init(&s);
    CMD(&s, DrawPixels, 2, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, 2);
    CMD(&s, CopyPixels, 0, 0, 2, 2, GL_DEPTH, 0);
    CMD(&s, CopyPixels, 0, 0, 2, 2, GL_RGB, 0); /* bad type */
    run(ip, &s);
    CHECK(count(DIAG_NOTE_PIXELS_OTHER) == 1);
    CHECK(count(DIAG_GL_INVALID_ENUM) == 1);
    interp_destroy(ip);
}

/* glReadBuffer, not recorded, can change only reads whose pixels the
 * trace lacks: a copy read back holds the read buffer's pixels already,
 * one not read back (id 0) or a glAccum does not. */
static void test_read_uses(void)
{
    const unsigned read = 1u << UNREC_USE_READ;
    for (int k = 0; k < 4; k++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, RasterPos2f, 0, 0);
        if (k == 0)
            CMD(&s, CopyPixels, 0, 0, 2, 2, GL_COLOR, 7);
        else if (k == 1)
            CMD(&s, CopyTexImage2D, GL_TEXTURE_2D, 0, GL_RGB, 0, 0, 2, 2, 0, 7);
        else if (k == 2)
            CMD(&s, CopyPixels, 0, 0, 2, 2, GL_COLOR, 0);
        else
            CMD(&s, Accum, GL_LOAD, 1.0);
        run(ip, &s);
        CHECK(((interp_unrecorded(ip)->uses & read) != 0) == (k >= 2));
        interp_destroy(ip);
    }
}

/* The image is in front of everything: a note says when GL would hide
 * some of it (the depth test on, or geometry drawn after it over its
 * pixels: k 1; k 3 draws it after but elsewhere, quiet). */
static void test_pixels_notes(void)
{
    static const uint8_t bits[1] = {0x80};
    px_bytes[0] = bits;
    px_sizes[0] = 1;
    for (int k = 0; k < 4; k++) {
        interp *ip = fresh();
        interp_set_resources(ip, px_fetch, NULL);
        seq s;
        seq_init(&s);
        if (k == 2)
            CMD(&s, Enable, GL_DEPTH_TEST);
        if (k != 1) { /* the triangle first: the text over it is exact */
            CMD(&s, Begin, GL_TRIANGLES);
            CMD(&s, Vertex2f, 0, 0);
            CMD(&s, Vertex2f, 1, 0);
            CMD(&s, Vertex2f, 0, 1);
            CMD0(&s, End);
        }
        CMD(&s, Bitmap, 1, 1, 0, 0, 0, 0, 1); /* the window's pixel (0, 0) */
        if (k == 1 || k == 3) {
            double o = k == 1 ? -1 : 0; /* over the pixel, or the upper right quarter */
            CMD(&s, Begin, GL_TRIANGLES);
            CMD(&s, Vertex2f, o, o);
            CMD(&s, Vertex2f, 1, o);
            CMD(&s, Vertex2f, o, 1);
            CMD0(&s, End);
        }
        run(ip, &s);
        interp_end_frame(ip);
        CHECK(sc.overlay != NULL);
        CHECK(count(DIAG_NOTE_PIXELS_DEPTH) == (k == 0 || k == 3 ? 0u : 1u));
        interp_destroy(ip);
    }
}

/* ---- Accumulation buffer ---------------------------------------------------- */

/* One accumulated pass: a triangle seen through a frustum moved by
 * (pdx, pdy) pixels of 320 x 240 and an eye moved by (ex, ey) around a
 * focus at 5, the triangle itself moved by mx. */
static void accum_pass(seq *s, double pdx, double pdy, double ex, double ey, double mx)
{
    const double top = 0.36397023426620234, right = top * 320 / 240;
    double dx = -(pdx * 2 * right / 320 + ex / 5), dy = -(pdy * 2 * top / 240 + ey / 5);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Frustum, -right + dx, right + dx, -top + dy, top + dy, 1, 30);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
    CMD(s, Translatef, -ex, -ey, 0);
    CMD(s, Translatef, mx, 0, 0);
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, -1, -1, -5);
    CMD(s, Vertex3f, 1, -1, -5);
    CMD(s, Vertex3f, 0, 1, -6);
    CMD0(s, End);
    CMD(s, Accum, GL_ACCUM, 0.25);
}

static void test_accum(void)
{
    static const double jit[4][2] = {{-0.375, -0.125}, {-0.125, 0.375}, {0.125, -0.375},
                                     {0.375, 0.125}};
    /* Jittered projection: one copy, antialiasing, no note. */
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 320, 240);
    for (int i = 0; i < 4; i++)
        accum_pass(&s, jit[i][0], jit[i][1], 0, 0, 0);
    CMD(&s, Accum, GL_RETURN, 1);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK_EQ_U(sc.antialias_depth, 2);
    CHECK(!sc.focal_blur);
    CHECK_EQ_U(count(DIAG_NOTE_ACCUM_PASSES) + count(DIAG_NOTE_ACCUM_WEIGHTS), 0);
    CHECK_EQ_U(count(DIAG_NOTE_PROJECTION), 0);
    interp_destroy(ip);

    /* The eye around a focal point at 5: one copy, focal blur. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 320, 240);
    for (int i = 0; i < 4; i++)
        accum_pass(&s, 0, 0, 0.1 * jit[i][0], 0.1 * jit[i][1], 0);
    CMD(&s, Accum, GL_RETURN, 1);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK_EQ_U(sc.antialias_depth, 0);
    CHECK(sc.focal_blur);
    CHECK_NEAR(sc.focal_point[2], -5, 1e-3);
    CHECK(sc.aperture > 0.1 && sc.aperture < 0.12); /* 2 sqrt(2) x the eyes' rms spread, 0.0395 */
    CHECK_EQ_U(count(DIAG_NOTE_ACCUM_PASSES), 0);
    interp_destroy(ip);

    /* The geometry moves (motion blur): one copy, the first pass, noted;
     * weights adding up to 1/2 are noted too. A draw after GL_RETURN adds. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 320, 240);
    for (int i = 0; i < 2; i++)
        accum_pass(&s, 0, 0, 0, 0, 0.1 * i);
    CMD(&s, Accum, GL_RETURN, 1);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, -1, -1, -5);
    CMD(&s, Vertex3f, 1, -1, -5);
    CMD(&s, Vertex3f, 0, 1, -6);
    CMD0(&s, End);
    CMD(&s, Accum, 0x1234, 1);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 2);
    CHECK(sc.nverts >= 1 && sc.verts[0].pos[0] == -1);
    CHECK_EQ_U(sc.antialias_depth, 0);
    CHECK(!sc.focal_blur);
    CHECK_EQ_U(count(DIAG_NOTE_ACCUM_PASSES), 1);
    CHECK_EQ_U(count(DIAG_NOTE_ACCUM_WEIGHTS), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    interp_destroy(ip);
}

/* ---- Fog coordinates, secondary colour, colour control: said when used --------- */

static void tri(seq *s)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, -1, -1, -5);
    CMD(s, Vertex3f, 1, -1, -5);
    CMD(s, Vertex3f, 0, 1, -5);
    CMD0(s, End);
}

static void test_secondary_notes(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_FOG);
    tri(&s);
    CMD(&s, Fogi, GL_FOG_COORD_SRC, 0x1234);
    CMD(&s, Fogi, GL_FOG_COORD_SRC, GL_FOG_COORD);
    tri(&s);
    CMD(&s, Disable, GL_FOG);
    tri(&s);
    CMD(&s, Enable, GL_COLOR_SUM);
    tri(&s);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    /* Unlit and untextured: both translated (test_fogsec.c); GL_EXP
     * fog of fog coordinates is interpolated per vertex, with a note. */
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD), 0);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD_VERTEX), 1);
    CHECK_EQ_U(count(DIAG_NOTE_COLOR_SUM), 0);
    CHECK(interp_state(ip)->a.fog.coord_src == GL_FOG_COORD);
    interp_destroy(ip);

    /* The current values, kept (GL 1.x 2.7: integers normalised). */
    ip = fresh();
    seq_init(&s);
    CMD(&s, SecondaryColor3ub, 255, 51, 0);
    CMD(&s, FogCoordfEXT, 3.5);
    run(ip, &s);
    CHECK_NEAR(interp_state(ip)->a.current.secondary[0], 1, 1e-6);
    CHECK_NEAR(interp_state(ip)->a.current.secondary[1], 0.2, 1e-6);
    CHECK_NEAR(interp_state(ip)->a.current.fog_coord, 3.5, 0);
    seq_init(&s);
    CMD(&s, SecondaryColor3fvEXT, 0.25, 0.5, 0.75);
    CMD(&s, FogCoorddv, -2);
    run(ip, &s);
    CHECK_NEAR(interp_state(ip)->a.current.secondary[2], 0.75, 0);
    CHECK_NEAR(interp_state(ip)->a.current.fog_coord, -2, 0);
    interp_destroy(ip);

    /* Lit and textured: GL_SINGLE_COLOR (the default) is noted where the
     * material has a highlight, GL_SEPARATE_SPECULAR_COLOR is not. */
    for (int sep = 0; sep < 2; sep++) {
        ip = fresh();
        seq_init(&s);
        CMD(&s, Enable, GL_LIGHTING);
        CMD(&s, Enable, GL_TEXTURE_2D);
        if (sep)
            CMD(&s, LightModeli, GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
        tri(&s); /* the default material has no highlight */
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_SINGLE_COLOR), 0);
        seq_init(&s);
        CMD(&s, Materialf, GL_FRONT, GL_SHININESS, 20);
        CMD(&s, Materialfv, GL_FRONT, GL_SPECULAR, 0.5, 0.5, 0.5, 1.0);
        tri(&s);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_SINGLE_COLOR), sep ? 0 : 1);
        CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 0);
        interp_destroy(ip);
    }
}

/* Pixels drawn before any geometry do not choose the camera; the image
 * then takes the camera's viewport, the same window pixels. */
static void test_pixels_first(void)
{
    static const uint8_t bits[1] = {0x80};
    px_bytes[0] = bits;
    px_sizes[0] = 1;
    interp *ip = fresh();
    interp_set_resources(ip, px_fetch, NULL);
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 50);
    CMD(&s, Ortho, 0, 100, 0, 50, -1, 1);
    CMD(&s, RasterPos2i, 30, 20);
    CMD(&s, Bitmap, 1, 1, 0, 0, 0, 0, 1);
    CMD0(&s, LoadIdentity); /* the projection */
    CMD(&s, Viewport, 10, 5, 80, 40);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK(sc.overlay != NULL && sc.overlay_w == 80 && sc.overlay_h == 40);
    CHECK(sc.camera.width == 80);
    if (sc.overlay && sc.overlay_w == 80) {
        /* Mesa puts glRasterPos2i(30, 20) at x = 29.9999981 (single
         * precision, measured with OSMesa): window pixel 29. */
        CHECK(overlay_px(19, 15)[3] == 255);
        CHECK(overlay_px(20, 15)[3] == 0);
        CHECK(overlay_px(30, 20)[3] == 0);
    }
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    test_paper_modelview();
    test_teapot();
    test_transforms();
    test_stacks();
    test_rejected();
    test_assembly();
    test_flat_lines();
    test_culling();
    test_polygon_mode();
    test_attributes();
    test_blend();
    test_normal_notes();
    test_runs();
    test_painter();
    test_alloc_failure();
    test_fast_path();
    test_fast_path_cuts();
    test_alloc_translation();
    test_shape_budget();
    test_eval_maths();
    test_eval_draw();
    test_eval_rejected();
    test_skipped();
    test_raster_pos();
    test_bitmap();
    test_draw_pixels();
    test_pixels_notes();
    test_read_uses();
    test_pixels_first();
    test_accum();
    test_secondary_notes();
    test_multitex();
    scene_finish(&sc);
    return CHECK_RESULT("test_interp");
}
