/* lights_one_side_back.c: back faces under one-sided lighting (GL's
 * default): GL lights a back face with the front material and the normal
 * as given, pointing away from the viewer, so GL_LIGHT0 on the viewer's
 * side leaves the top quad dark and GL_LIGHT1 behind the scene lights the
 * bottom one. POV-Ray turns every shading normal toward the viewer and
 * would do the opposite: the translator draws back faces with GL's own
 * per-vertex colours (translate/gl/interp_relit.c, docs/mapping.md "Faces
 * lit and fogged as GL does them").
 */
#include "lights_conform.h"

static void away_quad(float x, float y)
{
    glPushMatrix();
    glTranslatef(x, y, -6.0f);
    glRotatef(180.0f + 25.0f, 0.0f, 1.0f, 0.0f); /* its front looks away */
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glVertex3f(-0.6f, -0.5f, 0);
    glVertex3f(0.6f, -0.5f, 0);
    glVertex3f(0.6f, 0.5f, 0);
    glVertex3f(-0.6f, 0.5f, 0);
    glEnd();
    glPopMatrix();
}

static int draw(int w, int h)
{
    conform_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat back_pos[4] = {-0.5f, 0.2f, -1.0f, 0.0f}, dim[4] = {0.6f, 0.6f, 0.5f, 1};
    glLightfv(GL_LIGHT1, GL_POSITION, back_pos);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);
    GLfloat front[4] = {0.8f, 0.5f, 0.2f, 1}, back[4] = {0.2f, 0.5f, 0.8f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, front);
    glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, back);

    away_quad(-1.8f, 0.7f);
    glEnable(GL_LIGHT1);
    glDisable(GL_LIGHT0);
    away_quad(-1.8f, -0.7f);
    glEnable(GL_LIGHT0);
    glDisable(GL_LIGHT1);

    return 0;
}

RGL_TEST_MAIN(draw)
