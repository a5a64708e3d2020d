/* real_bitmap_label.c: a turning wire cube with a label drawn with
 * glRasterPos and glBitmap (a hand-made 8x8 glyph, as bitmap-font demos
 * do), two frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    static const GLubyte glyph[8] = {0x18, 0x3c, 0x66, 0x66, 0x7e, 0x66, 0x66, 0x00};
    static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int e[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                                 {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, -6);
    glRotatef(20, 1, 0, 0);
    glRotatef(25.0f + 30.0f * (float)frame, 0, 1, 0);
    glColor3f(0.3f, 1, 0.4f);
    glBegin(GL_LINES);
    for (int i = 0; i < 12; i++) {
        glVertex3fv(v[e[i][0]]);
        glVertex3fv(v[e[i][1]]);
    }
    glEnd();
    glColor3f(1, 1, 0);
    glRasterPos3f(1, 1, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int k = 0; k < 4; k++)
        glBitmap(8, 8, 0, 0, 9, 0, glyph);
}

RGL_REAL_MAIN(draw, 2)
