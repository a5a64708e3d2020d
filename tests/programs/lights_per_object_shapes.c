/* lights_per_object_shapes.c: light sets on what is not a plain mesh. A
 * GLU sphere (an exact POV-Ray sphere) under a warm GL_LIGHT0; a display
 * list holding a torus, called twice, once under GL_LIGHT0 alone and once
 * under a blue GL_LIGHT1 alone (two instances of one prototype, in two
 * light groups); a second GLU sphere under both lights. Local viewer, no
 * shadows (docs/mapping.md section 19).
 */
#include "lit_scene.h"

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat warm[4] = {0.95f, 0.7f, 0.4f, 1.0f}, dir0[4] = {-1.0f, 0.8f, 0.9f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir0);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, warm);
    GLfloat blue[4] = {0.3f, 0.5f, 1.0f, 1.0f}, pos1[4] = {2.0f, 2.0f, -2.0f, 1.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, blue);
    glLightfv(GL_LIGHT1, GL_SPECULAR, blue);
    lit_material(0.85f, 0.85f, 0.85f, 0.6f, 40.0f);

    GLUquadric *q = gluNewQuadric();
    glEnable(GL_LIGHT0);
    glPushMatrix();
    glTranslatef(-1.5f, 0.6f, -6.0f);
    gluSphere(q, 0.7, 48, 32);
    glPopMatrix();

    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    lit_torus(0, 0, 0, 0.5f, 0.2f, 0.3f, 0.8f, 0.55f);
    glEndList();
    glPushMatrix();
    glTranslatef(0.6f, 0.7f, -6.0f);
    glCallList(list);
    glPopMatrix();
    glDisable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glPushMatrix();
    glTranslatef(0.6f, -0.9f, -6.0f);
    glCallList(list);
    glPopMatrix();

    glEnable(GL_LIGHT0);
    glPushMatrix();
    glTranslatef(-1.5f, -1.0f, -6.0f);
    gluSphere(q, 0.55, 48, 32);
    glPopMatrix();
    gluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
