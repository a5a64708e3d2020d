/* real_robot_arm.c: the red book's robot arm: a shoulder and an elbow
 * joint, each a scaled unit cube drawn in a glPushMatrix/glPopMatrix
 * hierarchy with glTranslate/glRotate, plus a two-fingered hand, over a
 * floor, the joints at angles the frame number gives; the cubes filled,
 * unlit, each face its colour. Four frames. */
#include "real.h"

#include <raygl/gl.h>

static void cube(float r, float g, float b)
{
    static const float v[8][3] = {{-0.5f, -0.5f, -0.5f}, {0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, -0.5f},
                                  {-0.5f, 0.5f, -0.5f},  {-0.5f, -0.5f, 0.5f}, {0.5f, -0.5f, 0.5f},
                                  {0.5f, 0.5f, 0.5f},    {-0.5f, 0.5f, 0.5f}};
    static const int f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++) {
        float k = 0.5f + 0.09f * (float)i;
        glColor3f(r * k, g * k, b * k);
        for (int j = 0; j < 4; j++)
            glVertex3fv(v[f[i][j]]);
    }
    glEnd();
}

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.15f, 0.15f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 1, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, -0.8f, -8.0f);
    glRotatef(20, 1, 0, 0);
    glRotatef(-25.0f + 8.0f * (float)frame, 0, 1, 0);
    glColor3f(0.35f, 0.4f, 0.35f);
    glBegin(GL_QUADS);
    glVertex3f(-4, -1, 3);
    glVertex3f(4, -1, 3);
    glVertex3f(4, -1, -3);
    glVertex3f(-4, -1, -3);
    glEnd();
    float shoulder = -20.0f + 25.0f * (float)frame, elbow = 30.0f + 20.0f * (float)frame;
    glTranslatef(-1.0f, 0, 0);
    glRotatef(shoulder, 0, 0, 1);
    glTranslatef(1.0f, 0, 0);
    glPushMatrix();
    glScalef(2.0f, 0.4f, 1.0f);
    cube(0.9f, 0.5f, 0.2f);
    glPopMatrix();
    glTranslatef(1.0f, 0, 0);
    glRotatef(elbow, 0, 0, 1);
    glTranslatef(1.0f, 0, 0);
    glPushMatrix();
    glScalef(2.0f, 0.4f, 1.0f);
    cube(0.3f, 0.6f, 0.9f);
    glPopMatrix();
    for (int k = -1; k <= 1; k += 2) {
        glPushMatrix();
        glTranslatef(1.0f, 0, 0.3f * (float)k);
        glRotatef(-15.0f * (float)k * (float)(frame % 2 ? 1 : 2), 0, 1, 0);
        glTranslatef(0.3f, 0, 0);
        glScalef(0.6f, 0.15f, 0.15f);
        cube(0.9f, 0.9f, 0.3f);
        glPopMatrix();
    }
}

RGL_REAL_MAIN(draw, 4)
