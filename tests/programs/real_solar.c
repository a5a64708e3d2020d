/* real_solar.c: the teaching program's planet system: a lit sun, a planet
 * on its orbit and a moon, placed with glPushMatrix/glRotate/glTranslate,
 * a point light at the sun (local viewer). Three frames of the year. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.02f, 0.02f, 0.05f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 1, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0, 3, 8, 0, 0, 0, 0, 1, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat at_sun[4] = {0, 0, 0, 1}, amb[4] = {0.15f, 0.15f, 0.15f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, at_sun);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    GLUquadric *q = gluNewQuadric();
    /* The sun glows: emission, no light reaches its outside. */
    const GLfloat sun[4] = {1, 0.8f, 0.2f, 1}, none[4] = {0, 0, 0, 1};
    glMaterialfv(GL_FRONT, GL_EMISSION, sun);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, none);
    gluSphere(q, 1.0, 40, 20);
    glMaterialfv(GL_FRONT, GL_EMISSION, none);
    const GLfloat blue[4] = {0.2f, 0.4f, 1, 1}, grey[4] = {0.7f, 0.7f, 0.7f, 1};
    glPushMatrix();
    glRotatef(40.0f * (float)frame + 10, 0, 1, 0);
    glTranslatef(3.2f, 0, 0);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, blue);
    gluSphere(q, 0.45, 32, 16);
    glRotatef(90.0f * (float)frame + 30, 0, 1, 0);
    glTranslatef(0.9f, 0, 0);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    gluSphere(q, 0.15, 20, 10);
    glPopMatrix();
    gluDeleteQuadric(q);
}

RGL_REAL_MAIN(draw, 3)
