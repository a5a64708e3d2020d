/* scenes.c: the small traces the golden, CLI and fuzz-seed tests share.
 *
 * Each builder appends one frame's commands to a sequence, written the way
 * libraygl records them (snapshot-free frames: the program's own calls,
 * with @Matrix before draws where the paper's example needs it).
 */
#include "scenes.h"

#include <GL/gl.h>
#include <math.h>

static void ortho2d_setup(seq *s, int w, int h)
{
    CMD(s, Viewport, 0, 0, w, h);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Ortho2D, 0, w, 0, h);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
}

/* The paper's example: three faces of a box, placed by glTranslatef and
 * glRotatef that the recorder never saw; @Matrix carries GL's result. */
void scene_paper_box(seq *s)
{
    CMD(s, Viewport, 0, 0, 320, 240);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Ortho, 45 - 25 * 4.0 / 3, 45 + 25 * 4.0 / 3, 20, 70, -100, 100);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD(s, ClearColor, 0, 0, 0, 1);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    CMD(s, Enable, GL_DEPTH_TEST);
    CMD(s, Matrix, GL_MODELVIEW, 0.853553f, -0.146447f, 0.5f, 0, -0.146447f, 0.853553f, 0.5f, 0,
        -0.5f, -0.5f, 0.707107f, 0, 45, 45, 45, 1);
    CMD(s, Begin, GL_QUADS);
    CMD(s, Color3f, 0.9, 0.2, 0.2);
    CMD(s, Vertex3f, 10, -10, -10);
    CMD(s, Vertex3f, 10, 10, -10);
    CMD(s, Vertex3f, 10, 10, 10);
    CMD(s, Vertex3f, 10, -10, 10);
    CMD(s, Color3f, 0.2, 0.8, 0.3);
    CMD(s, Vertex3f, -10, 10, -10);
    CMD(s, Vertex3f, -10, 10, 10);
    CMD(s, Vertex3f, 10, 10, 10);
    CMD(s, Vertex3f, 10, 10, -10);
    CMD(s, Color3f, 0.2, 0.4, 0.9);
    CMD(s, Vertex3f, -10, -10, 10);
    CMD(s, Vertex3f, 10, -10, 10);
    CMD(s, Vertex3f, 10, 10, 10);
    CMD(s, Vertex3f, -10, 10, 10);
    CMD0(s, End);
}

/* Perspective: a smooth triangle, a flat fan, a strip behind them. */
void scene_smooth(seq *s)
{
    CMD(s, Viewport, 0, 0, 400, 300);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Perspective, 50, 4.0 / 3, 1, 50);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
    CMD(s, LookAt, 0, 1, 6, 0, 0, 0, 0, 1, 0);
    CMD(s, ClearColor, 0.3, 0.3, 0.3, 1);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(s, Enable, GL_DEPTH_TEST);
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Color3f, 1, 0, 0);
    CMD(s, Vertex3f, -1, 0, 0);
    CMD(s, Color3f, 0, 1, 0);
    CMD(s, Vertex3f, 1, 0, 0);
    CMD(s, Color3f, 0, 0, 1);
    CMD(s, Vertex3f, 0, 1.5, 0);
    CMD0(s, End);
    CMD(s, ShadeModel, GL_FLAT);
    CMD0(s, PushMatrix);
    CMD(s, Translatef, 1.5, -0.5, -1);
    CMD(s, Begin, GL_TRIANGLE_FAN);
    CMD(s, Color3ub, 255, 255, 0);
    CMD(s, Vertex2f, 0, 0);
    CMD(s, Vertex2f, 1, 0);
    CMD(s, Color3ub, 0, 255, 255);
    CMD(s, Vertex2f, 1, 1);
    CMD(s, Color3ub, 255, 0, 255);
    CMD(s, Vertex2f, 0, 1);
    CMD0(s, End);
    CMD0(s, PopMatrix);
    CMD(s, ShadeModel, GL_SMOOTH);
    CMD(s, Translatef, 0, 0, -4);
    CMD(s, Begin, GL_QUAD_STRIP);
    for (int i = 0; i <= 4; i++) {
        CMD(s, Color3f, i / 4.0, 0.5, 1 - i / 4.0);
        CMD(s, Vertex3f, -3 + 1.5 * i, -1, 0);
        CMD(s, Vertex3f, -3 + 1.5 * i, 2, 0);
    }
    CMD0(s, End);
}

/* Lines and points under gluOrtho2D: widths, smooth and flat colours,
 * square and round points. */
void scene_lines_points(seq *s)
{
    ortho2d_setup(s, 320, 240);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(s, LineWidth, 3);
    CMD(s, Begin, GL_LINES);
    CMD(s, Color3f, 1, 0, 0);
    CMD(s, Vertex2f, 20, 20);
    CMD(s, Color3f, 0, 0, 1);
    CMD(s, Vertex2f, 150, 40);
    CMD0(s, End);
    CMD(s, ShadeModel, GL_FLAT);
    CMD(s, LineWidth, 2);
    CMD(s, Begin, GL_LINE_LOOP);
    CMD(s, Color3f, 1, 1, 0);
    CMD(s, Vertex2f, 200, 20);
    CMD(s, Color3f, 0, 1, 1);
    CMD(s, Vertex2f, 300, 30);
    CMD(s, Vertex2f, 250, 120);
    CMD0(s, End);
    CMD(s, PointSize, 5);
    CMD(s, Begin, GL_POINTS);
    CMD(s, Color3f, 1, 1, 1);
    CMD(s, Vertex2f, 40.5, 200.5);
    CMD0(s, End);
    CMD(s, Enable, GL_POINT_SMOOTH);
    CMD(s, Begin, GL_POINTS);
    CMD(s, Vertex2f, 80.5, 200.5);
    CMD0(s, End);
}

/* Culling and polygon mode with edge flags; a glRect. */
void scene_faces(seq *s)
{
    ortho2d_setup(s, 200, 100);
    CMD(s, ClearColor, 0, 0, 0.2, 1);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT);
    CMD(s, Enable, GL_CULL_FACE);
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Color3f, 0, 1, 0);
    CMD(s, Vertex2f, 10, 10);
    CMD(s, Vertex2f, 50, 10);
    CMD(s, Vertex2f, 30, 50); /* counter-clockwise: drawn */
    CMD(s, Color3f, 1, 0, 0);
    CMD(s, Vertex2f, 60, 10);
    CMD(s, Vertex2f, 80, 50);
    CMD(s, Vertex2f, 100, 10); /* clockwise: culled */
    CMD0(s, End);
    CMD(s, Disable, GL_CULL_FACE);
    CMD(s, PolygonMode, GL_FRONT_AND_BACK, GL_LINE);
    CMD(s, Begin, GL_POLYGON);
    CMD(s, Color3f, 1, 1, 1);
    CMD(s, Vertex2f, 110, 10);
    CMD(s, EdgeFlag, 0);
    CMD(s, Vertex2f, 150, 10);
    CMD(s, EdgeFlag, 1);
    CMD(s, Vertex2f, 150, 50);
    CMD(s, Vertex2f, 110, 50);
    CMD0(s, End);
    CMD(s, PolygonMode, GL_FRONT_AND_BACK, GL_FILL);
    CMD(s, Color3f, 0.5, 0.25, 1);
    CMD(s, Rectf, 160, 60, 190, 90);
}

/* rayglFrameBegin with a hostile name: the paper's camera and light. */
void scene_framebegin(seq *s, const char *name)
{
    static const double cam[9] = {30, 40, 50, 0, 0, 0, 100, 100, 100};
    seq_framebegin(s, name, cam);
    CMD(s, Viewport, 0, 0, 320, 240);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Perspective, 45, 4.0 / 3, 1, 500);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
    CMD(s, Begin, GL_QUADS);
    CMD(s, Color3f, 0.2, 0.4, 0.9);
    CMD(s, Vertex3f, -10, -10, 10);
    CMD(s, Vertex3f, 10, -10, 10);
    CMD(s, Vertex3f, 10, 10, 10);
    CMD(s, Vertex3f, -10, 10, 10);
    CMD0(s, End);
    CMD0(s, FrameEnd);
}

/* Awkward input: NaN and infinite values, w = 0, a projective and a
 * singular modelview, degenerate triangles, a HUD drawn with another
 * projection, an unterminated glBegin. Nothing of it may reach the SDL as
 * nan, inf or a broken object. */
void scene_awkward(seq *s)
{
    CMD(s, Viewport, 0, 0, 160, 120);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Frustum, -1, 1, -0.75, 0.75, 1, 20);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
    CMD(s, Translatef, 0, 0, -5);
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, NAN, 0, 0);
    CMD(s, Vertex3f, 1, 0, 0);
    CMD(s, Vertex3f, 0, 1, 0);
    CMD(s, Vertex4f, 1, 1, 0, 0); /* w = 0 */
    CMD(s, Vertex3f, 1, 0, 0);
    CMD(s, Vertex3f, 0, 1, 0);
    CMD(s, Vertex3f, 0, 0, 0); /* degenerate: a line */
    CMD(s, Vertex3f, 1, 1, 0);
    CMD(s, Vertex3f, 2, 2, 0);
    CMD(s, Color3f, INFINITY, 0.5, -1);
    CMD(s, Vertex3f, -1, -1, 0); /* a proper one */
    CMD(s, Vertex3f, 0, -1, 0);
    CMD(s, Vertex3f, -1, 0, 0);
    CMD0(s, End);
    CMD0(s, PushMatrix);
    CMD(s, MultMatrixf, 1, 0, 0, 0.1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1); /* projective */
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, 0, 0, 0);
    CMD(s, Vertex3f, 1, 0, 0);
    CMD(s, Vertex3f, 0, 1, 0);
    CMD0(s, End);
    CMD0(s, PopMatrix);
    CMD0(s, PushMatrix);
    CMD(s, Scalef, 1, 0, 1); /* singular */
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, Vertex3f, 0, 0, 0);
    CMD(s, Vertex3f, 1, 1, 0);
    CMD(s, Vertex3f, 0, 1, 1);
    CMD0(s, End);
    CMD0(s, PopMatrix);
    /* A HUD quad in window coordinates. */
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Ortho2D, 0, 160, 0, 120);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
    CMD(s, Color3f, 1, 1, 1);
    CMD(s, Rectf, 5, 5, 25, 15);
    CMD(s, Begin, GL_LINES);
    CMD(s, Vertex2f, 1e30, 0);
    CMD(s, Vertex2f, 5, 5);
    CMD(s, Begin, GL_POINTS);
}
