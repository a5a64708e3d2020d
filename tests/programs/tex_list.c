/* tex_list.c: textures inside display lists: one list defines the texture
 * object (glTexImage2D compiled into it), another binds it and draws a
 * textured quad, called four times with different transforms and
 * environment modes (the repeated calls share one prototype). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    unsigned char px[TEX_N * TEX_N * 4];
    tex_checker(px);
    GLuint base = rayglGenLists(2);
    rayglNewList(base, GL_COMPILE);
    rayglBindTexture(GL_TEXTURE_2D, 3);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TEX_N, TEX_N, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglEndList();
    rayglNewList(base + 1, GL_COMPILE);
    rayglBindTexture(GL_TEXTURE_2D, 3);
    rayglBegin(GL_QUADS);
    rayglTexCoord2f(0, 0);
    rayglVertex2f(0, 0);
    rayglTexCoord2f(1, 0);
    rayglVertex2f(120, 0);
    rayglTexCoord2f(1, 1);
    rayglVertex2f(120, 90);
    rayglTexCoord2f(0, 1);
    rayglVertex2f(0, 90);
    rayglEnd();
    rayglEndList();

    rayglCallList(base);
    rayglBindTexture(GL_TEXTURE_2D, 0);
    rayglEnable(GL_TEXTURE_2D);
    static const float at[4][2] = {{20, 15}, {170, 15}, {20, 130}, {170, 130}};
    static const GLenum env[4] = {GL_MODULATE, GL_MODULATE, GL_REPLACE, GL_MODULATE};
    static const float col[4][3] = {{1, 1, 1}, {1, 0.6f, 0.3f}, {0.2f, 0.2f, 0.2f}, {1, 1, 1}};
    for (int i = 0; i < 4; i++) {
        rayglPushMatrix();
        rayglTranslatef(at[i][0], at[i][1], 0);
        rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)env[i]);
        rayglColor3fv(col[i]);
        rayglCallList(base + 1);
        rayglPopMatrix();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
