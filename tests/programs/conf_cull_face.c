/* conf_cull_face.c: every glCullFace with each glFrontFace, and windings
 * flipped by the matrices. Six panels (GL_BACK, GL_FRONT, GL_FRONT_AND_BACK
 * across; GL_CCW above, GL_CW below), each with a counter-clockwise
 * rectangle (warm) and a clockwise one (cool): GL keeps the front faces
 * under GL_BACK, the back faces under GL_FRONT and nothing under
 * GL_FRONT_AND_BACK (points and lines would stay; none here). A seventh
 * and eighth row-end pair: under GL_BACK, the counter-clockwise rectangle
 * drawn through glScalef(-1, 1, 1) and through a projection mirrored in y
 * (glOrtho with bottom > top) is seen clockwise, so culled, and the
 * clockwise one kept. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

/* Pixels x0..x1 - 1, y0..y1 - 1, counter-clockwise or clockwise. */
static void rect(int x0, int y0, int x1, int y1, int ccw)
{
    float a = (float)x0 + 0.25f, b = (float)x1 + 0.25f;
    float c = (float)y0 + 0.25f, d = (float)y1 + 0.25f;
    glBegin(GL_TRIANGLE_STRIP);
    if (ccw) {
        glVertex2f(a, c);
        glVertex2f(b, c);
        glVertex2f(a, d);
        glVertex2f(b, d);
    } else {
        glVertex2f(a, c);
        glVertex2f(a, d);
        glVertex2f(b, c);
        glVertex2f(b, d);
    }
    glEnd();
}

static void pair(int x, int y)
{
    glColor3f(0.9f, 0.5f, 0.2f);
    rect(x, y, x + 30, y + 80, 1);
    glColor3f(0.2f, 0.6f, 0.9f);
    rect(x + 36, y, x + 66, y + 80, 0);
}

static int draw(int w, int h)
{
    static const GLenum modes[3] = {GL_BACK, GL_FRONT, GL_FRONT_AND_BACK};
    conf_pixels(w, h, 0.1f, 0.1f, 0.1f);
    glEnable(GL_CULL_FACE);
    for (int row = 0; row < 2; row++) {
        glFrontFace(row == 0 ? GL_CCW : GL_CW);
        for (int i = 0; i < 3; i++) {
            glCullFace(modes[i]);
            pair(6 + 76 * i, row == 0 ? 140 : 30);
        }
    }
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    /* Mirrored by the modelview: x -> 2 * 270 - x keeps the pair in place. */
    glPushMatrix();
    glTranslatef(540.0f, 0.0f, 0.0f);
    glScalef(-1.0f, 1.0f, 1.0f);
    pair(236, 140);
    glPopMatrix();
    /* Mirrored by the projection: window y = h - y. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, (double)h, 0.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    pair(240, h - 110);
    glDisable(GL_CULL_FACE);
    return 0;
}

RGL_TEST_MAIN(draw)
