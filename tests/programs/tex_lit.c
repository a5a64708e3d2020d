/* tex_lit.c: a lit, textured square (a fine grid) (GL_MODULATE multiplies the lit colour
 * by the texel) under a local viewer and a point light, with a white
 * material (grey diffuse: POV-Ray's diffuse is one number) and no
 * specular (GL modulates a highlight by the texel, POV-Ray adds it). */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(45, (double)w / h, 1, 100);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglEnable(GL_DEPTH_TEST);
    rayglLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    static const GLfloat lpos[4] = {1, 2, 1, 1}, amb[4] = {0.2f, 0.2f, 0.2f, 1};
    static const GLfloat white[4] = {0.9f, 0.9f, 0.9f, 1}, none[4] = {0, 0, 0, 1};
    rayglLightfv(GL_LIGHT0, GL_POSITION, lpos);
    rayglLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    rayglEnable(GL_LIGHTING);
    rayglEnable(GL_LIGHT0);
    rayglMaterialfv(GL_FRONT, GL_DIFFUSE, white);
    rayglMaterialfv(GL_FRONT, GL_SPECULAR, none);
    tex_make(GL_RGB, GL_REPEAT, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    rayglEnable(GL_TEXTURE_2D);
    rayglTranslatef(0, 0, -5);
    rayglRotatef(-50, 1, 0, 0);
    /* A fine grid: GL lights the vertices, POV-Ray every pixel. */
    enum { N = 32 };
    for (int j = 0; j < N; j++) {
        rayglBegin(GL_QUAD_STRIP);
        rayglNormal3f(0, 0, 1);
        for (int i = 0; i <= N; i++)
            for (int k = 1; k >= 0; k--) {
                float u = (float)i / N, v = (float)(j + k) / N;
                rayglTexCoord2f(2 * u, 2 * v);
                rayglVertex2f(-1.5f + 3 * u, -1.5f + 3 * v);
            }
        rayglEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
