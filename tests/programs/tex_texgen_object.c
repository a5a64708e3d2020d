/* tex_texgen_object.c: GL_OBJECT_LINEAR texture coordinate generation
 * (s and t from object x and y through planes with an offset), on a quad
 * drawn under a rotation, so that object and eye coordinates differ. */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    tex_make(GL_RGB, GL_REPEAT, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    static const GLfloat sp[4] = {1.0f / 140, 0, 0, -0.3f}, tp[4] = {0, 1.0f / 100, 0, 0.1f};
    rayglTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    rayglTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    rayglTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    rayglTexGenfv(GL_T, GL_OBJECT_PLANE, tp);
    rayglEnable(GL_TEXTURE_GEN_S);
    rayglEnable(GL_TEXTURE_GEN_T);
    rayglEnable(GL_TEXTURE_2D);
    rayglTranslatef(160, 120, 0);
    rayglRotatef(20, 0, 0, 1);
    rayglScalef(0.8f, 0.8f, 1); /* inside the view: GL's clipping re-splits a quad */
    rayglTranslatef(-160, -120, 0);
    tex_quad(false);
    return 0;
}

RGL_TEST_MAIN(draw)
