/* eval_surface.c: a lit bicubic Bezier patch (OSMesa): glMap2f of
 * GL_MAP2_VERTEX_3 with strides wider than a point, glMapGrid2f and
 * glEvalMesh2(GL_FILL) with GL_AUTO_NORMAL, a local viewer; beside it a
 * second patch drawn with GL_MAP2_VERTEX_4 (a rational patch) and
 * GL_MAP2_NORMAL off, inside a display list that glCallList runs after its
 * map changed (the list evaluates the maps current at the call).
 */
#include "harness.h"

#include <raygl/gl.h>

/* 4 x 4 points, each padded to 5 floats, rows 24 floats apart. */
static GLfloat patch[4][24];

static void make_patch(void)
{
    static const float h[4][4] = {
        {0.0f, 0.4f, 0.2f, -0.2f},
        {0.3f, 1.2f, 0.9f, 0.0f},
        {0.1f, 1.0f, 1.3f, 0.2f},
        {-0.3f, 0.2f, 0.4f, 0.0f},
    };
    for (int i = 0; i < 4; i++) {
        for (int j = 0; j < 4; j++) {
            GLfloat *p = &patch[i][5 * j];
            p[0] = -1.5f + (float)j;
            p[1] = -1.5f + (float)i;
            p[2] = h[i][j];
            p[3] = 99.0f; /* padding GL skips */
            p[4] = 99.0f;
        }
    }
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 2.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {2.0f, 3.0f, 6.0f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    GLfloat diff[4] = {0.85f, 0.55f, 0.2f, 1.0f}, spec[4] = {0.4f, 0.4f, 0.4f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diff);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 30.0f);

    make_patch();
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 5, 4, 0.0f, 1.0f, 24, 4, &patch[0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_AUTO_NORMAL);
    glMapGrid2f(24, 0.0f, 1.0f, 24, 0.0f, 1.0f);

    glPushMatrix();
    glTranslatef(-1.9f, 0.0f, -9.0f);
    glRotatef(-55.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(15.0f, 0.0f, 0.0f, 1.0f);
    glEvalMesh2(GL_FILL, 0, 24, 0, 24);
    glPopMatrix();

    /* A list that draws whatever MAP2 vertex map is current at its call. */
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glEvalMesh2(GL_FILL, 0, 24, 0, 24);
    glEndList();

    /* A rational biquadratic patch (w varies), domain [2, 4] x [-1, 1]. */
    static const GLfloat q[3][3][4] = {
        {{-1.2f, -1.2f, 0.0f, 1.0f}, {0.0f, -1.6f, 0.8f, 1.2f}, {1.2f, -1.2f, 0.0f, 1.0f}},
        {{-1.5f, 0.0f, 0.6f, 1.4f}, {0.0f, 0.0f, 2.4f, 1.4f}, {1.5f, 0.0f, 0.6f, 1.4f}},
        {{-1.2f, 1.2f, 0.0f, 1.0f}, {0.0f, 1.6f, 0.8f, 1.2f}, {1.2f, 1.2f, 0.0f, 1.0f}},
    };
    GLfloat qs[3][3][4];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            for (int c = 0; c < 4; c++) /* homogeneous: (w x, w y, w z, w) */
                qs[i][j][c] = c < 3 ? q[i][j][c] * q[i][j][3] : q[i][j][3];
    glMap2f(GL_MAP2_VERTEX_4, 2.0f, 4.0f, 4, 3, -1.0f, 1.0f, 12, 3, &qs[0][0][0]);
    glDisable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_VERTEX_4);
    glMapGrid2f(24, 2.0f, 4.0f, 24, -1.0f, 1.0f);
    GLfloat diff2[4] = {0.3f, 0.6f, 0.9f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, diff2);
    /* No highlight: GL's, interpolated between vertices, is not POV-Ray's. */
    GLfloat nospec[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, nospec);
    glPushMatrix();
    glTranslatef(1.9f, 0.0f, -9.0f);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glCallList(list);
    glPopMatrix();
    return 0;
}

RGL_TEST_MAIN(draw)
