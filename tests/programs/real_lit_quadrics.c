/* real_lit_quadrics.c: lit GLU quadrics on a lit floor with a light that
 * moves (local viewer), the red book's material demo style. Three
 * frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.1f, 0.1f, 0.12f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.01, 2.5, 7, 0, 0.3, 0, 0, 1, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat pos[4] = {-3.0f + 2.0f * (float)frame, 4, 3, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    const GLfloat spec[4] = {0.6f, 0.6f, 0.6f, 1};
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 40);
    const GLfloat floor_c[4] = {0.4f, 0.4f, 0.45f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, floor_c);
    glNormal3f(0, 1, 0);
    glBegin(GL_QUADS);
    for (int i = -4; i < 4; i++)
        for (int j = -4; j < 4; j++) {
            glVertex3f((float)i, -1, (float)j + 1);
            glVertex3f((float)i + 1, -1, (float)j + 1);
            glVertex3f((float)i + 1, -1, (float)j);
            glVertex3f((float)i, -1, (float)j);
        }
    glEnd();
    GLUquadric *q = gluNewQuadric();
    const GLfloat c1[4] = {0.9f, 0.3f, 0.2f, 1}, c2[4] = {0.2f, 0.5f, 0.9f, 1},
                  c3[4] = {0.9f, 0.8f, 0.2f, 1};
    glPushMatrix();
    glTranslatef(-1.8f, 0, 0);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, c1);
    gluSphere(q, 0.9, 48, 24);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(0.3f, -1, 0);
    glRotatef(-90, 1, 0, 0);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, c2);
    gluCylinder(q, 0.6, 0.6, 1.6, 40, 4);
    glTranslatef(0, 0, 1.6f);
    gluDisk(q, 0, 0.6, 40, 2);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(2.2f, -1, 0.5f);
    glRotatef(-90, 1, 0, 0);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, c3);
    gluCylinder(q, 0.8, 0, 1.8, 40, 4);
    glPopMatrix();
    gluDeleteQuadric(q);
}

RGL_REAL_MAIN(draw, 3)
