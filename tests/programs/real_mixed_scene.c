/* real_mixed_scene.c: the mix a small game draws each frame: a sky
 * gradient in glOrtho (depth test off), a lit perspective scene, then a
 * score bar in window pixels on top. Three frames, the objects turning. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(-1, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);
    glColor3f(0.9f, 0.6f, 0.3f);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glColor3f(0.2f, 0.3f, 0.6f);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();

    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, -6);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat pos[4] = {1, 2, 3, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    const GLfloat col[4] = {0.3f, 0.8f, 0.4f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, col);
    GLUquadric *q = gluNewQuadric();
    glRotatef(30.0f * (float)frame, 0, 1, 0);
    gluSphere(q, 1.1, 48, 24);
    const GLfloat col2[4] = {0.8f, 0.3f, 0.6f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, col2);
    glTranslatef(1.8f, 0, 0);
    gluSphere(q, 0.5, 32, 16);
    gluDeleteQuadric(q);

    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1, 1, 1);
    glRectf(10, (float)h - 20, 10 + 40.0f * (float)(frame + 1), (float)h - 10);
}

RGL_REAL_MAIN(draw, 3)
