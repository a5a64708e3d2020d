/* nurbs_trim.c: a trimmed GLU NURBS surface (OSMesa): a lit bicubic
 * surface of 4 x 4 points over [0,1]^2 with an outer trim loop given as a
 * piecewise-linear NURBS curve (GLU_MAP1_TRIM_2, order 2, counter-
 * clockwise) and a square hole as a clockwise gluPwlCurve; beside it the
 * same surface with an outer pwl loop inside the domain and a rational
 * (GLU_MAP1_TRIM_3) pwl hole.
 */
#include "harness.h"

#include <raygl/gl.h>

static GLfloat hill[4][4][3];
static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};

static void surface(GLUnurbs *nurb)
{
    gluNurbsSurface(nurb, 8, knots, 8, knots, 4 * 3, 3, &hill[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
}

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
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    GLfloat pos[4] = {3.0f, 4.0f, 8.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    GLfloat diff[4] = {0.8f, 0.6f, 0.3f, 1.0f}, spec[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diff);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glEnable(GL_AUTO_NORMAL);
    glEnable(GL_NORMALIZE);

    for (int u = 0; u < 4; u++) {
        for (int v = 0; v < 4; v++) {
            hill[u][v][0] = 2.0f * ((GLfloat)u - 1.5f);
            hill[u][v][1] = 2.0f * ((GLfloat)v - 1.5f);
            hill[u][v][2] = ((u == 1 || u == 2) && (v == 1 || v == 2)) ? 2.0f : -1.0f;
        }
    }
    GLUnurbs *nurb = gluNewNurbsRenderer();
    gluNurbsProperty(nurb, GLU_SAMPLING_METHOD, GLU_DOMAIN_DISTANCE);
    gluNurbsProperty(nurb, GLU_U_STEP, 24.0f);
    gluNurbsProperty(nurb, GLU_V_STEP, 24.0f);

    /* Outer loop: the domain's square, counter-clockwise, as an order-2
     * NURBS curve through its corners. */
    static GLfloat outer[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    static GLfloat oknots[7] = {0, 0, 1, 2, 3, 4, 4};
    /* The hole: [0.25, 0.75]^2, clockwise. */
    static GLfloat hole[5][2] = {{0.25f, 0.25f}, {0.25f, 0.75f}, {0.75f, 0.75f},
                                 {0.75f, 0.25f}, {0.25f, 0.25f}};
    glPushMatrix();
    glTranslatef(-2.3f, 0.0f, -12.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glScalef(0.55f, 0.55f, 0.55f);
    gluBeginSurface(nurb);
    surface(nurb);
    gluBeginTrim(nurb);
    gluNurbsCurve(nurb, 7, oknots, 2, &outer[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &hole[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluEndSurface(nurb);
    glPopMatrix();

    /* An outer loop short of the domain's edges; a rational hole
     * (u w, v w, w) with w = 2, off centre. */
    static GLfloat outer2[5][2] = {{0.1f, 0}, {0.9f, 0}, {0.9f, 1}, {0.1f, 1}, {0.1f, 0}};
    static GLfloat hole3[5][3] = {{0.4f, 0.6f, 2}, {0.4f, 1.3f, 2}, {1.2f, 1.3f, 2},
                                  {1.2f, 0.6f, 2}, {0.4f, 0.6f, 2}};
    glPushMatrix();
    glTranslatef(2.3f, 0.0f, -12.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-20.0f, 0.0f, 0.0f, 1.0f);
    glScalef(0.55f, 0.55f, 0.55f);
    gluBeginSurface(nurb);
    surface(nurb);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &outer2[0][0], 2, GLU_MAP1_TRIM_2);
    gluEndTrim(nurb);
    gluBeginTrim(nurb);
    gluPwlCurve(nurb, 5, &hole3[0][0], 3, GLU_MAP1_TRIM_3);
    gluEndTrim(nurb);
    gluEndSurface(nurb);
    glPopMatrix();
    gluDeleteNurbsRenderer(nurb);
    return 0;
}

RGL_TEST_MAIN(draw)
