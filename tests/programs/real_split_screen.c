/* real_split_screen.c: a two-player racing game's frame: the window cleared
 * whole, then the left and right halves each drawn in its own viewport
 * with its own perspective camera following its car (a box) along a road
 * of quads lined with posts, then a divider and each player's speed bar
 * in window pixels across both. Unlit. Three frames. */
#include "real.h"

#include <raygl/gl.h>

static void box(float x, float y, float z, float sx, float sy, float sz, float r, float g, float b)
{
    static const float v[8][3] = {{-1, 0, -1}, {1, 0, -1}, {1, 1, -1}, {-1, 1, -1},
                                  {-1, 0, 1},  {1, 0, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++) {
        float k = 0.55f + 0.08f * (float)i;
        glColor3f(r * k, g * k, b * k);
        for (int j = 0; j < 4; j++)
            glVertex3f(x + sx * v[f[i][j]][0], y + sy * v[f[i][j]][1], z + sz * v[f[i][j]][2]);
    }
    glEnd();
}

static void world(float car0, float car1)
{
    glColor3f(0.25f, 0.45f, 0.25f);
    glBegin(GL_QUADS);
    glVertex3f(-20, -0.01f, 5);
    glVertex3f(20, -0.01f, 5);
    glVertex3f(20, -0.01f, -60);
    glVertex3f(-20, -0.01f, -60);
    glEnd();
    glColor3f(0.35f, 0.35f, 0.38f);
    glBegin(GL_QUADS);
    glVertex3f(-3, 0, 5);
    glVertex3f(3, 0, 5);
    glVertex3f(3, 0, -60);
    glVertex3f(-3, 0, -60);
    glEnd();
    for (int i = 0; i < 10; i++) {
        box(-3.6f, 0, -6.0f * (float)i, 0.15f, 1.0f, 0.15f, 0.9f, 0.9f, 0.9f);
        box(3.6f, 0, -6.0f * (float)i - 3.0f, 0.15f, 1.0f, 0.15f, 0.9f, 0.9f, 0.9f);
    }
    box(-1.3f, 0, -car0, 0.7f, 0.6f, 1.2f, 0.9f, 0.2f, 0.2f);
    box(1.3f, 0, -car1, 0.7f, 0.6f, 1.2f, 0.2f, 0.4f, 0.9f);
}

static void draw(int frame, int w, int h)
{
    float car[2] = {5.0f + 4.0f * (float)frame, 4.0f + 5.0f * (float)frame};
    glViewport(0, 0, w, h);
    glClearColor(0.5f, 0.65f, 0.85f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    for (int p = 0; p < 2; p++) {
        glViewport(p * w / 2, 0, w / 2, h);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        gluPerspective(50, (double)(w / 2) / h, 0.5, 80);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        float cx = p ? 1.3f : -1.3f;
        gluLookAt(cx + 0.01, 2.2, -car[p] + 5.5, cx, 0.6, -car[p] - 4.0, 0, 1, 0);
        world(car[0], car[1]);
    }
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glColor3f(0.05f, 0.05f, 0.05f);
    glBegin(GL_QUADS);
    glVertex2f((float)w / 2 - 1.75f, 0.25f);
    glVertex2f((float)w / 2 + 2.25f, 0.25f);
    glVertex2f((float)w / 2 + 2.25f, (float)h + 0.25f);
    glVertex2f((float)w / 2 - 1.75f, (float)h + 0.25f);
    glEnd();
    for (int p = 0; p < 2; p++) {
        float x0 = (float)(p * w / 2) + 10.25f, len = 40.0f + 18.0f * (float)(frame + p);
        glColor3f(1.0f, 0.8f - 0.3f * (float)p, 0.2f);
        glBegin(GL_QUADS);
        glVertex2f(x0, 10.25f);
        glVertex2f(x0 + len, 10.25f);
        glVertex2f(x0 + len, 18.25f);
        glVertex2f(x0, 18.25f);
        glEnd();
    }
}

RGL_REAL_MAIN(draw, 3)
