/* fogsec_shapes.h: fog on GLU and GLUT shapes (issue 14), with the fog of
 * the including program (FOG_SETUP). GLUT window: run under Xvfb.
 *
 * Four columns at eye depths 5, 9, 14 and 20 under gluPerspective, three
 * rows: freeglut's teapot and a gluSphere (both become POV-Ray solids),
 * and freeglut's icosahedron (a mesh) compiled into a display list called
 * once per column (unfogged, the calls would share one prototype in the
 * SDL). Lit,
 * one directional light, local viewer. GL fogs each by its eye distance;
 * the cleared background stays unfogged. Included by fogsec_*.c.
 */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static const float fogsec_depth[4] = {5.0f, 9.0f, 14.0f, 20.0f};

/* Places column k of a row at height y (in units of the column's depth,
 * so that every column looks the same size apart from perspective). */
static void fogsec_cell(int k, float y)
{
    float d = fogsec_depth[k];
    glLoadIdentity();
    glTranslatef((-0.42f + 0.28f * (float)k) * d, y * d, -d);
    glScalef(d / 5.0f, d / 5.0f, d / 5.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
}

static void fogsec_material(float r, float g, float b)
{
    GLfloat diffuse[4] = {r, g, b, 1.0f}, ambient[4] = {0.3f * r, 0.3f * g, 0.3f * b, 1.0f};
    GLfloat specular[4] = {0.3f, 0.3f, 0.3f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.05f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat dir[4] = {1.0f, 1.5f, 2.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    GLfloat fogc[4] = {0.6f, 0.6f, 0.62f, 1.0f};
    glFogfv(GL_FOG_COLOR, fogc);
    FOG_SETUP;
    glEnable(GL_FOG);

    GLUquadric *q = gluNewQuadric();
    if (!q)
        return 1;
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glPushMatrix();
    glScalef(0.5f, 0.5f, 0.5f);
    glutSolidIcosahedron();
    glPopMatrix();
    glEndList();
    for (int k = 0; k < 4; k++) {
        fogsec_cell(k, 0.16f);
        fogsec_material(0.85f, 0.55f, 0.25f);
        glutSolidTeapot(0.55);
        fogsec_cell(k, -0.02f);
        fogsec_material(0.2f, 0.35f, 0.85f);
        gluSphere(q, 0.5, 32, 24);
        fogsec_cell(k, -0.2f);
        fogsec_material(0.25f, 0.75f, 0.3f);
        glCallList(list);
    }
    gluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
