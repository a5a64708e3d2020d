/* conf_rect.c: glRect in each of its forms (f, d, i, s and the vector
 * forms fv, dv, iv, sv), corners given in either order, under a rotated
 * and scaled modelview, and under GL_CULL_FACE: glRect is a polygon whose
 * winding follows its corners, so a rectangle given from (x2, y1) to
 * (x1, y2) is clockwise and GL_BACK culls it. Unlit; glOrtho in units of
 * 4 pixels shifted by a quarter pixel, so integer corners lie off the
 * pixel grid. */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-0.0625, (double)w / 4 - 0.0625, -0.0625, (double)h / 4 - 0.0625, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    glColor3f(0.9f, 0.3f, 0.2f);
    glRectf(2.0f, 45.0f, 12.0f, 56.0f);
    glColor3f(0.3f, 0.8f, 0.3f);
    glRectd(24.0, 56.0, 14.0, 45.0); /* both corners swapped: counter-clockwise */
    glColor3f(0.3f, 0.4f, 0.9f);
    glRecti(26, 45, 36, 56);
    glColor3f(0.9f, 0.8f, 0.2f);
    glRects(38, 45, 48, 56);
    const GLfloat f1[2] = {50, 45}, f2[2] = {60, 56};
    const GLdouble d1[2] = {62, 45}, d2[2] = {72, 56};
    const GLint i1[2] = {2, 30}, i2[2] = {12, 41};
    const GLshort s1[2] = {14, 30}, s2[2] = {24, 41};
    glColor3f(0.8f, 0.3f, 0.8f);
    glRectfv(f1, f2);
    glColor3f(0.3f, 0.8f, 0.8f);
    glRectdv(d1, d2);
    glColor3f(0.9f, 0.6f, 0.4f);
    glRectiv(i1, i2);
    glColor3f(0.6f, 0.9f, 0.4f);
    glRectsv(s1, s2);

    glPushMatrix();
    glTranslatef(45.0f, 30.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glScalef(1.5f, 0.6f, 1.0f);
    glColor3f(0.7f, 0.7f, 0.9f);
    glRectf(-6.0f, -6.0f, 6.0f, 6.0f);
    glPopMatrix();

    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glColor3f(1.0f, 1.0f, 1.0f);
    glRectf(2.0f, 4.0f, 12.0f, 20.0f);  /* kept */
    glRectf(24.0f, 4.0f, 14.0f, 20.0f); /* x swapped: clockwise, culled */
    glRectf(26.0f, 20.0f, 36.0f, 4.0f); /* y swapped: clockwise, culled */
    glRectf(48.0f, 20.0f, 38.0f, 4.0f); /* both: counter-clockwise, kept */
    glCullFace(GL_FRONT);
    glColor3f(0.9f, 0.4f, 0.1f);
    glRecti(60, 4, 50, 20); /* clockwise, kept under GL_FRONT */
    glRecti(62, 4, 72, 20); /* culled */
    glDisable(GL_CULL_FACE);
    return 0;
}

RGL_TEST_MAIN(draw)
