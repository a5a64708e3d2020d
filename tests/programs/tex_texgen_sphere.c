/* tex_texgen_sphere.c: GL_SPHERE_MAP texture coordinate generation on a
 * gluSphere (smooth normals), unlit, REPLACE, linear filtering. POV-Ray
 * has no sphere map: the translator computes GL's per-vertex coordinates,
 * and both interpolate them across the faces. */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    rayglEnable(GL_DEPTH_TEST);
    tex_make(GL_RGB, GL_REPEAT, GL_LINEAR);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    rayglTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    rayglTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    rayglEnable(GL_TEXTURE_GEN_S);
    rayglEnable(GL_TEXTURE_GEN_T);
    rayglEnable(GL_TEXTURE_2D);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglOrtho(0, 320, 0, 240, -200, 200);
    rayglMatrixMode(GL_MODELVIEW);
    rayglTranslatef(160, 120, 0);
    rayglRotatef(30, 1, 0.3f, 0);
    GLUquadric *q = raygluNewQuadric();
    raygluSphere(q, 100, 48, 24);
    raygluDeleteQuadric(q);
    return 0;
}

RGL_TEST_MAIN(draw)
