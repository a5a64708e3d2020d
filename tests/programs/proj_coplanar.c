/* proj_coplanar.c: draw order in one plane (issue 14). Translucent
 * triangles overlapping in one plane (the later one blends over the
 * earlier), then a wireframe grid and an outline in glOrtho with zNear = 0
 * and the depth test off (drawn in order, on the near plane).
 */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    (void)frame;
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
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 0.6f);
    glVertex2f(20, 20);
    glVertex2f(200, 30);
    glVertex2f(90, 200);
    glColor4f(0, 0, 1, 0.5f);
    glVertex2f(120, 40);
    glVertex2f(300, 60);
    glVertex2f(180, 220);
    glColor4f(0, 0.8f, 0, 0.4f);
    glVertex2f(60, 100);
    glVertex2f(260, 120);
    glVertex2f(150, 230);
    glEnd();
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

RGL_REAL_MAIN(draw, 1)
