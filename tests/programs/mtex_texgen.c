/* mtex_texgen.c: unit 1's coordinates from GL_OBJECT_LINEAR texture
 * generation (unit 1's own planes and enables) and a texture matrix of
 * its own, MODULATE over the checkerboard of unit 0 (mtex_scene.h). */
#include "harness.h"
#include "mtex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    mtex_make(GL_MODULATE, GL_MODULATE);
    /* unit 1 is active: its generation, enables and matrix */
    static const GLfloat sp[4] = {1.0f / 300, 0, 0, -0.05f}, tp[4] = {0, 1.0f / 220, 0, 0};
    rayglTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    rayglTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    rayglTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    rayglTexGenfv(GL_T, GL_OBJECT_PLANE, tp);
    rayglEnable(GL_TEXTURE_GEN_S);
    rayglEnable(GL_TEXTURE_GEN_T);
    rayglMatrixMode(GL_TEXTURE);
    rayglTranslatef(0.5f, 0.5f, 0);
    rayglRotatef(15, 0, 0, 1);
    rayglTranslatef(-0.5f, -0.5f, 0);
    rayglMatrixMode(GL_MODELVIEW);
    rayglActiveTexture(GL_TEXTURE0);
    mtex_quad(true, false);
    return 0;
}

RGL_TEST_MAIN(draw)
