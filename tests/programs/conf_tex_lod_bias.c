/* conf_tex_lod_bias.c: GL_TEXTURE_LOD_BIAS. A mipmapped 64 x 64 texture
 * whose levels are each one flat colour (so the level GL picks shows as
 * its colour), repeated 4 x 8 times over three rectangles of 64 x 128
 * pixels (4 texels a pixel: level 2 unbiased), GL_NEAREST_MIPMAP_NEAREST:
 * bias 0, +1.5 (the texture parameter: level 3.5, so 4) and -1 (the
 * environment's, GL_TEXTURE_FILTER_CONTROL: level 1). Unlit, window
 * pixels. */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    static const GLubyte level_colour[7][3] = {{230, 60, 60}, {60, 200, 60}, {60, 90, 230},
                                               {220, 220, 60}, {200, 60, 200}, {60, 210, 210},
                                               {240, 240, 240}};
    static GLubyte img[64 * 64 * 3];
    GLuint tex[3];
    glGenTextures(3, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int t = 0; t < 3; t++) {
        glBindTexture(GL_TEXTURE_2D, tex[t]);
        for (int l = 0, s = 64; s >= 1; l++, s /= 2) {
            for (int i = 0; i < s * s; i++)
                for (int c = 0; c < 3; c++)
                    img[i * 3 + c] = level_colour[l][c];
            glTexImage2D(GL_TEXTURE_2D, l, GL_RGB, s, s, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, t == 1 ? 1.5f : 0.0f);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (int t = 0; t < 3; t++) {
        glBindTexture(GL_TEXTURE_2D, tex[t]);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, t == 2 ? -1.0f : 0.0f);
        float x0 = 20.25f + 100.0f * (float)t;
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0);
        glVertex2f(x0, 60.25f);
        glTexCoord2f(4, 0);
        glVertex2f(x0 + 64.0f, 60.25f);
        glTexCoord2f(4, 8);
        glVertex2f(x0 + 64.0f, 188.25f);
        glTexCoord2f(0, 8);
        glVertex2f(x0, 188.25f);
        glEnd();
    }
    glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 0.0f);
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(3, tex);
    return 0;
}

RGL_TEST_MAIN(draw)
