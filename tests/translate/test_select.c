/* test_select.c: render modes and the name stack (interp_select.c), and
 * the scissor box (interp_scissor.c).
 *
 * Geometry and clears in GL_SELECT or GL_FEEDBACK mode leave the scene
 * as it was; the calls GL rejects are rejected; each mesh and solid drawn
 * in GL_RENDER mode carries the name stack of its draw, and the writer
 * names it in the SDL.
 */
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "interp_internal.h"
#include "outbuf.h"
#include "povwrite.h"
#include "tracegen.h"

static void triangle(seq *s)
{
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex2f, 0, 0);
    CMD(s, Vertex2f, 0.5f, 0);
    CMD(s, Vertex2f, 0, 0.5f);
    CMD0(s, End);
}

static bool names_are(uint32_t id, const uint32_t *want, uint32_t n)
{
    uint32_t got;
    const uint32_t *v = scene_names(&sc, id, &got);
    if (n == 0)
        return v == NULL && got == 0;
    return v && got == n && memcmp(v, want, n * sizeof *v) == 0;
}

/* A picking pass, then the real draw: only the real draw is in the scene,
 * a clear in GL_SELECT mode clears nothing, and the camera is the real
 * draw's (not the pick matrix's). */
static void test_select_pass(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, ClearColor, 0, 0, 1, 1);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(&s, SelectBuffer, 64);
    CMD(&s, RenderMode, GL_SELECT, 0);
    CMD0(&s, InitNames);
    CMD(&s, PushName, 3);
    CMD(&s, ClearColor, 1, 0, 0, 1);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Scalef, 50, 50, 1); /* a pick matrix */
    CMD(&s, MatrixMode, GL_MODELVIEW);
    triangle(&s);
    CMD(&s, SolidSphere, 0.5, 8, 8);
    CMD(&s, RenderMode, GL_RENDER, 1);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD0(&s, LoadIdentity);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    run(ip, &s);
    CHECK_EQ_U(sc.nverts + sc.ntris + sc.nsolids + sc.nlines + sc.npoints, 0);
    CHECK(sc.background[2] == 1 && sc.background[0] == 0);
    CHECK_EQ_U(count(DIAG_NOTE_RENDER_MODE), 1);
    /* Leaving GL_SELECT empties the stack. */
    CHECK_EQ_U(interp_state(ip)->nnames, 0);

    seq_init(&s);
    triangle(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK(sc.have_camera && sc.camera.right[0] > 1.5); /* identity: 2 wide, not 2/50 */
    CHECK_EQ_U(sc.meshes[0].look.names, 0);
    /* GL_FEEDBACK draws nothing either. */
    seq_init(&s);
    CMD(&s, FeedbackBuffer, 100, GL_3D);
    CMD(&s, RenderMode, GL_FEEDBACK, 0);
    CMD(&s, PassThrough, 1.5f);
    CMD(&s, Translatef, 1, 0, 0);
    triangle(&s);
    CMD(&s, RenderMode, GL_RENDER, 12);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION) + count(DIAG_GL_INVALID_ENUM), 0);
    interp_destroy(ip);
}

/* Names in the render pass label what is drawn; a change of the stack
 * starts a new mesh, and the SDL says the names. */
static void test_names(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST); /* draws in one plane stay in one run */
    CMD0(&s, InitNames);
    CMD(&s, PushName, 1);
    CMD(&s, PushName, 4);
    triangle(&s);
    triangle(&s); /* same names: the same mesh */
    CMD(&s, LoadName, 5);
    triangle(&s);
    CMD0(&s, PopName);
    CMD0(&s, PopName);
    triangle(&s);
    CMD0(&s, PopName); /* ignored outside GL_SELECT, as GL does */
    CMD(&s, LoadName, 9);
    CMD(&s, PushName, 7);
    CMD(&s, SolidSphere, 0.25, 8, 8);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(count(DIAG_GL_STACK_UNDERFLOW) + count(DIAG_GL_INVALID_OPERATION), 0);
    CHECK_EQ_U(sc.nmeshes, 3);
    CHECK_EQ_U(sc.ntris, 4);
    static const uint32_t n14[] = {1, 4}, n15[] = {1, 5}, n7[] = {7};
    if (sc.nmeshes == 3) {
        CHECK(sc.meshes[0].tri_count == 2 && names_are(sc.meshes[0].look.names, n14, 2));
        CHECK(names_are(sc.meshes[1].look.names, n15, 2));
        CHECK(names_are(sc.meshes[2].look.names, NULL, 0));
    }
    CHECK_EQ_U(sc.nsolids, 1);
    if (sc.nsolids == 1)
        CHECK(names_are(sc.solids[0].look.names, n7, 1));

    write_sdl();
    const char *a = strstr(sdl, "// names: 1 4\n"), *b = strstr(sdl, "// names: 1 5\n");
    const char *c = strstr(sdl, "// names: 7\n");
    CHECK(a && b && c && a < b);
    CHECK(a && strstr(a, "mesh2") != NULL);
    CHECK(c && strncmp(c + strlen("// names: 7\n"), "sphere", 6) == 0);
    interp_destroy(ip);
}

/* What GL rejects: enums, a mode without its buffer, buffers changed in
 * their own mode, stack limits in GL_SELECT mode, glScissor sizes. */
static void test_rejected(void)
{
    interp *ip = fresh();
    seq s;
    /* Without a buffer Mesa reports an error and enters the mode all the
     * same (OSMesa: GL_RENDER_MODE reads GL_SELECT after it). */
    seq_init(&s);
    CMD(&s, RenderMode, GL_SELECT, 0);   /* no select buffer */
    triangle(&s);
    CMD(&s, RenderMode, GL_RENDER, 0);
    CMD(&s, RenderMode, GL_FEEDBACK, 0); /* no feedback buffer */
    CMD(&s, RenderMode, GL_RENDER, 0);
    CMD(&s, SelectBuffer, 0);
    CMD(&s, RenderMode, GL_SELECT, 0);   /* a buffer of size 0: none (Mesa) */
    CMD(&s, RenderMode, GL_RENDER, 0);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 3);
    CHECK_EQ_U(sc.ntris, 0);
    CHECK(interp_state(ip)->render_mode == GL_RENDER);

    seq_init(&s);
    CMD(&s, RenderMode, 0x1234, 0);
    CMD(&s, FeedbackBuffer, 10, 0x1234);
    CMD(&s, SelectBuffer, -1);
    CMD(&s, Scissor, 0, 0, -1, 4);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 2);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 2);
    CHECK(!interp_state(ip)->a.scissor.set);

    diag_clear(&dlog);
    seq_init(&s);
    CMD(&s, SelectBuffer, 16);
    CMD(&s, RenderMode, GL_SELECT, 0);
    CMD(&s, SelectBuffer, 16);  /* in GL_SELECT mode */
    CMD0(&s, PopName);          /* underflow */
    CMD(&s, LoadName, 2);       /* empty stack */
    for (int i = 0; i < INTERP_MAX_NAME_STACK + 1; i++)
        CMD(&s, PushName, (uint32_t)i);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, PushName, 1);       /* not between glBegin and glEnd */
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_OPERATION), 3);
    CHECK_EQ_U(count(DIAG_GL_STACK_UNDERFLOW), 1);
    CHECK_EQ_U(count(DIAG_GL_STACK_OVERFLOW), 1);
    CHECK_EQ_U(interp_state(ip)->nnames, INTERP_MAX_NAME_STACK);

    /* What Mesa accepts in glEnable (checked with OSMesa): the client
     * arrays (silently: the draws' @ArrayData say what they read), and 8
     * clip planes; the ninth is an error. */
    diag_clear(&dlog);
    seq_init(&s);
    CMD(&s, RenderMode, GL_RENDER, 0);
    CMD(&s, Enable, GL_VERTEX_ARRAY);
    CMD(&s, Enable, GL_NORMAL_ARRAY);
    CMD(&s, Disable, GL_COLOR_ARRAY);
    CMD(&s, Enable, GL_CLIP_PLANE0 + 6);
    CMD(&s, Enable, GL_CLIP_PLANE0 + 7);
    CMD(&s, Enable, GL_CLIP_PLANE0 + 8);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK(interp_state(ip)->a.caps[INTERP_CAP_CLIP_PLANE7]);

    /* glBlendEquation and glLogicOp: kept, bad enums rejected, noted where
     * a draw uses what the scene does not draw (GL_COPY is no change). */
    diag_clear(&dlog);
    seq_init(&s);
    CMD(&s, BlendEquation, 0x1234);
    CMD(&s, LogicOp, GL_SET + 1);
    CMD(&s, Enable, GL_COLOR_LOGIC_OP);
    CMD(&s, LogicOp, GL_COPY);
    CMD(&s, Enable, GL_BLEND);
    CMD(&s, Disable, GL_SCISSOR_TEST);
    CMD(&s, Begin, GL_POINTS);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 2);
    CHECK_EQ_U(count(DIAG_NOTE_COLOR_MASK) + count(DIAG_NOTE_BLEND_EQUATION), 0);
    /* An empty draw changes no pixel: no note. A point XORed onto what the
     * frame did not clear: noted, and blending is off while the logic op
     * is on; without the logic op, GL_MAX over it is noted. */
    seq_init(&s);
    CMD(&s, BlendEquation, GL_MAX);
    CMD(&s, LogicOp, GL_XOR);
    CMD(&s, Begin, GL_POINTS);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_LOGIC_OP) + count(DIAG_NOTE_BLEND_DEST), 0);
    seq_init(&s);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex2f, 0, 0);
    CMD0(&s, End);
    CMD(&s, Disable, GL_COLOR_LOGIC_OP);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex2f, 0, 0);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_LOGIC_OP), 1);
    CHECK_EQ_U(count(DIAG_NOTE_BLEND_DEST), 1);
    CHECK_EQ_U(count(DIAG_NOTE_COLOR_MASK) + count(DIAG_NOTE_BLEND_EQUATION), 0);
    CHECK(interp_state(ip)->a.color_buffer.blend_equation == GL_MAX);

    /* glScissor is an attribute (GL_SCISSOR_BIT). */
    seq_init(&s);
    CMD(&s, Scissor, 1, 2, 3, 4);
    CMD(&s, PushAttrib, GL_SCISSOR_BIT);
    CMD(&s, Scissor, 5, 6, 7, 8);
    CMD0(&s, PopAttrib);
    run(ip, &s);
    const int32_t *box = interp_state(ip)->a.scissor.box;
    CHECK(interp_state(ip)->a.scissor.set && box[0] == 1 && box[1] == 2 && box[2] == 3 &&
          box[3] == 4);
    interp_destroy(ip);
}

/* A scissored clear: a box of the clear colour behind what is drawn,
 * through the frame's camera; a box that holds the viewport clears all;
 * triangles a box cuts carry it, lines are noted. */
static void test_scissor_clear(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 200, 100);
    CMD(&s, Enable, GL_SCISSOR_TEST);
    CMD(&s, ClearColor, 1, 0, 0, 1);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);   /* unset box: the whole window */
    CMD(&s, Scissor, -10, -10, 400, 300);
    CMD(&s, ClearColor, 0, 1, 0, 1);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);   /* holds the viewport: all */
    CMD(&s, Scissor, 50, 0, 100, 50);
    CMD(&s, ClearColor, 0, 0, 1, 1);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);   /* a box */
    CMD(&s, Scissor, 150, 50, 100, 100);   /* half outside the viewport */
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT);
    run(ip, &s);
    CHECK(sc.background[1] == 1 && sc.background[2] == 0);
    CHECK_EQ_U(count(DIAG_NOTE_SCISSOR) + count(DIAG_NOTE_SCISSOR_CLEAR), 0);
    CHECK_EQ_U(sc.ntris, 0); /* placed at the frame's end */
    seq_init(&s);
    CMD(&s, Disable, GL_SCISSOR_TEST);
    triangle(&s);
    CMD(&s, Enable, GL_SCISSOR_TEST);
    triangle(&s); /* scissored: clipped by the writer */
    CMD(&s, Begin, GL_LINES); /* scissored lines: drawn whole, noted */
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 1);
    CMD0(&s, End);
    CMD(&s, Clear, GL_COLOR_BUFFER_BIT); /* after a draw: noted */
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(count(DIAG_NOTE_SCISSOR), 1);
    CHECK_EQ_U(count(DIAG_NOTE_SCISSOR_CLEAR), 1);
    CHECK_EQ_U(sc.nmeshes, 3); /* two draws (painter), the boxes */
    CHECK_EQ_U(sc.ntris, 2 + 2 * 3);
    if (sc.nmeshes == 3) {
        const scene_look *l0 = &sc.meshes[0].look, *l1 = &sc.meshes[1].look;
        CHECK(!l0->scissored && l1->scissored);
        CHECK(l1->scissor[0] == 150 && l1->scissor[1] == 50 && l1->scissor[2] == 100 &&
              l1->scissor[3] == 100);
        const scene_mesh *m = &sc.meshes[2];
        CHECK(m->in_eye && !m->look.lit && m->tri_count == 6);
        /* Identity projection, viewport 200 x 100: window x 50 is NDC
         * -0.5, y 0 is -1; z just inside the far plane (eye z = ndc z). */
        const scene_vertex *v = &sc.verts[sc.tris[m->first_tri].v[0]];
        CHECK_NEAR(v->pos[0], -0.5, 1e-6);
        CHECK_NEAR(v->pos[1], -1, 1e-6);
        CHECK(v->pos[2] > 0.99999 && v->pos[2] < 1);
        CHECK(v->color[2] == 1 && v->color[0] == 0);
        const scene_vertex *c = &sc.verts[sc.tris[m->first_tri + 2].v[2]];
        CHECK_NEAR(c->pos[0], 1, 1e-6); /* x 150 .. 250 cut at 200 */
        CHECK_NEAR(c->pos[1], 1, 1e-6);
    }
    /* The writer clips the scissored run to x > 0.5, y > 0 (the box from
     * window 150, 50 in the identity camera's 200 x 100 image). */
    write_sdl();
    const char *clip = strstr(sdl, "clipped_by{plane{<-1,0,0>,-0.5}plane{<1,0,0>,1.5}"
                                   "plane{<0,-1,0>,0}plane{<0,1,0>,2}}");
    CHECK(clip != NULL);
    if (!clip)
        fprintf(stderr, "%s\n", sdl);
    CHECK(clip && !strstr(clip + 1, "clipped_by{plane{<-1"));
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    test_select_pass();
    test_names();
    test_rejected();
    test_scissor_clear();
    scene_finish(&sc);
    return CHECK_RESULT("test_select");
}
