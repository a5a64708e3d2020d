/* test_blend.c: blending and logic ops (interp_blend.c, interp_dest.c).
 *
 * What transmit and filter reproduce is mapped without a note whatever
 * lies behind; what reads the colour behind is exact over the clear colour
 * alone and noted elsewhere: over an earlier draw, where the draw covers a
 * pixel twice with an operation that is not idempotent, where its colour
 * varies over a face, and in a frame that never cleared. The notes come
 * only from draws that can change a pixel.
 */
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "tracegen.h"

static void view(seq *s, bool clear)
{
    CMD(s, Viewport, 0, 0, 100, 100);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD(s, Ortho, 0, 100, 0, 100, -1, 1);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD(s, ClearColor, 0.2, 0.4, 0.6, 1);
    if (clear)
        CMD(s, Clear, GL_COLOR_BUFFER_BIT);
}

static void quad(seq *s, double x0, double y0, double x1, double y1)
{
    CMD(s, Begin, GL_QUADS);
    CMD(s, Vertex2f, x0, y0);
    CMD(s, Vertex2f, x1, y0);
    CMD(s, Vertex2f, x1, y1);
    CMD(s, Vertex2f, x0, y1);
    CMD0(s, End);
}

static const scene_mesh *last_mesh(void)
{
    return sc.nmeshes ? &sc.meshes[sc.nmeshes - 1] : NULL;
}

static const float *last_colour(void)
{
    const scene_mesh *m = last_mesh();
    return m && m->tri_count ? sc.verts[sc.tris[m->first_tri].v[0]].color : NULL;
}

static bool near(double a, double b) { return a > b - 0.003 && a < b + 0.003; }

/* XOR over the clear colour: GL's bytes, opaque; over an earlier quad, or
 * in a frame with no clear: noted and drawn as GL_COPY. */
static void test_xor(void)
{
    for (int c = 0; c < 4; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        view(&s, c != 3);
        CMD(&s, Color3f, 0.8, 0.2, 0.2);
        if (c == 1)
            quad(&s, 10, 10, 50, 50); /* under the XOR quad */
        if (c == 2)
            quad(&s, 70, 70, 90, 90); /* beside it */
        CMD(&s, Enable, GL_COLOR_LOGIC_OP);
        CMD(&s, LogicOp, GL_XOR);
        CMD(&s, Color3f, 0.9, 0.6, 0.1);
        quad(&s, 20, 20, 60, 60);
        run(ip, &s);
        bool known = c == 0 || c == 2;
        CHECK_EQ_U(count(DIAG_NOTE_LOGIC_OP), known ? 0 : 1);
        const float *col = last_colour();
        CHECK(col && last_mesh()->look.blend == SCENE_BLEND_OPAQUE && col[3] == 1);
        if (col && known) /* 230 ^ 51, 153 ^ 102, 26 ^ 153 */
            CHECK(near(col[0], (230 ^ 51) / 255.0) && near(col[1], (153 ^ 102) / 255.0) &&
                  near(col[2], (26 ^ 153) / 255.0));
        if (col && !known)
            CHECK(near(col[0], 0.9) && near(col[1], 0.6) && near(col[2], 0.1));
        interp_destroy(ip);
    }
}

/* Two quads of one glBegin that overlap: XOR twice is not XOR (noted),
 * AND twice is AND (not noted); two that only share an edge are fine. */
static void test_self_overlap(void)
{
    static const GLenum ops[3] = {GL_XOR, GL_AND, GL_XOR};
    for (int c = 0; c < 3; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        view(&s, true);
        CMD(&s, Enable, GL_COLOR_LOGIC_OP);
        CMD(&s, LogicOp, ops[c]);
        CMD(&s, Color3f, 0.9, 0.6, 0.1);
        double x1 = c == 2 ? 40 : 30;
        CMD(&s, Begin, GL_QUADS);
        CMD(&s, Vertex2f, 10, 10);
        CMD(&s, Vertex2f, 40, 10);
        CMD(&s, Vertex2f, 40, 40);
        CMD(&s, Vertex2f, 10, 40);
        CMD(&s, Vertex2f, x1, 10);
        CMD(&s, Vertex2f, 80, 10);
        CMD(&s, Vertex2f, 80, 40);
        CMD(&s, Vertex2f, x1, 40);
        CMD0(&s, End);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_LOGIC_OP), c == 0 ? 1 : 0);
        interp_destroy(ip);
    }
}

/* Ops of the source alone over anything: no note. GL_COPY and a logic op
 * left enabled with GL_COPY: opaque (blending is off). XOR of a lit quad:
 * noted. XOR with its colour varying over the quad: noted. */
static void test_source_ops(void)
{
    for (int c = 0; c < 4; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        view(&s, true);
        CMD(&s, Color3f, 0.8, 0.2, 0.2);
        quad(&s, 10, 10, 50, 50);
        CMD(&s, Enable, GL_BLEND);
        CMD(&s, BlendFunc, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        CMD(&s, Enable, GL_COLOR_LOGIC_OP);
        CMD(&s, LogicOp, c == 0 ? GL_COPY_INVERTED : c == 1 ? GL_COPY : GL_XOR);
        if (c == 2)
            CMD(&s, Enable, GL_LIGHTING);
        CMD(&s, Color4f, 0.9, 0.6, 0.1, 0.5);
        if (c == 3) {
            CMD(&s, Begin, GL_TRIANGLES);
            CMD(&s, Vertex2f, 60, 60);
            CMD(&s, Color4f, 0.1, 0.6, 0.1, 0.5);
            CMD(&s, Vertex2f, 90, 60);
            CMD(&s, Vertex2f, 90, 90);
            CMD0(&s, End);
        } else {
            quad(&s, 20, 20, 60, 60);
        }
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_LOGIC_OP), c >= 2 ? 1 : 0);
        CHECK_EQ_U(count(DIAG_NOTE_BLEND), 0);
        const float *col = last_colour();
        CHECK(col && last_mesh()->look.blend == SCENE_BLEND_OPAQUE && col[3] == 1);
        if (col && c == 0)
            CHECK(near(col[0], 25 / 255.0) && near(col[1], 102 / 255.0) && near(col[2], 229 / 255.0));
        interp_destroy(ip);
    }
}

/* Blends over an earlier quad: the multiplying blend is a filter, the
 * constant alpha a transmit, exact (no note); a coloured constant colour
 * and GL_MIN read what is behind: noted. Over the clear colour alone they
 * are exact. */
static void test_blends(void)
{
    for (int c = 0; c < 6; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        view(&s, true);
        bool over = c < 4;
        CMD(&s, Color3f, 0.8, 0.2, 0.2);
        quad(&s, 10, 10, 50, 50);
        CMD(&s, Enable, GL_BLEND);
        CMD(&s, BlendColor, 0.2, 0.5, 0.8, 0.3);
        if (c == 0)
            CMD(&s, BlendFunc, GL_ZERO, GL_SRC_COLOR);
        else if (c == 1)
            CMD(&s, BlendFunc, GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA);
        else if (c == 2 || c == 4)
            CMD(&s, BlendFunc, GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR);
        else
            CMD(&s, BlendEquation, GL_MIN);
        CMD(&s, Color4f, 0.9, 0.6, 0.1, 0.5);
        if (over)
            quad(&s, 20, 20, 60, 60);
        else
            quad(&s, 60, 60, 90, 90);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_BLEND_DEST), c == 2 || c == 3 ? 1 : 0);
        CHECK_EQ_U(count(DIAG_NOTE_BLEND) + count(DIAG_NOTE_BLEND_EQUATION), 0);
        const scene_mesh *m = last_mesh();
        const float *col = last_colour();
        CHECK(m && col);
        if (m && col && c == 0) /* behind times the colour */
            CHECK(m->look.blend == SCENE_BLEND_ALPHA && m->look.filter == 1 && near(col[0], 0.9) &&
                  near(col[2], 0.1) && col[3] == 0);
        if (m && col && c == 1) /* transmit 0.7, 0.3 of the colour */
            CHECK(m->look.blend == SCENE_BLEND_ALPHA && m->look.filter == 0 && near(col[3], 0.3) &&
                  near(col[0], 0.9));
        if (m && col && c == 4) /* 0.9 x 0.2 + 0.2 x 0.8 */
            CHECK(m->look.blend == SCENE_BLEND_OPAQUE &&
                  near(col[0], (230 / 255.0) * (51 / 255.0) + (51 / 255.0) * (204 / 255.0)));
        interp_destroy(ip);
    }
}

/* A multiplying blend on faces drawn as lines: lines have no filter, so
 * over the clear colour alone they take GL's product, opaque, and over an
 * earlier draw they are noted (before, the lines took the filter's colour
 * with alpha 0 and vanished, silently). */
static void test_filter_lines(void)
{
    for (int c = 0; c < 2; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        view(&s, true);
        CMD(&s, Color3f, 0.8, 0.2, 0.2);
        quad(&s, 10, 10, 50, 50);
        CMD(&s, PolygonMode, GL_FRONT_AND_BACK, GL_LINE);
        CMD(&s, Enable, GL_BLEND);
        CMD(&s, BlendFunc, GL_ZERO, GL_SRC_COLOR);
        CMD(&s, Color3f, 0.9, 0.6, 0.1);
        if (c == 0)
            quad(&s, 60, 60, 90, 90);
        else
            quad(&s, 20, 20, 60, 60);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_BLEND_DEST), c == 1 ? 1 : 0);
        CHECK(sc.nlines == 4);
        if (sc.nlines && c == 0) {
            const float *col = sc.lines[sc.nlines - 1].color[0];
            CHECK(near(col[0], (230 / 255.0) * (51 / 255.0)) &&
                  near(col[1], (153 / 255.0) * (102 / 255.0)) &&
                  near(col[2], (26 / 255.0) * (153 / 255.0)) && col[3] == 1);
        }
        interp_destroy(ip);
    }
}

/* Blending off, and no logic op: nothing of this path, no note. */
static void test_off(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    view(&s, true);
    CMD(&s, BlendFunc, GL_ZERO, GL_SRC_COLOR);
    CMD(&s, BlendEquation, GL_MIN);
    CMD(&s, LogicOp, GL_XOR);
    quad(&s, 20, 20, 60, 60);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_BLEND_DEST) + count(DIAG_NOTE_LOGIC_OP) + count(DIAG_NOTE_BLEND), 0);
    CHECK(last_mesh() && last_mesh()->look.blend == SCENE_BLEND_OPAQUE);
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    test_xor();
    test_self_overlap();
    test_source_ops();
    test_blends();
    test_filter_lines();
    test_off();
    scene_finish(&sc);
    return CHECK_RESULT("test_blend");
}
