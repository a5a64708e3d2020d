/* eval_mesh_lines.c: glEvalMesh2 as GL_LINE and GL_POINT, unlit (OSMesa).
 *
 * A biquadratic patch, seen in perspective: left its grid lines
 * (glEvalMesh2(GL_LINE) over part of a 6 x 4 grid: the line strips of the
 * rows, then of the columns), right its grid points (GL_POINT, 3 pixels),
 * with GL_MAP2_COLOR_4 shading the lines; a glEvalPoint2 row drawn as a
 * line strip under them.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    static const GLfloat pts[3][3][3] = {
        {{-1.0f, -1.0f, 0.0f}, {0.0f, -1.0f, 0.6f}, {1.0f, -1.0f, 0.0f}},
        {{-1.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 1.2f}, {1.0f, 0.0f, 0.5f}},
        {{-1.0f, 1.0f, 0.0f}, {0.0f, 1.0f, 0.6f}, {1.0f, 1.0f, 0.0f}},
    };
    static const GLfloat cols[2][2][4] = {
        {{1, 1, 0.2f, 1}, {0.2f, 1, 1, 1}},
        {{1, 0.3f, 1, 1}, {1, 1, 1, 1}},
    };
    glMap2f(GL_MAP2_VERTEX_3, 0, 1, 3, 3, 0, 1, 9, 3, &pts[0][0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glMap2f(GL_MAP2_COLOR_4, 0, 1, 4, 2, 0, 1, 8, 2, &cols[0][0][0]);
    glMapGrid2f(6, 0.0f, 1.0f, 4, 0.0f, 1.0f);

    glPushMatrix();
    glTranslatef(-1.3f, 0.2f, -5.0f);
    glRotatef(-40.0f, 1.0f, 0.0f, 0.0f);
    glEnable(GL_MAP2_COLOR_4);
    glLineWidth(2.0f);
    glEvalMesh2(GL_LINE, 0, 5, 1, 4);
    glDisable(GL_MAP2_COLOR_4);
    glColor3f(1.0f, 0.4f, 0.2f);
    glBegin(GL_LINE_STRIP);
    for (int i = 0; i <= 6; i++)
        glEvalPoint2(i, 0);
    glEnd();
    glPopMatrix();

    glPushMatrix();
    glTranslatef(1.3f, 0.2f, -5.0f);
    glRotatef(-40.0f, 1.0f, 0.0f, 0.0f);
    glPointSize(3.0f);
    glColor3f(0.4f, 1.0f, 0.4f);
    glEvalMesh2(GL_POINT, 0, 6, 0, 4);
    glPopMatrix();
    return 0;
}

RGL_TEST_MAIN(draw)
