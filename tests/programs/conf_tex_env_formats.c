/* conf_tex_env_formats.c: each texture environment on each base internal
 * format. Rows: GL_RGB, GL_RGBA, GL_ALPHA, GL_LUMINANCE,
 * GL_LUMINANCE_ALPHA, GL_INTENSITY textures (the same 4 x 4 texels
 * reduced to each format); columns: GL_MODULATE, GL_REPLACE, GL_DECAL,
 * GL_BLEND (with a GL_TEXTURE_ENV_COLOR), GL_ADD, over a fragment colour of
 * its own per column. GL_DECAL is left out for the formats GL leaves it
 * undefined for (alpha, luminance, luminance-alpha, intensity). Blending
 * off: only the colour channels show. GL_NEAREST, magnified, window
 * pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static void quad(int x0, int y0, int x1, int y1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f((float)x0 + 0.25f, (float)y0 + 0.25f);
    glTexCoord2f(1, 0);
    glVertex2f((float)x1 + 0.25f, (float)y0 + 0.25f);
    glTexCoord2f(1, 1);
    glVertex2f((float)x1 + 0.25f, (float)y1 + 0.25f);
    glTexCoord2f(0, 1);
    glVertex2f((float)x0 + 0.25f, (float)y1 + 0.25f);
    glEnd();
}

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.15f, 0.15f, 0.15f);
    static const GLenum formats[6] = {GL_RGB, GL_RGBA, GL_ALPHA, GL_LUMINANCE,
                                      GL_LUMINANCE_ALPHA, GL_INTENSITY};
    static const GLenum envs[5] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_BLEND, GL_ADD};
    GLubyte texels[4][4][4];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            texels[y][x][0] = (GLubyte)(40 + 60 * x);
            texels[y][x][1] = (GLubyte)(220 - 50 * y);
            texels[y][x][2] = (GLubyte)((x + y) % 2 ? 200 : 60);
            texels[y][x][3] = (GLubyte)(50 + 50 * ((x + 2 * y) % 4));
        }
    GLuint tex[6];
    glGenTextures(6, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int f = 0; f < 6; f++) {
        glBindTexture(GL_TEXTURE_2D, tex[f]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[f], 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    }
    const GLfloat envc[4] = {0.2f, 0.9f, 0.6f, 1.0f};
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envc);
    glEnable(GL_TEXTURE_2D);
    for (int f = 0; f < 6; f++) {
        glBindTexture(GL_TEXTURE_2D, tex[f]);
        for (int e = 0; e < 5; e++) {
            if (envs[e] == GL_DECAL && f >= 2)
                continue;
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)envs[e]);
            glColor4f(0.9f - 0.15f * (float)e, 0.5f + 0.1f * (float)e, 0.4f, 0.6f);
            quad(4 + 63 * e, h - 40 - 39 * f, 60 + 63 * e, h - 4 - 39 * f);
        }
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(6, tex);
    return 0;
}

RGL_TEST_MAIN(draw)
