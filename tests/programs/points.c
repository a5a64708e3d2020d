/* points.c: points of several sizes under gluOrtho2D.
 *
 * Covers glPointSize 1..16. GL draws a non-antialiased point of size s as
 * an s x s square of pixels centred on the point; odd sizes sit on pixel
 * centres and even sizes on pixel corners, so the square is unambiguous.
 * Each point has its own colour; several points per glBegin.
 */
#include "harness.h"

#include "raygl.h"

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();

    rayglClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);

    static const int sizes[10] = {1, 2, 3, 4, 5, 6, 8, 10, 12, 16};
    for (int i = 0; i < 10; i++) {
        int s = sizes[i];
        GLfloat off = (s % 2) ? 0.5f : 0.0f;
        GLfloat x = 16.0f + 30.0f * (float)i + off;
        rayglPointSize((GLfloat)s);
        rayglBegin(GL_POINTS);
        for (int r = 0; r < 6; r++) {
            rayglColor3f(r % 3 == 0 ? 1.0f : 0.3f, r % 3 == 1 ? 1.0f : 0.4f,
                         r % 3 == 2 ? 1.0f : 0.2f + 0.1f * (float)r);
            rayglVertex2f(x, 22.0f + 38.0f * (float)r + off);
        }
        rayglEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
