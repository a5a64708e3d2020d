/* tex_texgen_eye.c: GL_EYE_LINEAR texture coordinate generation: the eye
 * planes are given under one modelview (GL transforms them by its
 * inverse) and the quad is drawn under another, plus a texture matrix
 * (scale and translation) on top. */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    tex_make(GL_RGB, GL_REPEAT, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    rayglPushMatrix();
    rayglTranslatef(30, -10, 0);
    rayglScalef(2, 2, 1);
    static const GLfloat sp[4] = {1.0f / 140, 0, 0, 0}, tp[4] = {0.002f, 1.0f / 100, 0, 0};
    rayglTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    rayglTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    rayglTexGenfv(GL_S, GL_EYE_PLANE, sp);
    rayglTexGenfv(GL_T, GL_EYE_PLANE, tp);
    rayglPopMatrix();
    rayglEnable(GL_TEXTURE_GEN_S);
    rayglEnable(GL_TEXTURE_GEN_T);
    rayglMatrixMode(GL_TEXTURE);
    rayglTranslatef(0.25f, 0, 0);
    rayglScalef(1.5f, 1, 1);
    rayglMatrixMode(GL_MODELVIEW);
    rayglEnable(GL_TEXTURE_2D);
    rayglTranslatef(160, 120, 0);
    rayglRotatef(-15, 0, 0, 1);
    rayglScalef(0.8f, 0.8f, 1); /* inside the view: GL's clipping re-splits a quad */
    rayglTranslatef(-160, -120, 0);
    tex_quad(false);
    return 0;
}

RGL_TEST_MAIN(draw)
