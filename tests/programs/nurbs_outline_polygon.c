/* nurbs_outline_polygon.c: GLU NURBS surfaces in GLU_OUTLINE_POLYGON
 * display mode (OSMesa), unlit, untrimmed: the hill and a biquadratic of
 * two knot spans each way. GLU outlines an untrimmed surface as the lines
 * of its sampling grid, which with GLU_DOMAIN_DISTANCE is the translator's
 * too; near trims GLU outlines triangles of its own (noted, not tested).
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
    gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_OUTLINE_POLYGON);

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

    /* A biquadratic of two spans each way, its middle raised. */
    static GLfloat rk[7] = {0, 0, 0, 0.5f, 1, 1, 1};
    static GLfloat q[4][4][3];
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            q[u][v][0] = 1.4f * ((GLfloat)u - 1.5f);
            q[u][v][1] = 1.4f * ((GLfloat)v - 1.5f);
            q[u][v][2] = (u == 1 || u == 2) && (v == 1 || v == 2) ? 1.5f : 0.0f;
        }
    glColor3f(0.4f, 0.8f, 1.0f);
    glPushMatrix();
    glTranslatef(2.4f, 0.0f, -13.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-20.0f, 0.0f, 0.0f, 1.0f);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 7, rk, 7, rk, 4 * 3, 3, &q[0][0][0], 3, 3, GL_MAP2_VERTEX_3);
    gluEndSurface(nurb);
    glPopMatrix();
    gluDeleteNurbsRenderer(nurb);
    return 0;
}

RGL_TEST_MAIN(draw)
