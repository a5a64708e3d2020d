/* test_nurbs.c: GLU NURBS in the translator (translate/gl/interp_nurbs.c).
 *
 * The evaluation against values worked out by hand (the classic hill's
 * top, a uniform B-spline at a knot, a rational quarter circle) and against
 * the Bezier evaluator of interp_eval.c; then whole sequences: how many
 * triangles a surface gives, untrimmed and trimmed (a square hole, with and
 * without an outer loop), outline modes, tessellator mode, bad input.
 */
#include <GL/gl.h>
#include <GL/glu.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "interp_internal.h"
#include "tracegen.h"
#include "wire.h"

/* A command whose scalars come from v in order and whose blobs are the
 * float arrays blobs[0..] of nfloats[0..] values. */
static void nurbs_cmd(seq *s, uint32_t opcode, const double *v, size_t n,
                      const float *const *blobs, const size_t *nfloats)
{
    static rgl_cmd cmd;
    static uint8_t bytes[4][1 << 18];
    if (rgl_cmd_init(&cmd, opcode) != RGL_OK) {
        CHECK(!"known opcode");
        return;
    }
    size_t used = 0, nb = 0;
    for (uint32_t i = 0; i < cmd.nargs; i++) {
        rgl_arg *a = &cmd.arg[i];
        if (cmd.info->args[i].kind == RGL_ARG_BLOB) {
            for (size_t k = 0; k < nfloats[nb]; k++)
                rgl_put_u32(bytes[nb] + 4 * k, rgl_f32_bits(blobs[nb][k]));
            a->bytes = bytes[nb];
            a->count = (uint32_t)(4 * nfloats[nb]);
            nb++;
            continue;
        }
        double x = used < n ? v[used] : 0;
        used++;
        if (a->type == RGL_T_f || a->type == RGL_T_d)
            a->v.f = x;
        else if (a->type == RGL_T_i || a->type == RGL_T_sz)
            a->v.i = (int64_t)x;
        else
            a->v.u = (uint64_t)x;
    }
    if (s->len + (1u << 20) > s->cap) {
        s->cap = s->len + (2u << 20);
        s->data = realloc(s->data, s->cap);
    }
    size_t w = rgl_cmd_encode(&cmd, s->data + s->len, s->cap - s->len);
    CHECK(w > 0);
    s->len += w;
}

static const float knots4[8] = {0, 0, 0, 0, 1, 1, 1, 1};
static float hill[4][4][3];

static void make_hill(void)
{
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            hill[u][v][0] = 2.0f * ((float)u - 1.5f);
            hill[u][v][1] = 2.0f * ((float)v - 1.5f);
            hill[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0f : -3.0f;
        }
}

/* ---- Evaluation ------------------------------------------------------------------ */

static void test_hill_top(void)
{
    make_hill();
    double pts[48], kn[8], out[3], du[3], dv[3];
    for (int i = 0; i < 48; i++)
        pts[i] = (&hill[0][0][0])[i];
    for (int i = 0; i < 8; i++)
        kn[i] = knots4[i];
    CHECK(interp_nurbs_surface_at(pts, 3, kn, 4, 4, kn, 4, 4, 0.5, 0.5, out, du, dv));
    /* Bernstein weights at 1/2: 1/8, 3/8, 3/8, 1/8; the middle four points
     * (z = 3) weigh (3/4)^2 = 9/16, the others 7/16 (z = -3). */
    CHECK_NEAR(out[0], 0, 1e-12);
    CHECK_NEAR(out[1], 0, 1e-12);
    CHECK_NEAR(out[2], 3 * 9.0 / 16 - 3 * 7.0 / 16, 1e-12);
    CHECK_NEAR(du[0], 6, 1e-12); /* x is linear in u: 3 x (2 per point) */
    CHECK_NEAR(du[2], 0, 1e-12); /* the top */
    CHECK_NEAR(dv[2], 0, 1e-12);
    /* The corners are the corner points (clamped knots); u past the domain
     * is clamped to it. */
    CHECK(interp_nurbs_surface_at(pts, 3, kn, 4, 4, kn, 4, 4, 1.0, 0.0, out, NULL, NULL));
    CHECK_NEAR(out[0], 3, 1e-12);
    CHECK_NEAR(out[1], -3, 1e-12);
    CHECK_NEAR(out[2], -3, 1e-12);
    CHECK(interp_nurbs_surface_at(pts, 3, kn, 4, 4, kn, 4, 4, 7.0, -2.0, out, NULL, NULL));
    CHECK_NEAR(out[0], 3, 1e-12);
    CHECK_NEAR(out[1], -3, 1e-12);
}

/* With knots {0,0,0,0,1,1,1,1} a NURBS is the Bezier patch of its points. */
static void test_bezier_agrees(void)
{
    double pts[4 * 4 * 4], kn[8];
    for (int i = 0; i < 8; i++)
        kn[i] = knots4[i];
    for (int i = 0; i < 64; i++)
        pts[i] = sin(1.7 * i) * 3 + (i % 4 == 3 ? 5 : 0); /* w from 2 to 8 */
    for (double u = 0; u <= 1.0; u += 0.125) {
        for (double v = 0; v <= 1.0; v += 0.25) {
            double a[4], ad[2][4], b[4], bd[2][4];
            CHECK(interp_nurbs_surface_at(pts, 4, kn, 4, 4, kn, 4, 4, u, v, a, ad[0], ad[1]));
            interp_eval_surface(pts, 4, 4, 4, u, v, b, bd[0], bd[1]);
            for (int c = 0; c < 4; c++) {
                CHECK_NEAR(a[c], b[c], 1e-9);
                CHECK_NEAR(ad[0][c], bd[0][c], 1e-9);
                CHECK_NEAR(ad[1][c], bd[1][c], 1e-9);
            }
        }
    }
}

static void test_curves(void)
{
    /* A uniform cubic B-spline: at an inner knot the point is
     * (P0 + 4 P1 + P2) / 6, the derivative (P2 - P0) / 2. */
    double kn[8] = {0, 1, 2, 3, 4, 5, 6, 7}, p[4] = {0, 6, 12, 30}, out, der;
    CHECK(interp_nurbs_curve_at(p, 1, kn, 4, 4, 3.0, &out, &der));
    CHECK_NEAR(out, (0 + 4 * 6 + 12) / 6.0, 1e-12);
    CHECK_NEAR(der, (12 - 0) / 2.0, 1e-12);
    CHECK(interp_nurbs_curve_at(p, 1, kn, 4, 4, 4.0, &out, NULL)); /* the domain's end */
    CHECK_NEAR(out, (6 + 4 * 12 + 30) / 6.0, 1e-12);

    /* A rational quadratic quarter circle: (1,0), (1,1) w = sqrt(2)/2, (0,1). */
    double s = sqrt(0.5), q[9] = {1, 0, 1, s, s, s, 0, 1, 1}, kq[6] = {0, 0, 0, 1, 1, 1};
    for (double t = 0; t <= 1.0; t += 0.1) {
        double h[3];
        CHECK(interp_nurbs_curve_at(q, 3, kq, 3, 3, t, h, NULL));
        CHECK_NEAR(hypot(h[0] / h[2], h[1] / h[2]), 1, 1e-12);
    }
    /* Repeated inner knots (a break), and sizes that are not a curve. */
    double kr[7] = {0, 0, 0.5, 0.5, 0.5, 1, 1}, pr[5] = {0, 1, 2, 3, 4};
    CHECK(interp_nurbs_curve_at(pr, 1, kr, 5, 2, 0.5, &out, NULL));
    CHECK_NEAR(out, 3, 1e-12); /* order 2 over a triple knot: the point there */
    CHECK(!interp_nurbs_curve_at(pr, 1, kr, 5, 0, 0.5, &out, NULL));
    CHECK(!interp_nurbs_curve_at(pr, 1, kr, 1, 2, 0.5, &out, NULL));
    double flat[4] = {1, 1, 1, 1};
    CHECK(!interp_nurbs_curve_at(pr, 1, flat, 2, 2, 1, &out, NULL)); /* no span */
}

/* ---- Sequences -------------------------------------------------------------------- */

enum { NURB = 7 };

/* A bilinear 2 x 2 surface over [0,1]^2 (16 x 16 cells of 2 triangles). */
static void flat_surface(seq *s)
{
    static const float kn[4] = {0, 0, 1, 1};
    static const float pts[12] = {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0};
    const float *blobs[3] = {kn, kn, pts};
    size_t n[3] = {4, 4, 12};
    /* nurb, sKnotCount, tKnotCount, sStride, tStride, sOrder, tOrder, type */
    const double v[] = {NURB, 4, 4, 6, 3, 2, 2, GL_MAP2_VERTEX_3};
    nurbs_cmd(s, RGL_OP_NurbsSurface, v, 8, blobs, n);
}

static void pwl(seq *s, const float *pts, int count)
{
    const float *blobs[1] = {pts};
    size_t n[1] = {(size_t)count * 2};
    const double v[] = {NURB, count, 2, GLU_MAP1_TRIM_2};
    CMD(s, BeginTrim, NURB);
    nurbs_cmd(s, RGL_OP_PwlCurve, v, 4, blobs, n);
    CMD(s, EndTrim, NURB);
}

static const float outer[10] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0};
static const float hole[10] = {0.25f, 0.25f, 0.25f, 0.75f, 0.75f, 0.75f, 0.75f, 0.25f, 0.25f, 0.25f};

static size_t surface_tris(int trims, GLenum display, GLenum mode)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, NewNurbsRenderer, NURB);
    if (display)
        CMD(&s, NurbsProperty, NURB, GLU_DISPLAY_MODE, display);
    if (mode)
        CMD(&s, NurbsProperty, NURB, GLU_NURBS_MODE, mode);
    CMD(&s, BeginSurface, NURB);
    flat_surface(&s);
    if (trims & 1)
        pwl(&s, outer, 5);
    if (trims & 2)
        pwl(&s, hole, 5);
    CMD(&s, EndSurface, NURB);
    run(ip, &s);
    size_t n = sc.ntris;
    interp_destroy(ip);
    return n;
}

static void test_surface_counts(void)
{
    CHECK_EQ_U(surface_tris(0, 0, 0), 16 * 16 * 2);
    /* GLU_PATH_LENGTH (the default) samples by the view: a note says the
     * grid may be finer than GLU's. */
    CHECK(dlog.e[DIAG_NOTE_NURBS_SAMPLING].count == 1);
    /* A square hole of half the side takes a quarter of the cells. */
    CHECK_EQ_U(surface_tris(3, 0, 0), 16 * 16 * 2 - 8 * 8 * 2);
    CHECK_EQ_U(surface_tris(1, 0, 0), 16 * 16 * 2);
    /* Trims without an outer loop: GLU draws nothing. */
    CHECK_EQ_U(surface_tris(2, 0, 0), 0);
    CHECK(dlog.e[DIAG_NOTE_NURBS_TRIM].count == 0); /* the trims are exact */
    /* Tessellator mode: the program draws; a note says so. */
    CHECK_EQ_U(surface_tris(0, 0, GLU_NURBS_TESSELLATOR), 0);
    CHECK(dlog.e[DIAG_NOTE_NURBS_TESSELLATOR].count == 1);
    /* The outline modes draw lines, no triangles; near trims GLU outlines
     * triangles of its own (a note). */
    CHECK_EQ_U(surface_tris(3, GLU_OUTLINE_POLYGON, 0), 0);
    CHECK(sc.nlines > 0);
    CHECK(dlog.e[DIAG_NOTE_NURBS_OUTLINE].count == 1);
}

static void test_outlines(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, NewNurbsRenderer, NURB);
    CMD(&s, NurbsProperty, NURB, GLU_DISPLAY_MODE, GLU_OUTLINE_PATCH);
    CMD(&s, BeginSurface, NURB);
    flat_surface(&s);
    CMD(&s, EndSurface, NURB);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 0);
    CHECK_EQ_U(sc.nlines, 4 * 16); /* the four edges, 16 segments each */
    interp_destroy(ip);

    ip = fresh();
    seq_init(&s);
    CMD(&s, NewNurbsRenderer, NURB);
    CMD(&s, NurbsProperty, NURB, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);
    CMD(&s, BeginSurface, NURB);
    flat_surface(&s);
    CMD(&s, EndSurface, NURB);
    run(ip, &s);
    CHECK_EQ_U(sc.nlines, 2 * 16 * 17); /* every grid edge once */
    CHECK(dlog.e[DIAG_NOTE_NURBS_OUTLINE].count == 0); /* untrimmed: GLU's grid lines */
    interp_destroy(ip);

    /* A curve: 16 segments per knot span. */
    ip = fresh();
    seq_init(&s);
    static const float kn[6] = {0, 0, 0, 1, 1, 1};
    static const float pts[9] = {0, 0, 0, 1, 1, 0, 2, 0, 0};
    const float *blobs[2] = {kn, pts};
    size_t nf[2] = {6, 9};
    const double v[] = {NURB, 6, 3, 3, GL_MAP1_VERTEX_3};
    CMD(&s, NewNurbsRenderer, NURB);
    CMD(&s, BeginCurve, NURB);
    nurbs_cmd(&s, RGL_OP_NurbsCurve, v, 5, blobs, nf);
    CMD(&s, EndCurve, NURB);
    run(ip, &s);
    CHECK_EQ_U(interp_frame_segments(ip), 16);
    interp_destroy(ip);

    /* GLU_DOMAIN_DISTANCE at 40 steps a unit: GLU's own grid, no note. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, NewNurbsRenderer, NURB);
    CMD(&s, NurbsProperty, NURB, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    CMD(&s, NurbsProperty, NURB, GLU_U_STEP, 40);
    CMD(&s, NurbsProperty, NURB, GLU_V_STEP, 40);
    CMD(&s, BeginSurface, NURB);
    flat_surface(&s);
    CMD(&s, EndSurface, NURB);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 40 * 40 * 2);
    CHECK(dlog.e[DIAG_NOTE_NURBS_SAMPLING].count == 0);
    interp_destroy(ip);

    /* GLU_PATH_LENGTH of 10 pixels, the unit square 500 pixels wide in a
     * 1000 x 1000 viewport: at least 50 steps each way, as GLU takes. */
    ip = fresh();
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 1000, 1000);
    CMD(&s, NewNurbsRenderer, NURB);
    CMD(&s, NurbsProperty, NURB, GLU_SAMPLING_TOLERANCE, 10);
    CMD(&s, BeginSurface, NURB);
    flat_surface(&s);
    CMD(&s, EndSurface, NURB);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 50 * 50 * 2);
    CHECK(dlog.e[DIAG_NOTE_NURBS_SAMPLING].count == 0);
    interp_destroy(ip);

    /* The same viewport given by gluLoadSamplingMatrices: used while
     * GLU_AUTO_LOAD_MATRIX is false, not after it is true again. */
    for (int autoload = 0; autoload < 2; autoload++) {
        ip = fresh();
        seq_init(&s);
        CMD(&s, Viewport, 0, 0, 100, 100); /* the square: 50 pixels, 5 steps */
        CMD(&s, NewNurbsRenderer, NURB);
        CMD(&s, NurbsProperty, NURB, GLU_SAMPLING_TOLERANCE, 10);
        CMD(&s, NurbsProperty, NURB, GLU_AUTO_LOAD_MATRIX, 0);
        CMD(&s, LoadSamplingMatrices, NURB, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 1, 0,
            0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1000, 1000);
        if (autoload)
            CMD(&s, NurbsProperty, NURB, GLU_AUTO_LOAD_MATRIX, 1);
        CMD(&s, BeginSurface, NURB);
        flat_surface(&s);
        CMD(&s, EndSurface, NURB);
        run(ip, &s);
        CHECK_EQ_U(sc.ntris, autoload ? 16 * 16 * 2 : 50 * 50 * 2);
        interp_destroy(ip);
    }
}

/* A GL_MAP2_NORMAL piece gives the normals (GL_AUTO_NORMAL would give
 * (0, 0, 1) for the flat square); GL_AUTO_NORMAL alone gives du x dv. */
static void test_normals(void)
{
    static const float kn[4] = {0, 0, 1, 1};
    static const float nrm[12] = {0.6f, 0, 0.8f, 0.6f, 0, 0.8f, 0.6f, 0, 0.8f, 0.6f, 0, 0.8f};
    const float *blobs[3] = {kn, kn, nrm};
    size_t n[3] = {4, 4, 12};
    const double v[] = {NURB, 4, 4, 6, 3, 2, 2, GL_MAP2_NORMAL};
    for (int with_piece = 0; with_piece < 2; with_piece++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, Enable, GL_LIGHTING);
        CMD(&s, Enable, GL_AUTO_NORMAL);
        CMD(&s, Normal3f, 0, 1, 0);
        CMD(&s, NewNurbsRenderer, NURB);
        CMD(&s, BeginSurface, NURB);
        flat_surface(&s);
        if (with_piece)
            nurbs_cmd(&s, RGL_OP_NurbsSurface, v, 8, blobs, n);
        CMD(&s, EndSurface, NURB);
        run(ip, &s);
        CHECK(sc.nverts > 0);
        for (size_t i = 0; i < sc.nverts; i++) {
            CHECK_NEAR(sc.verts[i].normal[0], with_piece ? 0.6 : 0, 1e-6);
            CHECK_NEAR(sc.verts[i].normal[1], 0, 1e-6);
            CHECK_NEAR(sc.verts[i].normal[2], with_piece ? 0.8 : 1, 1e-6);
        }
        /* The current normal is left as glNormal3f set it. */
        CHECK_NEAR(ip->st.a.current.normal[1], 1, 0);
        interp_destroy(ip);
    }
}

static void test_bad_input(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    static const float down[4] = {0, 1, 0, 1}; /* decreasing knots */
    static const float pts[12] = {0};
    const float *blobs[3] = {down, down, pts};
    size_t n[3] = {4, 4, 12};
    const double v[] = {NURB, 4, 4, 6, 3, 2, 2, GL_MAP2_VERTEX_3};
    CMD(&s, NewNurbsRenderer, NURB);
    CMD(&s, BeginSurface, NURB);
    nurbs_cmd(&s, RGL_OP_NurbsSurface, v, 8, blobs, n);
    size_t short_n[3] = {4, 4, 9}; /* the points do not match the sizes */
    const float *ok_blobs[3] = {knots4, knots4, pts};
    nurbs_cmd(&s, RGL_OP_NurbsSurface, v, 8, ok_blobs, short_n);
    CMD(&s, EndSurface, NURB);
    CMD(&s, EndSurface, NURB);                          /* without its begin */
    CMD(&s, NurbsProperty, NURB, GLU_DISPLAY_MODE, 5);  /* not a mode */
    CMD(&s, NurbsProperty, NURB, 12345, 1);             /* not a property */
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 0);
    CHECK(dlog.e[DIAG_IGNORED].count == 5);
    interp_destroy(ip);
}

/* A trim of 20000 oblique edges over a 500 x 500 grid: bounded work (a
 * scan per grid row, not a test per cell and edge). */
static void test_large_trim(void)
{
    enum { N = 20000 };
    static float circle[2 * (N + 1)];
    for (int i = 0; i <= N; i++) {
        double t = 2 * M_PI * (i % N) / N;
        circle[2 * i] = (float)(0.5 + 0.45 * cos(t));
        circle[2 * i + 1] = (float)(0.5 + 0.45 * sin(t));
    }
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, NewNurbsRenderer, NURB);
    CMD(&s, NurbsProperty, NURB, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    CMD(&s, NurbsProperty, NURB, GLU_U_STEP, 500);
    CMD(&s, NurbsProperty, NURB, GLU_V_STEP, 500);
    CMD(&s, BeginSurface, NURB);
    flat_surface(&s);
    pwl(&s, circle, N + 1);
    CMD(&s, EndSurface, NURB);
    run(ip, &s);
    /* About pi 0.45^2 of 500^2 cells, two triangles each. */
    CHECK(sc.ntris > 2 * 150000 && sc.ntris < 2 * 170000);
    CHECK(dlog.e[DIAG_NOTE_NURBS_TRIM].count == 1);
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    test_hill_top();
    test_bezier_agrees();
    test_curves();
    test_surface_counts();
    test_outlines();
    test_normals();
    test_bad_input();
    test_large_trim();
    scene_finish(&sc);
    return CHECK_RESULT("test_nurbs");
}
