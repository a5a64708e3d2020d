/* conf_hud.c: several projections in one frame, as a game draws them: a
 * depth-tested perspective scene (a floor and three boxes), a second
 * perspective view of the same scene from above in a corner viewport (a
 * minimap, its depth cleared by a scissored glClear first), then a HUD in
 * window pixels with gluOrtho2D and the depth test off: a translucent
 * panel, a health bar in two parts and a crosshair of two thin
 * rectangles. Unlit. */
#include "harness.h"

#include <raygl/gl.h>

static void box(float x, float z, float s, float r, float g, float b)
{
    static const float v[8][3] = {{-1, 0, -1}, {1, 0, -1}, {1, 2, -1}, {-1, 2, -1},
                                  {-1, 0, 1},  {1, 0, 1},  {1, 2, 1},  {-1, 2, 1}};
    static const int f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
    glPushMatrix();
    glTranslatef(x, 0.0f, z);
    glScalef(s, s, s);
    glBegin(GL_QUADS);
    for (int i = 0; i < 6; i++) {
        float k = 0.55f + 0.08f * (float)i;
        glColor3f(r * k, g * k, b * k);
        for (int j = 0; j < 4; j++)
            glVertex3fv(v[f[i][j]]);
    }
    glEnd();
    glPopMatrix();
}

static void scene(void)
{
    glColor3f(0.3f, 0.45f, 0.3f);
    glBegin(GL_QUADS);
    glVertex3f(-8.0f, 0.0f, 8.0f);
    glVertex3f(8.0f, 0.0f, 8.0f);
    glVertex3f(8.0f, 0.0f, -8.0f);
    glVertex3f(-8.0f, 0.0f, -8.0f);
    glEnd();
    box(-2.5f, -2.0f, 0.7f, 0.9f, 0.3f, 0.2f);
    box(1.5f, -4.0f, 1.0f, 0.3f, 0.5f, 0.9f);
    box(3.0f, 1.0f, 0.5f, 0.9f, 0.8f, 0.2f);
}

static void rect(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glVertex2f(x0 + 0.25f, y0 + 0.25f);
    glVertex2f(x1 + 0.25f, y0 + 0.25f);
    glVertex2f(x1 + 0.25f, y1 + 0.25f);
    glVertex2f(x0 + 0.25f, y1 + 0.25f);
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.5f, 0.6f, 0.8f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(55.0, (double)w / h, 0.5, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.3, 2.2, 7.0, 0.0, 0.8, 0.0, 0.0, 1.0, 0.0);
    scene();

    int mw = w / 4, mh = h / 4;
    glEnable(GL_SCISSOR_TEST);
    glScissor(w - mw - 6, h - mh - 6, mw, mh);
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glViewport(w - mw - 6, h - mh - 6, mw, mh);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60.0, (double)mw / mh, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.0, 14.0, 0.01, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0);
    scene();

    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (double)w, 0.0, (double)h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
    rect(8, 8, 128, 36);
    glDisable(GL_BLEND);
    glColor3f(0.2f, 0.9f, 0.2f);
    rect(14, 16, 90, 28);
    glColor3f(0.5f, 0.1f, 0.1f);
    rect(90, 16, 122, 28);
    glColor3f(1.0f, 1.0f, 1.0f);
    rect((float)w / 2 - 8, (float)h / 2 - 1, (float)w / 2 + 8, (float)h / 2 + 1);
    rect((float)w / 2 - 1, (float)h / 2 - 8, (float)w / 2 + 1, (float)h / 2 + 8);
    return 0;
}

RGL_TEST_MAIN(draw)
