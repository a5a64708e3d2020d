/* vlit_glu_spheres.c: lit GLU quadrics translated with --vertex-lighting
 * (issue 27). Three coarse gluSpheres and a gluCylinder under a point
 * light and a local viewer with a highlight: GL lights their vertices and
 * interpolates, so the facets show. Under --vertex-lighting the
 * translation draws GL's facets with GL's lit colours (before, the
 * shapes became exact solids drawn unlit: flat discs of the material's
 * colour).
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    static const GLfloat pos[4] = {-2.0f, 3.0f, 4.0f, 1.0f};
    static const GLfloat diff[3][4] = {
        {0.9f, 0.3f, 0.2f, 1.0f}, {0.2f, 0.8f, 0.3f, 1.0f}, {0.3f, 0.4f, 0.9f, 1.0f}};
    static const GLfloat spec[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    static const GLfloat amb[4] = {0.2f, 0.2f, 0.2f, 1.0f};
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 1.0, 7.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 20.0f);
    GLUquadric *q = gluNewQuadric();
    for (int i = 0; i < 3; i++) {
        glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diff[i]);
        glPushMatrix();
        glTranslatef(-2.2f + 2.2f * (float)i, 0.6f, 0.0f);
        gluSphere(q, 0.9, 8 + 4 * i, 6 + 2 * i);
        glPopMatrix();
    }
    glPushMatrix();
    glTranslatef(0.0f, -1.2f, 0.0f);
    glRotatef(90.0f, 0.0f, 1.0f, 0.0f);
    glTranslatef(0.0f, 0.0f, -2.0f);
    gluCylinder(q, 0.4, 0.4, 4.0, 10, 3);
    glPopMatrix();
    gluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
