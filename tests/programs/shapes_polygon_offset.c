/* shapes_polygon_offset.c: hidden-line wireframes with glPolygonOffset
 * (OSMesa). A sphere and a cube are each drawn filled with
 * GL_POLYGON_OFFSET_FILL (factor 1, units 2), then drawn again as lines
 * of the same shape on top: GL pushes the fill back in depth, so the
 * front edges show and the back ones stay hidden (issue 14,
 * "glPolygonOffset"). Unlit. */
#include "harness.h"

#include <raygl/gl.h>

static void cube(void)
{
    static const float v[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 4; k++)
            glVertex3fv(v[f[i][k]]);
    glEnd();
}

static void shapes(GLUquadric *q)
{
    glPushMatrix();
    glTranslatef(-1.4f, 0.0f, 0.0f);
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    gluSphere(q, 1.1, 14, 9);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.5f, 0.0f, 0.0f);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(35.0f, 0.0f, 1.0f, 0.0f);
    glScalef(0.8f, 0.8f, 0.8f);
    cube();
    glPopMatrix();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -8.0f);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    GLUquadric *q = gluNewQuadric();

    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 2.0f);
    glColor3f(0.2f, 0.3f, 0.8f);
    shapes(q);
    glDisable(GL_POLYGON_OFFSET_FILL);

    glColor3f(1.0f, 0.9f, 0.2f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    gluQuadricDrawStyle(q, GLU_LINE);
    shapes(q);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
