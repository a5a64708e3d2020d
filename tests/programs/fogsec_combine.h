/* fogsec_combine.h: mtex_scene.h's two units with their environments
 * written as GL_COMBINE settings (GL 1.3), which equal the fixed modes:
 * unit 0 MODULATE(PRIMARY_COLOR, TEXTURE), unit 1 COMBINE_SETUP (the
 * including program's). Included by fogsec_combine_*.c. */
#include "harness.h"
#include "mtex_scene.h"

static void combine(GLenum fn, GLenum s0, GLenum o0, GLenum s1, GLenum o1, GLenum s2, GLenum o2)
{
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)fn);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, (GLint)s0);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, (GLint)o0);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, (GLint)s1);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, (GLint)o1);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, (GLint)s2);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, (GLint)o2);
    rayglTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 1.0f);
}

static int draw(int w, int h)
{
    tex_view(w, h);
    mtex_make(GL_MODULATE, GL_MODULATE);
    rayglActiveTexture(GL_TEXTURE0);
    combine(GL_MODULATE, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_COLOR, GL_CONSTANT,
            GL_SRC_ALPHA);
    rayglActiveTexture(GL_TEXTURE1);
    COMBINE_SETUP;
    mtex_quad(false, true);
    return 0;
}

RGL_TEST_MAIN(draw)
