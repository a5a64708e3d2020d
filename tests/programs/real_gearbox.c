/* real_gearbox.c: three gears in the style of the classic gears demo: each
 * gear built once into a display list (frame 0) of flat-shaded lit quad
 * strips (faces, teeth, the outward and inward surfaces) under one
 * directional light, GL_CULL_FACE and GL_NORMALIZE off, called each frame
 * at the angle the frame number gives (not the clock), with the view
 * turned. Five frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static void gear(float inner, float outer, float width, int teeth, float depth)
{
    float r0 = inner, r1 = outer - depth / 2.0f, r2 = outer + depth / 2.0f;
    float da = 2.0f * (float)M_PI / (float)teeth / 4.0f;
    glShadeModel(GL_FLAT);
    glNormal3f(0, 0, 1);
    for (int side = 0; side < 2; side++) {
        float z = side ? -width * 0.5f : width * 0.5f;
        glNormal3f(0, 0, side ? -1.0f : 1.0f);
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= teeth; i++) {
            float a = (float)i * 2.0f * (float)M_PI / (float)teeth;
            glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
            glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
            if (i < teeth) {
                glVertex3f(r0 * cosf(a), r0 * sinf(a), z);
                glVertex3f(r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), z);
            }
        }
        glEnd();
        glBegin(GL_QUADS);
        for (int i = 0; i < teeth; i++) {
            float a = (float)i * 2.0f * (float)M_PI / (float)teeth;
            glVertex3f(r1 * cosf(a), r1 * sinf(a), z);
            glVertex3f(r2 * cosf(a + da), r2 * sinf(a + da), z);
            glVertex3f(r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da), z);
            glVertex3f(r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da), z);
        }
        glEnd();
    }
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i < teeth; i++) {
        float a = (float)i * 2.0f * (float)M_PI / (float)teeth;
        float p[4][2] = {{r1 * cosf(a), r1 * sinf(a)},
                         {r2 * cosf(a + da), r2 * sinf(a + da)},
                         {r2 * cosf(a + 2 * da), r2 * sinf(a + 2 * da)},
                         {r1 * cosf(a + 3 * da), r1 * sinf(a + 3 * da)}};
        for (int k = 0; k < 4; k++) {
            float nx = k == 1 || k == 2 ? cosf(a + (float)k * da) : p[(k + 1) % 4][1] - p[k][1];
            float ny = k == 1 || k == 2 ? sinf(a + (float)k * da) : -(p[(k + 1) % 4][0] - p[k][0]);
            glNormal3f(nx, ny, 0);
            glVertex3f(p[k][0], p[k][1], width * 0.5f);
            glVertex3f(p[k][0], p[k][1], -width * 0.5f);
        }
    }
    glVertex3f(r1, 0, width * 0.5f);
    glVertex3f(r1, 0, -width * 0.5f);
    glEnd();
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUAD_STRIP);
    for (int i = 0; i <= teeth; i++) {
        float a = (float)i * 2.0f * (float)M_PI / (float)teeth;
        glNormal3f(-cosf(a), -sinf(a), 0);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), -width * 0.5f);
        glVertex3f(r0 * cosf(a), r0 * sinf(a), width * 0.5f);
    }
    glEnd();
}

static void draw(int frame, int w, int h)
{
    static GLuint lists;
    static const GLfloat red[4] = {0.8f, 0.1f, 0.0f, 1}, green[4] = {0.0f, 0.8f, 0.2f, 1},
                         blue[4] = {0.2f, 0.2f, 1.0f, 1};
    if (frame == 0) {
        lists = glGenLists(3);
        const GLfloat *c[3] = {red, green, blue};
        const float g[3][5] = {{1.0f, 4.0f, 1.0f, 20, 0.7f}, {0.5f, 2.0f, 2.0f, 10, 0.7f},
                               {1.3f, 2.0f, 0.5f, 10, 0.7f}};
        for (int i = 0; i < 3; i++) {
            glNewList(lists + (GLuint)i, GL_COMPILE);
            glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, c[i]);
            gear(g[i][0], g[i][1], g[i][2], (int)g[i][3], g[i][4]);
            glEndList();
        }
    }
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    double a = (double)h / w;
    glFrustum(-1.0, 1.0, -a, a, 5.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, -40.0f);
    const GLfloat pos[4] = {5.0f, 5.0f, 10.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_CULL_FACE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_DEPTH_TEST);
    float angle = 7.0f * (float)frame;
    glRotatef(20.0f + 4.0f * (float)frame, 1, 0, 0);
    glRotatef(30.0f - 6.0f * (float)frame, 0, 1, 0);
    glPushMatrix();
    glTranslatef(-3.0f, -2.0f, 0.0f);
    glRotatef(angle, 0, 0, 1);
    glCallList(lists);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(3.1f, -2.0f, 0.0f);
    glRotatef(-2.0f * angle - 9.0f, 0, 0, 1);
    glCallList(lists + 1);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(-3.1f, 4.2f, 0.0f);
    glRotatef(-2.0f * angle - 25.0f, 0, 0, 1);
    glCallList(lists + 2);
    glPopMatrix();
}

RGL_REAL_MAIN(draw, 5)
