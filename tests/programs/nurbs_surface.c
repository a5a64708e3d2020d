/* nurbs_surface.c: GLU NURBS recorded as their own calls (OSMesa): the
 * classic hill, a bicubic NURBS surface of 4 x 4 control points with knots
 * {0,0,0,0,1,1,1,1}, lit, GL_AUTO_NORMAL giving the normals; beside it a
 * rational biquadratic surface (GL_MAP2_VERTEX_4, weights 1 to 1.4) of two
 * knot spans each way with a GL_MAP2_COLOR_4 piece under colour material,
 * compiled into a display list and drawn by glCallList.
 * GLU samples with GLU_DOMAIN_DISTANCE (24 steps a unit), so GL's mesh is
 * as fine as the translator's.
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
    glEnable(GL_DEPTH_TEST);

    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {3.0f, 4.0f, 8.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    GLfloat diff[4] = {0.7f, 0.7f, 0.7f, 1.0f}, spec[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diff);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);

    GLUnurbs *nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nurb, GLU_U_STEP, 24.0f);
    gluNurbsProperty(nurb, GLU_V_STEP, 24.0f);
    gluNurbsProperty(nurb, GLU_DISPLAY_MODE, GLU_FILL);

    /* The hill: the four middle points up, the rest down. */
    static GLfloat hill[4][4][3];
    for (int u = 0; u < 4; u++) {
        for (int v = 0; v < 4; v++) {
            hill[u][v][0] = 2.0f * ((GLfloat)u - 1.5f);
            hill[u][v][1] = 2.0f * ((GLfloat)v - 1.5f);
            hill[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 3.0f : -3.0f;
        }
    }
    static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    glPushMatrix();
    glTranslatef(-2.4f, 0.0f, -12.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glScalef(0.5f, 0.5f, 0.5f);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    gluEndSurface(nurb);
    glPopMatrix();

    /* A rational biquadratic of 3 + 1 points each way (two spans). */
    static GLfloat rk[7] = {0, 0, 0, 0.5f, 1, 1, 1};
    static GLfloat rp[4][4][4], col[4][4][4];
    for (int u = 0; u < 4; u++) {
        for (int v = 0; v < 4; v++) {
            GLfloat wgt = (u == 1 || u == 2) && (v == 1 || v == 2) ? 1.4f : 1.0f;
            GLfloat x = (GLfloat)u - 1.5f, y = (GLfloat)v - 1.5f;
            GLfloat z = (u == 0 || u == 3 || v == 0 || v == 3) ? 0.0f : 1.2f;
            rp[u][v][0] = x * wgt;
            rp[u][v][1] = y * wgt;
            rp[u][v][2] = z * wgt;
            rp[u][v][3] = wgt;
            col[u][v][0] = 0.2f + 0.25f * (GLfloat)u;
            col[u][v][1] = 0.3f;
            col[u][v][2] = 0.9f - 0.25f * (GLfloat)v;
            col[u][v][3] = 1.0f;
        }
    }
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    gluBeginSurface(nurb);
    gluNurbsSurface(nurb, 7, rk, 7, rk, 4 * 4, 4, &rp[0][0][0], 3, 3, GL_MAP2_VERTEX_4);
    gluNurbsSurface(nurb, 7, rk, 7, rk, 4 * 4, 4, &col[0][0][0], 3, 3, GL_MAP2_COLOR_4);
    gluEndSurface(nurb);
    glEndList();
    glPushMatrix();
    glTranslatef(2.0f, 0.0f, -10.0f);
    glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-25.0f, 0.0f, 0.0f, 1.0f);
    glCallList(list);
    glPopMatrix();
    gluDeleteNurbsRenderer(nurb);
    return 0;
}

RGL_TEST_MAIN(draw)
