/* tex_lod_bias.c: the level of detail's bias and clamps (GL 2.1 3.8.8,
 * 3.8.9; issue 22). A receding floor in five strips, each its own texture
 * object holding the same 64 x 64 mipmap whose levels are flat colours
 * (level 0 red, 1 yellow, 2 green, 3 cyan, 4 blue, 5 magenta, 6 white),
 * GL_NEAREST_MIPMAP_LINEAR, so the colour shows the level GL picks:
 * without bias; GL_TEXTURE_LOD_BIAS 1.5 on the object; the unit's
 * GL_TEXTURE_FILTER_CONTROL bias -1 (with the object's 0.5: -0.5 in all);
 * GL_TEXTURE_MIN_LOD 1.5 and MAX_LOD 3; GL_TEXTURE_BASE_LEVEL 2 and
 * MAX_LEVEL 4. GL_REPLACE, unlit. */
#include "harness.h"

#include <raygl/gl.h>

enum { T = 64 };

static const unsigned char level_rgb[7][3] = {
    {230, 40, 40}, {230, 220, 40}, {40, 200, 60}, {40, 210, 220},
    {40, 60, 230}, {220, 50, 220}, {240, 240, 240},
};

static void strip(float x0, float x1, float s0, float s1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(s0, 0);
    glVertex3f(x0, 0, 8);
    glTexCoord2f(s1, 0);
    glVertex3f(x1, 0, 8);
    glTexCoord2f(s1, 24);
    glVertex3f(x1, 0, -60);
    glTexCoord2f(s0, 24);
    glVertex3f(x0, 0, -60);
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.3f, 0.4f, 0.6f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50, (double)w / h, 0.5, 200);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(0.013, 1.5, 6, 0.013, 0.4, -10, 0, 1, 0);
    glEnable(GL_DEPTH_TEST);
    static unsigned char px[T * T * 3];
    GLuint names[5];
    glGenTextures(5, names);
    for (int k = 0; k < 5; k++) {
        glBindTexture(GL_TEXTURE_2D, names[k]);
        for (int l = 0, s = T; s >= 1; l++, s /= 2) {
            for (int i = 0; i < s * s; i++)
                for (int c = 0; c < 3; c++)
                    px[i * 3 + c] = level_rgb[l][c];
            glTexImage2D(GL_TEXTURE_2D, l, GL_RGB, s, s, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    glBindTexture(GL_TEXTURE_2D, names[1]);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 1.5f);
    glBindTexture(GL_TEXTURE_2D, names[2]);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 0.5f);
    glBindTexture(GL_TEXTURE_2D, names[3]);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.5f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, 3);
    glBindTexture(GL_TEXTURE_2D, names[4]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 2);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 4);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (int k = 0; k < 5; k++) {
        glBindTexture(GL_TEXTURE_2D, names[k]);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, k == 2 ? -1.0f : 0.0f);
        strip(-10 + 4.0f * k, -6 + 4.0f * k, 0, 6);
    }
    return 0;
}

RGL_TEST_MAIN(draw)
