/* tex_env_blend.c: the checkerboard (tex_scene.h) with GL_TEXTURE_ENV_MODE
 * GL_BLEND and an orange GL_TEXTURE_ENV_COLOR, one unit, unlit, corner
 * colours: C = Cf (1 - Ct) + Cc Ct per channel (GL 1.5 table 3.22). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    tex_make(GL_RGB, GL_REPEAT, GL_NEAREST);
    static const GLfloat env[4] = {1.0f, 0.55f, 0.1f, 1};
    rayglTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    rayglEnable(GL_TEXTURE_2D);
    tex_quad(true);
    return 0;
}

RGL_TEST_MAIN(draw)
