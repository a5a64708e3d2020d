/* real_spiky_ball.c: a bouncing ball with spikes in the style of the
 * dangerball screensaver: a lit gluSphere with cones (gluCylinder of top
 * radius 0) pointing out along a spread of directions whose lengths pulse
 * frame by frame, the whole turning and moving up and down. One positional
 * light, local viewer, specular. Four frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.0f, 0.0f, 0.05f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(35, (double)w / h, 1, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat pos[4] = {3, 4, 4, 1}, white[4] = {1, 1, 1, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightfv(GL_LIGHT0, GL_SPECULAR, white);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glTranslatef(0.0013f, -0.3f + 0.35f * sinf(1.3f * (float)frame), -9.0f);
    glRotatef(10.0f * (float)frame, 0.3f, 1.0f, 0.1f);
    const GLfloat ball[4] = {0.8f, 0.15f, 0.1f, 1}, spike[4] = {0.85f, 0.85f, 0.9f, 1};
    const GLfloat spec[4] = {0.7f, 0.7f, 0.7f, 1};
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 60);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, ball);
    GLUquadric *q = gluNewQuadric();
    gluQuadricNormals(q, GLU_SMOOTH);
    gluSphere(q, 1.0, 32, 24);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, spike);
    const int n = 14;
    for (int i = 0; i < n; i++) {
        /* Directions spread over the sphere (a golden-angle spiral). */
        float y = 1.0f - 2.0f * ((float)i + 0.5f) / n, r = sqrtf(1.0f - y * y);
        float phi = (float)i * 2.39996f;
        float d[3] = {r * cosf(phi), y, r * sinf(phi)};
        float len = 0.6f + 0.4f * (0.5f + 0.5f * sinf((float)(frame + i)));
        glPushMatrix();
        /* Turn +z onto d. */
        float ax = -d[1], ay = d[0], ang = acosf(d[2]) * 180.0f / (float)M_PI;
        if (fabsf(ax) + fabsf(ay) > 1e-4f)
            glRotatef(ang, ax, ay, 0.0f);
        else if (d[2] < 0)
            glRotatef(180.0f, 1, 0, 0);
        glTranslatef(0, 0, 0.85f);
        gluCylinder(q, 0.22, 0.0, len, 16, 1);
        glPopMatrix();
    }
    gluDeleteQuadric(q);
}

RGL_REAL_MAIN(draw, 4)
