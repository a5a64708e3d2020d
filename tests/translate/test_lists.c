/* test_lists.c: display lists and vertex arrays in the interpreter.
 *
 * Lists: bodies fetched through the resource callback, calls, state kept
 * after a call, glCallLists with every name type and glListBase, nesting
 * cut at 64, glDeleteLists, GL_COMPILE_AND_EXECUTE, carried by
 * interp_copy_state; and the shared output: repeated calls that draw the
 * same become one prototype and instances, calls in another inherited
 * colour get a prototype of their own, a list that loads an absolute
 * matrix stays inline. Arrays: @ArrayData with glDrawArrays,
 * glDrawElements (ubyte, ushort, uint), glDrawRangeElements,
 * glArrayElement, type conversion, and draws the trace cannot supply.
 * The writer: a prototype with a colour per vertex carries its colours as
 * one image (2x2 texels per face), or keeps its texture_list when the
 * fourth texel would need clamping; outside lists, strips of one look are
 * one mesh2 whose smooth colours are a grid of texels, one per vertex.
 */
#include <GL/gl.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "outbuf.h"
#include "povwrite.h"
#include "povwrite_texture.h"
#include "tracegen.h"

/* A body: one triangle in the current colour, then a move of +10 in x. */
static uint32_t tri_body(void)
{
    seq b;
    seq_init(&b);
    CMD(&b, Begin, GL_TRIANGLES);
    CMD(&b, Vertex2f, 0, 0);
    CMD(&b, Vertex2f, 1, 0);
    CMD(&b, Vertex2f, 0, 1);
    CMD0(&b, End);
    CMD(&b, Translatef, 10, 0, 0);
    return add_body(&b);
}

static void test_calls_and_sharing(void)
{
    interp *ip = fresh();
    uint32_t body = tri_body();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, NewList, 1, GL_COMPILE, body);
    CMD0(&s, EndList);
    CMD(&s, Color3f, 1, 0, 0);
    for (int i = 0; i < 5; i++)
        CMD(&s, CallList, 1);
    CMD(&s, Color3f, 0, 1, 0); /* another inherited colour: another prototype */
    CMD(&s, CallList, 1);
    CMD(&s, CallList, 1);
    CMD(&s, CallList, 99); /* undefined: nothing */
    run(ip, &s);
    /* The modelview moved on by 10 per call (state kept after a call). */
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 70, 1e-9);
    CHECK_EQ_U(sc.nprotos, 2);
    CHECK_EQ_U(sc.ninstances, 7);
    CHECK_EQ_U(sc.ntris, 2); /* one triangle per prototype */
    CHECK_EQ_U(sc.nmeshes, 2);
    for (size_t i = 0; i < sc.nmeshes; i++)
        CHECK(sc.meshes[i].proto == i + 1);
    for (size_t i = 0; i < sc.ninstances; i++) {
        CHECK_EQ_U(sc.instances[i].proto, i < 5 ? 0 : 1);
        CHECK_NEAR(sc.instances[i].to_eye.m[12], 10.0 * (double)i, 1e-9);
    }
    CHECK_NEAR(sc.verts[sc.tris[0].v[0]].color[0], 1, 0);
    CHECK_NEAR(sc.verts[sc.tris[1].v[0]].color[1], 1, 0);
    CHECK_EQ_U(count(DIAG_IGNORED), 0);
    interp_destroy(ip);
    free_bodies();
}

static void test_single_call_inline(void)
{
    interp *ip = fresh();
    uint32_t body = tri_body();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, NewList, 3, GL_COMPILE_AND_EXECUTE, body); /* drawn once, here */
    CMD0(&s, EndList);
    run(ip, &s);
    CHECK_EQ_U(sc.nprotos, 0);
    CHECK_EQ_U(sc.ninstances, 0);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 10, 1e-9);
    interp_destroy(ip);
    free_bodies();
}

static void test_absolute_matrix_inline(void)
{
    interp *ip = fresh();
    seq b;
    seq_init(&b);
    CMD0(&b, LoadIdentity);
    CMD(&b, Begin, GL_TRIANGLES);
    CMD(&b, Vertex2f, 0, 0);
    CMD(&b, Vertex2f, 1, 0);
    CMD(&b, Vertex2f, 0, 1);
    CMD0(&b, End);
    uint32_t body = add_body(&b);
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, NewList, 1, GL_COMPILE, body);
    CMD(&s, Translatef, 5, 0, 0);
    CMD(&s, CallList, 1);
    CMD(&s, Translatef, 7, 0, 0);
    CMD(&s, CallList, 1);
    run(ip, &s);
    /* Both calls draw at the origin: the same image, not the same output
     * relative to their modelviews; each stays inline. */
    CHECK_EQ_U(sc.nprotos, 0);
    CHECK_EQ_U(sc.ntris, 2);
    interp_destroy(ip);
    free_bodies();
}

static void test_calllists_types(void)
{
    interp *ip = fresh();
    /* List 100 + k moves x by k + 1. */
    for (int k = 0; k < 4; k++) {
        seq b;
        seq_init(&b);
        CMD(&b, Translatef, k + 1, 0, 0);
        seq s;
        seq_init(&s);
        CMD(&s, NewList, 100 + k, GL_COMPILE, add_body(&b));
        run(ip, &s);
    }
    struct {
        GLenum type;
        uint8_t bytes[8];
        size_t n, len;
        double expect; /* x moved by */
    } cases[] = {
        {GL_UNSIGNED_BYTE, {0, 3}, 2, 2, 1 + 4},
        {GL_BYTE, {2, 1}, 2, 2, 3 + 2},
        {GL_UNSIGNED_SHORT, {3, 0, 1, 0}, 2, 4, 4 + 2},
        {GL_SHORT, {2, 0}, 1, 2, 3},
        {GL_2_BYTES, {0, 1, 0, 2}, 2, 4, 2 + 3},
        {GL_3_BYTES, {0, 0, 3}, 1, 3, 4},
        {GL_4_BYTES, {0, 0, 0, 1}, 1, 4, 2},
        {GL_INT, {2, 0, 0, 0, 3, 0, 0, 0}, 2, 8, 3 + 4},
        {GL_UNSIGNED_INT, {1, 0, 0, 0}, 1, 4, 2},
        {GL_FLOAT, {0, 0, 0x40, 0x40}, 1, 4, 4}, /* 3.0f */
    };
    double x = 0;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        seq s;
        seq_init(&s);
        CMD(&s, ListBase, 100);
        seq_cmd_bytes(&s, RGL_OP_CallLists, cases[c].bytes, cases[c].len,
                      (const double[]){(double)cases[c].n, cases[c].type}, 2);
        run(ip, &s);
        x += cases[c].expect;
        CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], x, 1e-9);
    }
    /* A negative GL_BYTE offset from a higher base. */
    seq s;
    seq_init(&s);
    CMD(&s, ListBase, 103);
    seq_cmd_bytes(&s, RGL_OP_CallLists, (const uint8_t[]){0xfd}, 1,
                  (const double[]){1, GL_BYTE}, 2); /* 103 - 3 = 100 */
    /* A count that does not match the names: rejected. */
    seq_cmd_bytes(&s, RGL_OP_CallLists, (const uint8_t[]){0, 0}, 2,
                  (const double[]){3, GL_UNSIGNED_BYTE}, 2);
    run(ip, &s);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], x + 1, 1e-9);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 1);
    interp_destroy(ip);
    free_bodies();
}

static void test_nesting_and_delete(void)
{
    interp *ip = fresh();
    /* List 7 moves by 1 and calls itself: 64 levels run. */
    seq b;
    seq_init(&b);
    CMD(&b, Translatef, 1, 0, 0);
    CMD(&b, CallList, 7);
    uint32_t self = add_body(&b);
    seq s;
    seq_init(&s);
    CMD(&s, NewList, 7, GL_COMPILE, self);
    CMD(&s, CallList, 7);
    run(ip, &s);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], INTERP_MAX_LIST_NESTING, 1e-9);
    CHECK_EQ_U(count(DIAG_LIMIT), 1);

    /* Deleted, then a call does nothing; the name is defined again. */
    seq_init(&s);
    CMD0(&s, LoadIdentity);
    CMD(&s, DeleteLists, 5, 3);
    CMD(&s, CallList, 7);
    run(ip, &s);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 0, 0);
    seq_init(&b);
    CMD(&b, Translatef, 0, 2, 0);
    uint32_t up = add_body(&b);
    seq_init(&s);
    CMD(&s, NewList, 7, GL_COMPILE, up);
    CMD(&s, CallList, 7);
    CMD(&s, NewList, 0, GL_COMPILE, up); /* list 0: invalid */
    CMD(&s, NewList, 8, 0x1234, up);     /* bad mode */
    CMD(&s, NewList, 9, GL_COMPILE, 77); /* no such resource */
    CMD(&s, CallList, 9);
    run(ip, &s);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[13], 2, 0);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK_EQ_U(count(DIAG_IGNORED), 1);

    /* The table is context state: a copy carries it. */
    interp *other = interp_create(NULL, NULL);
    interp_set_resources(other, fetch_bodies, NULL);
    interp_copy_state(other, ip);
    seq_init(&s);
    CMD(&s, CallList, 7);
    rgl_error err;
    CHECK(interp_run(other, s.data, s.len, 0, &err) == RGL_OK);
    seq_free(&s);
    CHECK_NEAR(interp_matrix(other, INTERP_MV)->m[13], 4, 0);
    interp_destroy(other);
    interp_destroy(ip);
    free_bodies();
}

/* A list that calls itself twice would run 2^64 bodies: cut, not hung. */
static void test_call_budget(void)
{
    interp *ip = fresh();
    seq b;
    seq_init(&b);
    CMD(&b, CallList, 4);
    CMD(&b, CallList, 4);
    uint32_t twice = add_body(&b);
    seq s;
    seq_init(&s);
    CMD(&s, NewList, 4, GL_COMPILE, twice);
    CMD(&s, CallList, 4);
    CMD(&s, CallList, 4);
    run(ip, &s);
    CHECK(count(DIAG_LIMIT) >= 1);
    interp_destroy(ip);
    free_bodies();
}

/* A list of 30 vertices that calls itself twice (issue 12: 524 bytes took
 * 4.9 s and 1.96 GB) is cut by the frame budget: the scene stops at the
 * budget's vertices, the rest of the frame is not run, and the next frame
 * has a budget of its own. */
static void test_frame_budget(void)
{
    interp *ip = fresh();
    seq b;
    seq_init(&b);
    CMD(&b, Begin, GL_TRIANGLES);
    for (int i = 0; i < 30; i++)
        CMD(&b, Vertex3f, i % 3 == 1, i % 3 == 2, -1);
    CMD0(&b, End);
    CMD(&b, CallList, 4);
    CMD(&b, CallList, 4);
    uint32_t bomb = add_body(&b);
    seq s;
    seq_init(&s);
    CMD(&s, NewList, 4, GL_COMPILE, bomb);
    CMD(&s, CallList, 4);
    CMD(&s, Translatef, 5, 0, 0); /* after the cut: not run */
    run(ip, &s);
    const char *cut = interp_frame_cut(ip);
    CHECK(cut != NULL && strstr(cut, "over the frame budget of 4194304 vertices") != NULL &&
          strstr(cut, "(in a display list)") != NULL);
    CHECK(sc.nverts <= INTERP_BUDGET_VERTICES && sc.nverts > INTERP_BUDGET_VERTICES - 30);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 0, 0);
    interp_end_frame(ip);
    CHECK_EQ_U(count(DIAG_IGNORED), 0); /* the open glBegin the cut left is not the trace's */
    interp_begin_frame(ip);
    CHECK(interp_frame_cut(ip) == NULL && sc.nverts == 0);
    seq_init(&s);
    CMD(&s, Translatef, 5, 0, 0);
    run(ip, &s);
    CHECK_NEAR(interp_matrix(ip, INTERP_MV)->m[12], 5, 0);
    interp_destroy(ip);
    free_bodies();
}

/* A list whose body the trace cannot supply: the call is skipped, and the
 * frame knows what it was drawn without (the CLI then exits 1). */
static void test_missing_body(void)
{
    interp *ip = fresh();
    uint32_t n;
    seq s;
    seq_init(&s);
    CMD(&s, NewList, 3, GL_COMPILE, 42); /* no resource 42 */
    CMD(&s, CallList, 3);
    CMD(&s, CallList, 3);
    run(ip, &s);
    const char *m = interp_frame_missing(ip, &n);
    CHECK(m != NULL && strcmp(m, "display list 3 (body #42 unreadable: missing or malformed resource)") == 0);
    CHECK(n >= 1);
    interp_begin_frame(ip);
    CHECK(interp_frame_missing(ip, &n) == NULL && n == 0);
    interp_destroy(ip);
}

/* ---- Arrays ------------------------------------------------------------------------------ */

static void array_data(seq *s, GLenum array, int first, int size, GLenum type, const void *data,
                       size_t bytes)
{
    seq_cmd_bytes(s, RGL_OP_ArrayData, data, bytes,
                  (const double[]){array, first, size, type}, 4);
}

static void test_arrays(void)
{
    interp *ip = fresh();
    static const float pos[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 2}};
    static const uint8_t col[5][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255},
                                      {255, 255, 255, 255}, {0, 0, 0, 255}};
    static const int16_t nrm[5][3] = {{0, 0, 32767}, {0, 0, 32767}, {0, 0, 32767},
                                      {0, 0, 32767}, {0, 0, 32767}};
    seq s;
    seq_init(&s);
    array_data(&s, GL_VERTEX_ARRAY, 0, 2, GL_FLOAT, pos, sizeof pos);
    array_data(&s, GL_COLOR_ARRAY, 0, 4, GL_UNSIGNED_BYTE, col, sizeof col);
    array_data(&s, GL_NORMAL_ARRAY, 0, 3, GL_SHORT, nrm, sizeof nrm);
    CMD(&s, DrawArrays, GL_QUADS, 0, 4);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 2);
    CHECK_EQ_U(sc.nverts, 4);
    CHECK_NEAR(sc.verts[1].color[1], 1, 0);
    CHECK_NEAR(sc.verts[2].pos[0], 1, 0);
    CHECK_NEAR(sc.verts[0].normal[2], 1, 1e-9);
    /* The current colour and normal are what they were before the draw,
     * as Mesa leaves them (GL: indeterminate). */
    CHECK_NEAR(interp_state(ip)->a.current.color[0], 1, 0);
    CHECK_NEAR(interp_state(ip)->a.current.color[1], 1, 0);
    CHECK_NEAR(interp_state(ip)->a.current.color[2], 1, 0);
    CHECK_NEAR(interp_state(ip)->a.current.normal[2], 1, 0);

    /* Indexed: ubyte, ushort and uint indices, from element 1 on. */
    static const uint8_t i8[3] = {1, 2, 3};
    static const uint16_t i16[3] = {1, 3, 2};
    static const uint32_t i32[3] = {2, 3, 1};
    static const float pos3[3][3] = {{1, 0, -1}, {1, 1, -1}, {0, 1, -1}};
    const void *idx[3] = {i8, i16, i32};
    const GLenum types[3] = {GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT, GL_UNSIGNED_INT};
    const size_t sizes[3] = {1, 2, 4};
    for (int k = 0; k < 3; k++) {
        seq_init(&s);
        array_data(&s, GL_VERTEX_ARRAY, 1, 3, GL_FLOAT, pos3, sizeof pos3);
        if (k == 2)
            seq_cmd_bytes(&s, RGL_OP_DrawRangeElements, idx[k], 3 * sizes[k],
                          (const double[]){GL_TRIANGLES, 1, 3, 3, types[k]}, 5);
        else
            seq_cmd_bytes(&s, RGL_OP_DrawElements, idx[k], 3 * sizes[k],
                          (const double[]){GL_TRIANGLES, 3, types[k]}, 3);
        run(ip, &s);
    }
    CHECK_EQ_U(sc.ntris, 5);
    const scene_vertex *v = &sc.verts[sc.tris[2].v[0]];
    CHECK_NEAR(v->pos[0], 1, 0);
    CHECK_NEAR(v->pos[2], -1, 0);

    /* An index beyond the recorded elements: the draw is skipped. */
    seq_init(&s);
    array_data(&s, GL_VERTEX_ARRAY, 1, 3, GL_FLOAT, pos3, sizeof pos3);
    seq_cmd_bytes(&s, RGL_OP_DrawElements, (const uint8_t[]){1, 2, 4}, 3,
                  (const double[]){GL_TRIANGLES, 3, GL_UNSIGNED_BYTE}, 3);
    /* The records last one draw: this one has no array, so draws nothing. */
    CMD(&s, DrawArrays, GL_TRIANGLES, 0, 3);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 5);
    CHECK_EQ_U(count(DIAG_IGNORED), 1);

    /* glArrayElement inside glBegin/glEnd, doubles and ints. */
    static const double dpos[2][3] = {{0, 0, -2}, {3, 0, -2}};
    static const int32_t ipos[1][2] = {{0, 3}};
    seq_init(&s);
    CMD(&s, Begin, GL_TRIANGLES);
    array_data(&s, GL_VERTEX_ARRAY, 0, 3, GL_DOUBLE, dpos, sizeof dpos);
    CMD(&s, ArrayElement, 0);
    array_data(&s, GL_VERTEX_ARRAY, 1, 3, GL_DOUBLE, dpos[1], sizeof dpos[1]);
    CMD(&s, ArrayElement, 1);
    array_data(&s, GL_VERTEX_ARRAY, 7, 2, GL_INT, ipos, sizeof ipos);
    CMD(&s, ArrayElement, 7);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 6);
    v = &sc.verts[sc.tris[5].v[2]];
    CHECK_NEAR(v->pos[1], 3, 0);
    CHECK_NEAR(v->pos[2], 0, 0);
    interp_destroy(ip);
}

static int texel(float c) { return (int)(c * 255.0f + 0.5f); }

/* One triangle with three colours, then a move of +10 in x. */
static uint32_t coloured_body(const float c[3][3])
{
    static const float xy[3][2] = {{0, 0}, {1, 0}, {0, 1}};
    seq b;
    seq_init(&b);
    CMD(&b, Begin, GL_TRIANGLES);
    for (int k = 0; k < 3; k++) {
        CMD(&b, Color3f, c[k][0], c[k][1], c[k][2]);
        CMD(&b, Vertex2f, xy[k][0], xy[k][1]);
    }
    CMD0(&b, End);
    CMD(&b, Translatef, 10, 0, 0);
    return add_body(&b);
}

static void test_colour_image(void)
{
    /* D = B + C - A stays in 0..255 with corner 0 as A. */
    static const float soft[3][3] = {{0.2f, 0.4f, 0.6f}, {0.6f, 0.4f, 0.2f}, {0.4f, 0.8f, 0.4f}};
    /* Red, green, blue: D leaves 0..255 whichever corner is A. */
    static const float rgb[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const float *cs[3] = {soft[0], soft[1], soft[2]}, *cr[3] = {rgb[0], rgb[1], rgb[2]};
    CHECK(povtex_colour_origin(cs) == 0);
    CHECK(povtex_colour_origin(cr) == -1);
    /* Black, white, white: only a white corner as A keeps D in range. */
    static const float bww[3][3] = {{0, 0, 0}, {1, 1, 1}, {1, 1, 1}};
    const float *cb[3] = {bww[0], bww[1], bww[2]};
    CHECK(povtex_colour_origin(cb) == 1);

    interp *ip = fresh();
    uint32_t bs = coloured_body(soft), br = coloured_body(rgb);
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, NewList, 1, GL_COMPILE, bs);
    CMD0(&s, EndList);
    CMD(&s, NewList, 2, GL_COMPILE, br);
    CMD0(&s, EndList);
    for (int i = 0; i < 3; i++)
        CMD(&s, CallList, 1);
    CMD(&s, Translatef, 0, 5, 0);
    for (int i = 0; i < 3; i++)
        CMD(&s, CallList, 2);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nprotos, 2);

    povwriter *w = povwriter_create();
    CHECK(w != NULL);
    write_sdl_with(w, NULL);
    /* The soft prototype: its colours as an image, each corner at the
     * centre of its texel; the RGB one keeps its texture_list. */
    CHECK_EQ_U(occurrences(sdl, "image_map{png"), 1);
    CHECK_EQ_U(occurrences(sdl, "texture_list{3,"), 1);
    CHECK_EQ_U(occurrences(sdl, "uv_indices{1,"), 1);
    CHECK(strstr(sdl, "uv_vectors{3,\n<0.25,0.25>,\n<0.75,0.25>,\n<0.25,0.75>}") != NULL);
    CHECK(strstr(sdl, "interpolate 2") != NULL);
    const povtex_image *im = povwriter_image(w, 0);
    CHECK(im != NULL && povwriter_image(w, 1) == NULL);
    if (im) {
        CHECK(im->width == 2 && im->height == 2 && !im->alpha);
        CHECK(strstr(sdl, im->name) != NULL);
        const uint8_t *a = im->rgba, *b = a + 4, *c = a + 8, *d = a + 12;
        for (int k = 0; k < 3; k++) {
            CHECK(a[k] == texel(soft[0][k]));
            CHECK(b[k] == texel(soft[1][k]));
            CHECK(c[k] == texel(soft[2][k]));
            CHECK(d[k] == b[k] + c[k] - a[k]);
        }
    }
    povwriter_destroy(w);
    interp_destroy(ip);
    free_bodies();
}

/* Grid colour (i rows, j columns): linear in both, so each quad's colours
 * are a parallelogram; sixteen and more of them. */
static void grid_colour(int i, int j, float c[3])
{
    c[0] = 0.1f + 0.1f * (float)i;
    c[1] = 0.2f + 0.05f * (float)j;
    c[2] = 0.5f;
}

/* The numbers after "name{count," in sdl, up to n. */
static size_t sdl_numbers(const char *name, double *out, size_t n)
{
    const char *p = strstr(sdl, name);
    if (!p)
        return 0;
    p = strchr(p, ',');
    size_t k = 0;
    while (p && *p && *p != '}' && k < n) {
        while (*p && strchr(",\n<> ", *p))
            p++;
        if (*p == '}' || !*p)
            break;
        char *e;
        out[k++] = strtod(p, &e);
        p = e;
    }
    return k;
}

/* A strip of `quads` quads in one colour run drawn apart, with its top
 * corner at column 6 black (no parallelogram in colour with its
 * neighbours), written as SDL into sdl. ramp: the colours repeat every 8
 * columns and blue rises along the strip. */
static void black_corner_strip(int quads, bool ramp)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Translatef, 0, 0, -20);
    CMD(&s, Begin, GL_TRIANGLE_STRIP);
    for (int j = 0; j <= quads; j++)
        for (int r = 1; r >= 0; r--) {
            float c[3];
            grid_colour(r, ramp ? j % 8 : j, c);
            if (ramp)
                c[2] = 0.01f * (float)j; /* linear along the strip */
            if (j == 6 && r == 1)
                c[0] = c[1] = c[2] = 0;
            CMD(&s, Color3f, c[0], c[1], c[2]);
            CMD(&s, Vertex2f, j, r);
        }
    CMD0(&s, End);
    run(ip, &s);
    interp_end_frame(ip);
    povwriter *w = povwriter_create();
    CHECK(w != NULL);
    write_sdl_with(w, NULL);
    povwriter_destroy(w);
    interp_destroy(ip);
}

static void test_colour_grid(void)
{
    /* Five triangle strips over a 6 x 5 grid, each its own glBegin/End,
     * one look and transform: one mesh2, every vertex once, its colour
     * one texel of the image at its uv (taken by face_indices). */
    enum { COLS = 6, ROWS = 5 };
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Translatef, 0, 0, -20);
    for (int i = 0; i < ROWS; i++) {
        CMD(&s, Begin, GL_TRIANGLE_STRIP);
        for (int j = 0; j <= COLS; j++)
            for (int r = 1; r >= 0; r--) {
                float c[3];
                grid_colour(i + r, j, c);
                CMD(&s, Color3f, c[0], c[1], c[2]);
                CMD(&s, Vertex2f, j, i + r);
            }
        CMD0(&s, End);
        /* Another look in between: the strips are meshes of their own. */
        CMD(&s, ShadeModel, GL_FLAT);
        CMD(&s, Color3f, 0.9, 0.9, 0.9);
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, Vertex3f, 10, i, 0);
        CMD(&s, Vertex3f, 11, i, 0);
        CMD(&s, Vertex3f, 10, i + 1, 0);
        CMD0(&s, End);
        CMD(&s, ShadeModel, GL_SMOOTH);
    }
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nmeshes, 2 * ROWS);
    povwriter *w = povwriter_create();
    CHECK(w != NULL);
    write_sdl_with(w, NULL);
    size_t nv = (COLS + 1) * (ROWS + 1);
    CHECK_EQ_U(occurrences(sdl, "mesh2{"), 2); /* the strips, the flat triangles */
    CHECK_EQ_U(occurrences(sdl, "texture_list"), 0);
    CHECK_EQ_U(occurrences(sdl, "face_indices{60,"), 1);
    CHECK_EQ_U(occurrences(sdl, "face_indices{5,"), 1);
    CHECK_EQ_U(occurrences(sdl, "uv_indices"), 0);
    CHECK_EQ_U(occurrences(sdl, "image_map{png"), 1);
    double pos[3 * 64], uv[2 * 64];
    CHECK_EQ_U(sdl_numbers("vertex_vectors{", pos, 3 * 64), 3 * nv);
    CHECK_EQ_U(sdl_numbers("uv_vectors{", uv, 2 * 64), 2 * nv);
    const povtex_image *im = povwriter_image(w, 0);
    CHECK(im != NULL && povwriter_image(w, 1) == NULL);
    for (size_t v = 0; im && v < nv; v++) {
        int tx = (int)(uv[2 * v] * im->width), ty = (int)(uv[2 * v + 1] * im->height);
        CHECK_NEAR(uv[2 * v] * im->width, tx + 0.5, 1e-4); /* the texel's centre */
        CHECK_NEAR(uv[2 * v + 1] * im->height, ty + 0.5, 1e-4);
        float c[3];
        grid_colour((int)pos[3 * v + 1], (int)pos[3 * v], c);
        const uint8_t *t = im->rgba + ((size_t)ty * (size_t)im->width + (size_t)tx) * 4;
        for (int k = 0; k < 3 && tx >= 0 && ty >= 0 && tx < im->width && ty < im->height; k++)
            CHECK(t[k] == texel(c[k]));
    }
    /* Texels of the grid's neighbours: the four corners of a face's cell. */
    CHECK(im && im->width * im->height <= 2 * (int)nv);
    povwriter_destroy(w);
    interp_destroy(ip);

    /* A strip whose quads are no parallelograms in colour (one corner
     * black): those faces keep blocks of their own, through uv_indices. */
    black_corner_strip(12, false);
    CHECK_EQ_U(occurrences(sdl, "uv_indices{24,"), 1);
    /* 26 vertices on the grid, then 3 texels for each of the 4 faces
     * that touch the black corner's two quads. */
    CHECK(strstr(sdl, "uv_vectors{38,") != NULL);

    /* The same black corner in a strip of 60 quads: its 4 faces get copies
     * of their corners (122 + 12 vertices), the uv stay parallel. */
    black_corner_strip(60, true);
    CHECK_EQ_U(occurrences(sdl, "uv_indices"), 0);
    CHECK(strstr(sdl, "vertex_vectors{134,") != NULL);
    CHECK(strstr(sdl, "uv_vectors{134,") != NULL);
    CHECK(strstr(sdl, "face_indices{120,") != NULL);
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_bodies;
    test_calls_and_sharing();
    test_single_call_inline();
    test_absolute_matrix_inline();
    test_calllists_types();
    test_nesting_and_delete();
    test_call_budget();
    test_frame_budget();
    test_missing_body();
    test_arrays();
    test_colour_image();
    test_colour_grid();
    scene_finish(&sc);
    return CHECK_RESULT("test_lists");
}
