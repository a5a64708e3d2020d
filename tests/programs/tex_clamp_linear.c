/* tex_clamp_linear.c: GL_CLAMP with GL_LINEAR, where GL blends the edge
 * texels with the border colour (here a set one, orange), unlike
 * GL_CLAMP_TO_EDGE; DECAL of RGB (tex_scene.h). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    static const GLfloat orange[4] = {1, 0.5f, 0, 1};
    tex_view(w, h);
    tex_make(GL_RGB, GL_CLAMP, GL_LINEAR);
    rayglTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, orange);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_DECAL);
    rayglEnable(GL_TEXTURE_2D);
    tex_quad(true);
    return 0;
}

RGL_TEST_MAIN(draw)
