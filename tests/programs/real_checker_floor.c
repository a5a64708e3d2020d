/* real_checker_floor.c: a textured checkerboard floor (GL_NEAREST,
 * GL_REPEAT, GL_REPLACE) under a turning colour pyramid. Two frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    static GLubyte tex[8][8][3];
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++) {
            GLubyte v = ((i ^ j) & 1) ? 230 : 40;
            tex[i][j][0] = v;
            tex[i][j][1] = v;
            tex[i][j][2] = (GLubyte)(v / 2 + 60);
        }
    glViewport(0, 0, w, h);
    glClearColor(0.2f, 0.25f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 1, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.01, 3, 6, 0, 0, 0, 0, 1, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex3f(-3, 0, 3);
    glTexCoord2f(2, 0);
    glVertex3f(3, 0, 3);
    glTexCoord2f(2, 2);
    glVertex3f(3, 0, -3);
    glTexCoord2f(0, 2);
    glVertex3f(-3, 0, -3);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glTranslatef(0, 0.01f, 0);
    glRotatef(25.0f * (float)frame + 10, 0, 1, 0);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex3f(0, 1.8f, 0);
    const float b[5][2] = {{-1, 1}, {1, 1}, {1, -1}, {-1, -1}, {-1, 1}};
    const float c[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}};
    for (int i = 0; i < 5; i++) {
        glColor3fv(c[i % 4]);
        glVertex3f(b[i][0], 0, b[i][1]);
    }
    glEnd();
}

RGL_REAL_MAIN(draw, 2)
