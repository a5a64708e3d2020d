/* nurbs_outline.c: GLU NURBS surfaces in GLU_OUTLINE_PATCH display mode
 * (OSMesa), unlit: the hill's patch boundary, then a trimmed surface whose
 * outline is its trim loops (an outer pwl square and a square hole),
 * mapped onto the surface.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 3.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    static GLfloat hill[4][4][3];
    for (int u = 0; u < 4; u++) {
        for (int v = 0; v < 4; v++) {
            hill[u][v][0] = 2.0f * ((GLfloat)u - 1.5f);
            hill[u][v][1] = 2.0f * ((GLfloat)v - 1.5f);
            hill[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0f : -3.0f;
        }
    }
    static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    GLUnurbs *nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nurb, GLU_U_STEP, 24.0f);
    gluNurbsProperty(nurb, GLU_V_STEP, 24.0f);
    gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_PATCH);

    glColor3f(1.0f, 0.8f, 0.3f);
    glPushMatrix();
    glTranslatef(-2.4f, 0.0f, -13.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glScalef(0.5f, 0.5f, 0.5f);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluEndSurface(nurb);
    glPopMatrix();

    static GLfloat outer[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    static GLfloat hole[5][2] = {{0.3f, 0.3f}, {0.3f, 0.7f}, {0.7f, 0.7f},
                                 {0.7f, 0.3f}, {0.3f, 0.3f}};
    glColor3f(0.4f, 0.8f, 1.0f);
    glPushMatrix();
    glTranslatef(2.4f, 0.0f, -13.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-20.0f, 0.0f, 0.0f, 1.0f);
    glScalef(0.5f, 0.5f, 0.5f);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &outer[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &hole[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluEndSurface(nurb);
    glPopMatrix();
    gluDeleteNurbsRenderer(nurb);
    return 0;
}

RGL_TEST_MAIN(draw)
