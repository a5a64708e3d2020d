/* tex_blend.c: texel alpha under blending (GL_SRC_ALPHA,
 * GL_ONE_MINUS_SRC_ALPHA): the checkerboard's dark squares (alpha 64/255)
 * let an opaque quad behind show through, MODULATE with opaque vertex
 * colours and REPLACE of RGBA side by side (tex_scene.h). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    rayglEnable(GL_DEPTH_TEST);
    rayglColor3f(0.9f, 0.2f, 0.4f);
    rayglBegin(GL_QUADS);
    rayglVertex3f(40, 50, -0.5f);
    rayglVertex3f(280, 50, -0.5f);
    rayglVertex3f(280, 190, -0.5f);
    rayglVertex3f(40, 190, -0.5f);
    rayglEnd();
    tex_make(GL_RGBA, GL_REPEAT, GL_NEAREST);
    rayglEnable(GL_TEXTURE_2D);
    rayglEnable(GL_BLEND);
    rayglBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int k = 0; k < 2; k++) {
        rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, k ? GL_REPLACE : GL_MODULATE);
        float x0 = k ? 165.0f : 20.0f;
        rayglBegin(GL_QUADS);
        rayglColor3f(1, 1, 1);
        rayglTexCoord2f(0, 0);
        rayglVertex2f(x0, 20);
        rayglColor3f(0.6f, 1, 0.8f);
        rayglTexCoord2f(1, 0);
        rayglVertex2f(x0 + 135, 20);
        rayglTexCoord2f(1, 1);
        rayglVertex2f(x0 + 135, 220);
        rayglColor3f(1, 1, 1);
        rayglTexCoord2f(0, 1);
        rayglVertex2f(x0, 220);
        rayglEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
