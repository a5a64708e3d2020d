/* lights_rescale_normal.c: GL_RESCALE_NORMAL against GL_NORMALIZE and
 * scaled modelviews. Top row: a sphere under glScalef(0.5) with
 * GL_RESCALE_NORMAL; one under glScalef(1.6) with GL_NORMALIZE; one
 * mirrored by glScalef(-0.7, 0.7, 0.7) with GL_RESCALE_NORMAL (GL_CW
 * front faces, as a mirroring program sets). Bottom row: a uniformly
 * scaled torus with both enabled; a quad under glScalef(0.4) drawn in a
 * display list with GL_RESCALE_NORMAL enabled inside the list; a sphere
 * point-reflected by glScalef(-0.5, -0.5, -0.5) under GL_RESCALE_NORMAL
 * (GL_CW front faces). Local viewer.
 */
#include "lit_scene.h"

static void sphere_at(float x, float y, float s, float r)
{
    glPushMatrix();
    glTranslatef(x, y, -6.0f);
    glScalef(s, s, s);
    lit_sphere(0, 0, 0, r);
    glPopMatrix();
}

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.8f, 0.3f, 0.25f, 0.5f, 30.0f);

    glEnable(GL_RESCALE_NORMAL);
    sphere_at(-1.8f, 0.9f, 0.5f, 1.2f);
    glDisable(GL_RESCALE_NORMAL);

    glEnable(GL_NORMALIZE);
    sphere_at(0.0f, 0.9f, 1.6f, 0.4f);
    glDisable(GL_NORMALIZE);

    glEnable(GL_RESCALE_NORMAL);
    glFrontFace(GL_CW);
    glPushMatrix();
    glTranslatef(1.8f, 0.9f, -6.0f);
    glScalef(-0.7f, 0.7f, 0.7f);
    lit_sphere(0, 0, 0, 0.9f);
    glPopMatrix();
    glFrontFace(GL_CCW);
    glDisable(GL_RESCALE_NORMAL);

    lit_material(0.25f, 0.6f, 0.35f, 0.5f, 30.0f);
    glEnable(GL_RESCALE_NORMAL);
    glEnable(GL_NORMALIZE);
    glPushMatrix();
    glTranslatef(-1.8f, -0.9f, -6.0f);
    glScalef(0.6f, 0.6f, 0.6f);
    lit_torus(0, 0, 0, 1.0f, 0.4f, 0.3f, 0.8f, 0.55f);
    glPopMatrix();
    glDisable(GL_NORMALIZE);
    glDisable(GL_RESCALE_NORMAL);

    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glEnable(GL_RESCALE_NORMAL);
    glBegin(GL_QUADS);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-1.5f, -1.5f, 0.0f);
    glVertex3f(1.5f, -1.5f, 0.0f);
    glVertex3f(1.5f, 1.5f, 0.0f);
    glVertex3f(-1.5f, 1.5f, 0.0f);
    glEnd();
    glDisable(GL_RESCALE_NORMAL);
    glEndList();
    glPushMatrix();
    glTranslatef(0.0f, -0.9f, -6.0f);
    glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
    glScalef(0.4f, 0.4f, 0.4f);
    glCallList(list);
    glPopMatrix();

    /* A point-reflected sphere: glScalef(-0.5, -0.5, -0.5) (det < 0). */
    lit_material(0.3f, 0.35f, 0.8f, 0.5f, 30.0f);
    glEnable(GL_RESCALE_NORMAL);
    glFrontFace(GL_CW);
    glPushMatrix();
    glTranslatef(1.8f, -0.9f, -6.0f);
    glScalef(-0.5f, -0.5f, -0.5f);
    lit_sphere(0, 0, 0, 1.3f);
    glPopMatrix();
    glFrontFace(GL_CCW);
    glDisable(GL_RESCALE_NORMAL);
    return 0;
}

RGL_TEST_MAIN(draw)
