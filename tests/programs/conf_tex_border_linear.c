/* conf_tex_border_linear.c: GL_CLAMP_TO_BORDER under GL_LINEAR
 * magnification. A 4 x 4 texture of distinct texels on quads whose
 * coordinates run from -0.75 to 1.75: outside [0, 1] the border colour
 * (magenta; then a green of alpha 0.5, blending off), blended with the
 * edge texels over the half texel at the edge; then the border in s
 * alone, t clamped to its edge; and GL_NEAREST (no blend at the edge).
 * Unlit, window pixels, GL_REPLACE. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.3f, 0.3f, 0.3f);
    GLubyte texels[4][4][3];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            texels[y][x][0] = (GLubyte)(40 + 70 * x);
            texels[y][x][1] = (GLubyte)(230 - 60 * y);
            texels[y][x][2] = (GLubyte)((x + y) % 2 ? 220 : 30);
        }
    static const GLint wraps_s[4] = {GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER,
                                     GL_CLAMP_TO_BORDER};
    static const GLint wraps_t[4] = {GL_CLAMP_TO_BORDER, GL_CLAMP_TO_BORDER, GL_CLAMP_TO_EDGE,
                                     GL_CLAMP_TO_BORDER};
    static const GLfloat border[2][4] = {{0.9f, 0.1f, 0.6f, 1.0f}, {0.2f, 0.8f, 0.3f, 0.5f}};
    GLuint tex[4];
    glGenTextures(4, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int i = 0; i < 4; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
        GLint f = i == 3 ? GL_NEAREST : GL_LINEAR;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps_s[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps_t[i]);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border[i == 1]);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    for (int i = 0; i < 4; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        float x0 = 20.25f + 75.0f * (float)i, y0 = 60.25f, s = 58.0f;
        glBegin(GL_QUADS);
        glTexCoord2f(-0.75f, -0.75f);
        glVertex2f(x0, y0);
        glTexCoord2f(1.75f, -0.75f);
        glVertex2f(x0 + s, y0);
        glTexCoord2f(1.75f, 1.75f);
        glVertex2f(x0 + s, y0 + 2 * s);
        glTexCoord2f(-0.75f, 1.75f);
        glVertex2f(x0, y0 + 2 * s);
        glEnd();
    }
    glDisable(GL_TEXTURE_2D);
    glDeleteTextures(4, tex);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
