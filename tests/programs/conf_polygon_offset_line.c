/* conf_polygon_offset_line.c: glPolygonOffset with GL_POLYGON_OFFSET_LINE.
 * A cube drawn filled, then its outline drawn with glPolygonMode GL_LINE
 * and the offset (-1, -1) pulling the outline's faces toward the eye: the
 * visible edges show whole, the hidden ones stay hidden. Beside it the
 * same with GL_POLYGON_OFFSET_FILL on the fill instead (1, 1), the way a
 * hidden-line program does it. 1-pixel lines, unlit. */
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

static void place(float x)
{
    glLoadIdentity();
    glTranslatef(x, 0.0013f, -7.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(33.0f, 0.0f, 1.0f, 0.0f);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    place(-1.6f);
    glColor3f(0.3f, 0.3f, 0.6f);
    cube();
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(-1.0f, -1.0f);
    glColor3f(1.0f, 1.0f, 0.3f);
    cube();
    glDisable(GL_POLYGON_OFFSET_LINE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);

    place(1.6f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.0f, 1.0f);
    glColor3f(0.6f, 0.3f, 0.3f);
    cube();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(0.3f, 1.0f, 1.0f);
    cube();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    return 0;
}

RGL_TEST_MAIN(draw)
