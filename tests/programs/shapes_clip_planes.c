/* shapes_clip_planes.c: user clip planes on every kind of shape (OSMesa).
 * Two planes, set under different modelviews (GL keeps each in eye space
 * as of its glClipPlane call): one slanted through the scene's middle,
 * one cutting the tops off. Clipped: a gluSphere (a true sphere), a
 * smooth triangle-strip band, a gluCylinder seen from the side, lines
 * and 3-pixel points. Unlit. */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static void grid_lines(void)
{
    glBegin(GL_LINES);
    for (int i = 0; i <= 8; i++) {
        float x = -4.0f + (float)i;
        glColor3f(1.0f, 1.0f - 0.1f * (float)i, 0.2f);
        glVertex3f(x, -2.6f, -1.0f);
        glColor3f(0.2f, 1.0f, 0.1f * (float)i);
        glVertex3f(x + 0.5f, 2.6f, -1.0f);
    }
    glEnd();
}

static void dots(void)
{
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (int i = 0; i < 30; i++) {
        glColor3f(1.0f, 0.3f + 0.02f * (float)i, 1.0f);
        glVertex3f(-4.2f + 0.29f * (float)i, -1.9f + 0.13f * (float)i, 0.5f);
    }
    glEnd();
}

static void band(void)
{
    glBegin(GL_TRIANGLE_STRIP);
    for (int i = 0; i <= 12; i++) {
        float a = (float)i / 12.0f * 3.14159265f;
        glColor3f(0.2f + 0.06f * (float)i, 0.3f, 0.9f - 0.05f * (float)i);
        glVertex3f(-3.8f + 0.6f * (float)i, -2.2f + 0.3f * sinf(a), 0.0f);
        glVertex3f(-3.8f + 0.6f * (float)i, -1.4f + 0.3f * sinf(a), 0.0f);
    }
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glTranslatef(0.0f, 0.0f, -8.0f);

    /* Keeps x + 0.6 y + 2 >= 0 in this modelview's object space... */
    static const GLdouble slant[4] = {1.0, 0.6, 0.0, 2.0};
    glPushMatrix();
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glClipPlane(GL_CLIP_PLANE0, slant);
    glPopMatrix();
    /* ...and y <= 1.2 in the eye-translated space. */
    static const GLdouble top[4] = {0.0, -1.0, 0.0, 1.2};
    glClipPlane(GL_CLIP_PLANE3, top);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE3);

    GLUquadric *q = gluNewQuadric();
    glColor3f(0.9f, 0.4f, 0.2f);
    glPushMatrix();
    glTranslatef(0.6f, 0.4f, 0.0f);
    gluSphere(q, 1.4, 24, 16);
    glPopMatrix();
    glColor3f(0.3f, 0.8f, 0.6f);
    glPushMatrix();
    glTranslatef(-2.6f, -0.2f, 0.0f);
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    gluCylinder(q, 0.6, 0.6, 2.2, 20, 1);
    glPopMatrix();
    gluDeleteQuadric(q);
    band();
    grid_lines();
    dots();
    glDisable(GL_CLIP_PLANE0);
    glDisable(GL_CLIP_PLANE3);
    return 0;
}

RGL_TEST_MAIN(draw)
