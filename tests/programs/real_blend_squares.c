/* real_blend_squares.c: translucent squares drifting over each other
 * (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, no depth test), three frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.05f, 0.05f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.21f, 0.43f, 0);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    const float c[5][4] = {{1, 0.2f, 0.2f, 0.5f}, {0.2f, 1, 0.2f, 0.5f}, {0.2f, 0.4f, 1, 0.6f},
                           {1, 1, 0.2f, 0.4f},    {1, 0.3f, 1, 0.5f}};
    for (int i = 0; i < 5; i++) {
        float x = 30.0f + 50.0f * (float)i + 9.0f * (float)(frame * (i % 3));
        float y = 40.0f + 25.0f * (float)((i * 3) % 5) + 6.0f * (float)frame;
        glColor4fv(c[i]);
        glRectf(x, y, x + 90, y + 90);
    }
    glDisable(GL_BLEND);
}

RGL_REAL_MAIN(draw, 3)
