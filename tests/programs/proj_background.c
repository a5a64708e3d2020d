/* proj_background.c: a full-window background in another projection
 * (issue 14): a gradient quad drawn in glOrtho with the depth test off,
 * then a lit sphere and a cone with gluPerspective. Animated: the cone
 * turns over four frames; in the last the background is drawn with the
 * depth test on and the depth buffer cleared after it.
 */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* The background: unit square in glOrtho, no depth test, no lighting
     * (frame 3: drawn with the depth test, then the depth buffer cleared,
     * as some programs do). */
    if (frame == 3)
        glEnable(GL_DEPTH_TEST);
    else
        glDisable(GL_DEPTH_TEST);
    glDisable(GL_LIGHTING);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 1, 0, 1, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);
    glColor3f(0.1f, 0.1f, 0.4f);
    glVertex2f(0, 0);
    glVertex2f(1, 0);
    glColor3f(0.6f, 0.7f, 0.9f);
    glVertex2f(1, 1);
    glVertex2f(0, 1);
    glEnd();

    if (frame == 3)
        glClear(GL_DEPTH_BUFFER_BIT);

    /* The scene. */
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, -6);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat pos[4] = {2, 3, 4, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    const GLfloat red[4] = {0.8f, 0.2f, 0.1f, 1}, grey[4] = {0.5f, 0.5f, 0.5f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, red);
    glMaterialfv(GL_FRONT, GL_SPECULAR, grey);
    glMaterialf(GL_FRONT, GL_SHININESS, 30);
    GLUquadric *q = gluNewQuadric();
    glPushMatrix();
    glTranslatef(-1.1f, 0, 0);
    gluSphere(q, 0.9, 48, 24);
    glPopMatrix();
    const GLfloat green[4] = {0.2f, 0.7f, 0.3f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, green);
    glPushMatrix();
    glTranslatef(1.2f, 0, 0);
    glRotatef(30.0f + 25.0f * (float)frame, 1, 0.5f, 0);
    gluCylinder(q, 0.6, 0.3, 1.2, 40, 8);
    glPopMatrix();
    gluDeleteQuadric(q);
}

RGL_REAL_MAIN(draw, 4)
