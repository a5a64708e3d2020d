/* lines_polymode.c: glPolygonMode(GL_LINE) as modelling tools and demos
 * use it for wireframes: an unlit terrain of triangle strips in
 * perspective, a lit quad mesh (a bent sheet), and a lit gluSphere, all
 * with 1-pixel edges and no offsets. GL draws each polygon's boundary
 * edges as lines from vertex to vertex (shared edges twice, once each
 * way), each by the diamond-exit rule. */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static float height(int i, int k) { return 0.3f * (float)(sin(i * 0.7) * cos(k * 0.5)); }

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);

    /* The terrain: 12 strips of 16 quads, unlit, smooth colours. */
    glPushMatrix();
    glTranslatef(-1.6f, -1.2f, -6);
    glRotatef(35, 1, 0, 0);
    for (int k = 0; k < 12; k++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (int i = 0; i <= 16; i++)
            for (int d = 0; d < 2; d++) {
                /* a vertex's colour is its place's: the strips' shared
                 * edges then look alike whichever GL_LESS keeps */
                glColor3f(0.2f + 0.05f * (float)(k + d), 0.9f - 0.03f * (float)i, 0.4f);
                glVertex3f(-1.6f + 0.2f * (float)i, height(i, k + d), -1.2f + 0.2f * (float)(k + d));
            }
        glEnd();
    }
    glPopMatrix();

    /* Lit: a bent sheet of quads and a sphere. */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    static const float pos[4] = {2, 3, 4, 0}, col[4] = {0.9f, 0.8f, 0.5f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, col);
    glPushMatrix();
    glTranslatef(1.4f, 0.6f, -5);
    glRotatef(-30, 0, 1, 0);
    glBegin(GL_QUADS);
    for (int k = 0; k < 6; k++)
        for (int i = 0; i < 8; i++)
            for (int c = 0; c < 4; c++) {
                int ii = i + (c == 1 || c == 2), kk = k + (c >= 2);
                double a = ii * 0.25;
                glNormal3f((float)-sin(a), 0, (float)cos(a));
                glVertex3f((float)(0.8 * sin(a)) - 0.4f, -0.6f + 0.2f * (float)kk, (float)(0.8 * cos(a)));
            }
    glEnd();
    glPopMatrix();
    glPushMatrix();
    glTranslatef(-1.2f, 0.9f, -5);
    GLUquadric *q = gluNewQuadric();
    gluSphere(q, 0.7, 14, 9);
    gluDeleteQuadric(q);
    glPopMatrix();
    return 0;
}

RGL_TEST_MAIN(draw)
