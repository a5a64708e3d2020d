/* lights_two_side.c: back faces under GL_LIGHT_MODEL_TWO_SIDE with a
 * GL_BACK material. Right: quads whose front looks away from the viewer,
 * lit by GL_LIGHT0 on the viewer's side (top) and by GL_LIGHT1 behind the
 * scene (bottom): GL lights the back face with the back material and the
 * reversed normal. Middle: a curved quad strip under glFrontFace(GL_CW)
 * whose front (clockwise) side looks away, so the viewer sees its back.
 * Local viewer.
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

    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    away_quad(1.6f, 0.7f);
    glEnable(GL_LIGHT1);
    glDisable(GL_LIGHT0);
    away_quad(1.6f, -0.7f);
    glEnable(GL_LIGHT0);
    glDisable(GL_LIGHT1);

    glFrontFace(GL_CW);
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -6.0f);
    glRotatef(35.0f, 0.0f, 1.0f, 0.0f);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= 8; i++) {
        float a = -1.2f + 0.3f * (float)i;
        float nx = 0.3f * (float)(i - 4) / 4.0f, nl = sqrtf(nx * nx + 1);
        glNormal3f(-nx / nl, 0, -1 / nl); /* the front, wound CW, looks toward -z */
        glVertex3f(0.5f * a, 1.0f, -0.2f * a * a);
        glVertex3f(0.5f * a, -1.0f, -0.2f * a * a);
    }
    glEnd();
    glPopMatrix();
    glFrontFace(GL_CCW);
    return 0;
}

RGL_TEST_MAIN(draw)
