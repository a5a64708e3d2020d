/* real_tunnel.c: a flying-tunnel screensaver: a textured cylinder of quad
 * strips (a 32 x 32 checker-and-stripe texture, GL_REPEAT, GL_NEAREST,
 * GL_REPLACE) seen from inside, the texture scrolling along it through the
 * texture matrix (glMatrixMode(GL_TEXTURE), glTranslatef) frame by frame,
 * linear fog to black toward the far end. Four frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static void draw(int frame, int w, int h)
{
    static GLuint tex;
    if (frame == 0) {
        static GLubyte img[32][32][3];
        for (int y = 0; y < 32; y++)
            for (int x = 0; x < 32; x++) {
                int c = ((x / 8) + (y / 8)) % 2;
                img[y][x][0] = (GLubyte)(c ? 220 : 40);
                img[y][x][1] = (GLubyte)(y % 8 < 2 ? 220 : c ? 120 : 60);
                img[y][x][2] = (GLubyte)(c ? 60 : 200);
            }
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 32, 32, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60, (double)w / h, 0.2, 40);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.0f, -0.125f * (float)frame, 0.0f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(3.0f * (float)frame, 0, 0, 1);
    glEnable(GL_FOG);
    const GLfloat black[4] = {0, 0, 0, 1};
    glFogfv(GL_FOG_COLOR, black);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 4.0f);
    glFogf(GL_FOG_END, 22.0f);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    const int sides = 24, rings = 24;
    for (int i = 0; i < sides; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= rings; j++)
            for (int k = 0; k < 2; k++) {
                double a = 2 * M_PI * (i + k) / sides;
                glTexCoord2f((float)(i + k) / 6.0f, (float)j / 2.0f);
                glVertex3d(1.5 * cos(a) + 0.0013, 1.5 * sin(a) + 0.0017, -1.0 * j);
            }
        glEnd();
    }
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_FOG);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
}

RGL_REAL_MAIN(draw, 4)
