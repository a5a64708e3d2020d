/* proj_coplanar.c: draw order in one plane (issue 14). Translucent
 * triangles overlapping in one plane, one draw each (the later one blends
 * over the earlier: POV-Ray must tell the draw-order offsets apart), then
 * a wireframe grid and an outline in glOrtho with zNear = 0 and the depth
 * test off (drawn in order, on the near plane, where the camera is).
 * Frame 1: translucent rectangles in one plane in perspective. Frame 2:
 * translucent triangles and quads overlapping within one draw each.
 */
#include "real.h"

#include <raygl/gl.h>

/* Frame 1: the same in perspective, 6 units from the eye. */
static void draw_perspective(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.9f, 0.9f, 0.85f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, -6);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    static const float col[3][4] = {{1, 0, 0, 0.6f}, {0, 0, 1, 0.5f}, {0, 0.8f, 0, 0.4f}};
    for (int t = 0; t < 3; t++) {
        glColor4fv(col[t]);
        glRectf(-2.0f + 0.9f * (float)t, -1.5f + 0.5f * (float)t, 0.2f + 0.9f * (float)t,
                0.7f + 0.5f * (float)t);
    }
    glDisable(GL_BLEND);
}

/* Frame 2: translucent triangles and quads overlapping within one draw
 * each (a particle system's batch). */
static void draw_batch(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.2f, 0.2f, 0.25f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.21f, 0.43f, 0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_TRIANGLES);
    for (int t = 0; t < 4; t++) {
        glColor4f(t % 2 ? 1.0f : 0.2f, 0.3f * (float)t, t % 2 ? 0.1f : 1.0f, 0.6f);
        float x = 20.0f + 35.0f * (float)t;
        glVertex2f(x, 20);
        glVertex2f(x + 110, 30);
        glVertex2f(x + 40, 140);
    }
    glEnd();
    glBegin(GL_QUADS);
    for (int q = 0; q < 4; q++) {
        glColor4f(0.9f, 0.9f - 0.2f * (float)q, 0.2f * (float)q, 0.5f);
        float x = 150.0f + 30.0f * (float)q, y = 90.0f + 25.0f * (float)q;
        glVertex2f(x, y);
        glVertex2f(x + 80, y);
        glVertex2f(x + 80, y + 70);
        glVertex2f(x, y + 70);
    }
    glEnd();
    glDisable(GL_BLEND);
}

static void draw(int frame, int w, int h)
{
    if (frame == 1) {
        draw_perspective(w, h);
        return;
    }
    if (frame == 2) {
        draw_batch(w, h);
        return;
    }
    glViewport(0, 0, w, h);
    glClearColor(0.9f, 0.9f, 0.85f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 320, 0, 240, 0, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.21f, 0.43f, 0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    /* One draw each: GL blends each over the ones before. */
    static const float tri[3][3][2] = {{{20, 20}, {200, 30}, {90, 200}},
                                       {{120, 40}, {300, 60}, {180, 220}},
                                       {{60, 100}, {260, 120}, {150, 230}}};
    static const float col[3][4] = {{1, 0, 0, 0.6f}, {0, 0, 1, 0.5f}, {0, 0.8f, 0, 0.4f}};
    for (int t = 0; t < 3; t++) {
        glColor4fv(col[t]);
        glBegin(GL_TRIANGLES);
        for (int k = 0; k < 3; k++)
            glVertex2fv(tri[t][k]);
        glEnd();
    }
    glDisable(GL_BLEND);
    glColor3f(0.1f, 0.1f, 0.1f);
    glBegin(GL_LINES);
    for (int x = 0; x <= 320; x += 40) {
        glVertex2f((float)x + 0.5f, 0);
        glVertex2f((float)x + 0.5f, 240);
    }
    glEnd();
    glColor3f(0.8f, 0.3f, 0);
    glBegin(GL_LINE_LOOP);
    glVertex2f(20.5f, 20.5f);
    glVertex2f(299.5f, 20.5f);
    glVertex2f(299.5f, 219.5f);
    glVertex2f(20.5f, 219.5f);
    glEnd();
}

RGL_REAL_MAIN(draw, 3)
