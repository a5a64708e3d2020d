/* nurbs_curve.c: GLU NURBS curves (OSMesa), unlit: a cubic
 * GL_MAP1_VERTEX_3 curve of 7 points over uniform knots (4 spans) coloured
 * by a GL_MAP1_COLOR_4 piece, 2 pixels wide; a circle as a rational
 * quadratic (GL_MAP1_VERTEX_4, 9 points, weights 1 and sqrt(2)/2), also 2
 * pixels wide.
 */
#include "harness.h"

#include <math.h>
#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-4.0, 4.0, -3.0, 3.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    GLUnurbs *nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nurb, GLU_U_STEP, 24.0f);

    static GLfloat pts[7][3] = {{-3.5f, -2.0f, 0}, {-2.5f, 2.0f, 0}, {-1.5f, -2.5f, 0},
                                {-0.5f, 2.5f, 0},  {0.5f, -1.0f, 0}, {1.0f, 2.0f, 0},
                                {-0.5f, 0.5f, 0}};
    static GLfloat cols[7][4] = {{1, 0.2f, 0.2f, 1}, {1, 0.6f, 0.2f, 1}, {1, 1, 0.2f, 1},
                                 {0.2f, 1, 0.2f, 1}, {0.2f, 1, 1, 1},    {0.3f, 0.4f, 1, 1},
                                 {1, 0.3f, 1, 1}};
    static GLfloat knots[11] = {0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4};
    glLineWidth(2.0f);
    gluBeginCurve(nurb);
    gluNurbsCurve(nurb, 11, knots, 3, &pts[0][0], 4, GL_MAP1_VERTEX_3);
    gluNurbsCurve(nurb, 11, knots, 4, &cols[0][0], 4, GL_MAP1_COLOR_4);
    gluEndCurve(nurb);

    /* The circle: centre (2, 0), radius 1.5. */
    const GLfloat r = 1.5f, cx = 2.0f, s = (GLfloat)(sqrt(2.0) / 2.0);
    static const GLfloat dir[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0},
                                      {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    GLfloat circ[9][4];
    for (int i = 0; i < 9; i++) {
        GLfloat wgt = (i & 1) ? s : 1.0f;
        circ[i][0] = (cx + r * dir[i][0]) * wgt;
        circ[i][1] = r * dir[i][1] * wgt;
        circ[i][2] = 0;
        circ[i][3] = wgt;
    }
    static GLfloat cknots[12] = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
    glColor3f(0.9f, 0.9f, 0.9f);
    gluBeginCurve(nurb);
    gluNurbsCurve(nurb, 12, cknots, 4, &circ[0][0], 3, GL_MAP1_VERTEX_4);
    gluEndCurve(nurb);
    gluDeleteNurbsRenderer(nurb);
    return 0;
}

RGL_TEST_MAIN(draw)
