/* shapes_quadric_lists.c: the classic "quadric" teaching program (OSMesa).
 * One quadric object; four shapes compiled into display lists at start-up,
 * each with the quadric's draw style and normals of its compile time: a
 * smooth sphere, a flat-normal cylinder, a GLU_LINE disk and a
 * GLU_SILHOUETTE partial disk (GLU_NONE normals for both). glOrtho,
 * lighting on for the first two, off for the disks; flat shading for the
 * cylinder. Unlike the original, no specular (GL lights per vertex) and
 * the cylinder seen from the side (its inside is lit one-sided in GL).
 * GLU draws a compiled shape with the state of compile time,
 * never of the call (issue 14, "GLU quadric styles"). */
#include "harness.h"

#include <raygl/gl.h>

static GLuint compile(void)
{
    GLUquadric *q = gluNewQuadric();
    GLuint base = glGenLists(4);
    gluQuadricDrawStyle(q, GLU_FILL);
    gluQuadricNormals(q, GLU_SMOOTH);
    glNewList(base, GL_COMPILE);
    gluSphere(q, 0.75, 15, 10);
    glEndList();
    gluQuadricDrawStyle(q, GLU_FILL);
    gluQuadricNormals(q, GLU_FLAT);
    glNewList(base + 1, GL_COMPILE);
    gluCylinder(q, 0.5, 0.3, 1.0, 15, 5);
    glEndList();
    gluQuadricDrawStyle(q, GLU_LINE);
    gluQuadricNormals(q, GLU_NONE);
    glNewList(base + 2, GL_COMPILE);
    gluDisk(q, 0.25, 1.0, 20, 4);
    glEndList();
    /* A state call while a list is compiled is done at once, as GLU does. */
    glNewList(base + 3, GL_COMPILE);
    gluQuadricDrawStyle(q, GLU_SILHOUETTE);
    gluPartialDisk(q, 0.0, 1.0, 20, 4, 0.0, 225.0);
    glEndList();
    /* The quadric's state now is the last one set: nothing above uses it. */
    gluQuadricDrawStyle(q, GLU_POINT);
    return base;
}

static int draw(int w, int h)
{
    static const GLfloat amb[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    static const GLfloat spec[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    static const GLfloat pos[4] = {1.0f, 1.0f, 1.0f, 0.0f};
    static const GLfloat model_amb[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    GLuint base = compile();
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    double a = (double)w / (double)h;
    glOrtho(-2.5 * a, 2.5 * a, -2.5, 2.5, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMaterialfv(GL_FRONT, GL_AMBIENT, amb);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 50.0f);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, model_amb);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);

    glPushMatrix();
    /* A quarter pixel off the pixel grid: the disks' straight lines would
     * otherwise lie on pixel edges, where either side is right. */
    glTranslatef(0.0035f, 0.0035f, 0.0f);
    glEnable(GL_LIGHTING);
    glShadeModel(GL_SMOOTH);
    glTranslatef(-1.0f, -1.0f, 0.0f);
    glCallList(base);
    glShadeModel(GL_FLAT);
    glTranslatef(0.0f, 2.0f, 0.0f);
    glPushMatrix();
    glRotatef(270.0f, 1.0f, 0.0f, 0.0f);
    glCallList(base + 1);
    glPopMatrix();
    glDisable(GL_LIGHTING);
    glColor3f(0.0f, 1.0f, 1.0f);
    glTranslatef(2.0f, -2.0f, 0.0f);
    glCallList(base + 2);
    glColor3f(1.0f, 1.0f, 0.0f);
    glTranslatef(0.0f, 2.0f, 0.0f);
    glCallList(base + 3);
    glPopMatrix();
    return 0;
}

RGL_TEST_MAIN(draw)
