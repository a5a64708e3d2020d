/* point_sprites.c: textured points and point sprites (GL 2.1 3.3, 3.3.1;
 * issue 22). An 8 x 8 texture of 2 x 2 checks, its top-right check red,
 * under a perspective camera, the depth test on, points apart on screen.
 * Row 1: GL_POINT_SPRITE with GL_COORD_REPLACE, GL_MODULATE by each
 * point's colour, GL_NEAREST, the default GL_UPPER_LEFT origin (t runs
 * down the square), sizes from glPointParameter's distance attenuation
 * (not whole pixels: a sprite's size is not rounded). Row 2: the same with
 * GL_LOWER_LEFT, GL_LINEAR and GL_REPLACE, GL_POINT_SMOOTH on (sprites
 * ignore it). Row 3: textured points without sprites, each the texel at
 * its own coordinates. */
#define GL_GLEXT_PROTOTYPES 1
#include <stdbool.h>

#include "harness.h"

#include <raygl/gl.h>
#include <GL/glext.h>

enum { N = 8 };

static void row(float y, int first)
{
    glBegin(GL_POINTS);
    for (int i = 0; i < 6; i++) {
        float z = -4.0f - 1.6f * i;
        glColor3f(1, 1 - 0.12f * i, 0.4f + 0.1f * i);
        glTexCoord2f(0.06f + 0.17f * (i + first), 0.913f - 0.15f * i);
        glVertex3f((-2.6f + 1.05f * i) * -z / 6 + 0.013f, y * -z / 6 + 0.011f, z);
    }
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 1, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    unsigned char px[N * N * 3];
    for (int y = 0; y < N; y++)
        for (int x = 0; x < N; x++) {
            unsigned char *p = px + (y * N + x) * 3;
            bool light = (x / 2 + y / 2) % 2 == 0;
            p[0] = light ? 230 : 30;
            p[1] = light ? 200 : 60;
            p[2] = light ? 40 : 200;
            if (x >= 6 && y >= 6)
                p[0] = 250, p[1] = 10, p[2] = 10;
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    GLuint tex[2];
    glGenTextures(2, tex);
    for (int k = 0; k < 2; k++) {
        glBindTexture(GL_TEXTURE_2D, tex[k]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, N, N, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
        GLint f = k ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
    }
    glEnable(GL_TEXTURE_2D);
    static const GLfloat atten[3] = {0, 0.4f, 0.015f};
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, atten);
    glPointParameterf(GL_POINT_SIZE_MIN, 2);
    glPointParameterf(GL_POINT_SIZE_MAX, 64);
    glPointSize(38);

    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    row(1.3f, 0);

    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    glEnable(GL_POINT_SMOOTH);
    row(0.1f, 0);
    glDisable(GL_POINT_SMOOTH);

    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
    glDisable(GL_POINT_SPRITE);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glPointSize(20);
    row(-1.2f, 0);
    return 0;
}

RGL_TEST_MAIN(draw)
