/* tex_lit_scene.h: the lit, textured scene of tex_lit_gold.c, tex_lit_env.c
 * and tex_lit_cm.c: a grey wood-like 16 x 16 texture on squares of 16 x 16
 * quads, under a local viewer and a point light with no specular. Each
 * file sets its texture environment between tex_lit_begin and
 * tex_lit_place, then its materials and squares.
 */
#include "harness.h"
#include "tex_scene.h"

/* Grey rings with a little grain, 16 x 16. */
static void wood(unsigned char px[16 * 16 * 3])
{
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 16; x++) {
            int r = ((x - 3) * (x - 3) + (y - 5) * (y - 5)) / 6;
            unsigned char v = (unsigned char)(r % 2 ? 150 : 230);
            v = (unsigned char)(v - ((x * 7 + y * 3) % 5) * 6);
            for (int k = 0; k < 3; k++)
                px[(y * 16 + x) * 3 + k] = v;
        }
}

/* A square from x0, width wide, 2.4 high; with coloured, each vertex's
 * colour runs from yellow to cyan to magenta over it. */
static void tex_lit_square(float x0, float width, bool coloured)
{
    enum { N = 16 };
    for (int j = 0; j < N; j++) {
        rayglBegin(GL_QUAD_STRIP);
        rayglNormal3f(0, 0, 1);
        for (int i = 0; i <= N; i++)
            for (int k = 1; k >= 0; k--) {
                float u = (float)i / N, v = (float)(j + k) / N;
                if (coloured)
                    rayglColor3f(0.75f - 0.5f * v, 0.7f - 0.4f * u * v, 0.2f + 0.5f * u);
                rayglTexCoord2f(u, v);
                rayglVertex2f(x0 + width * u, -1.2f + 2.4f * v);
            }
        rayglEnd();
    }
}

/* The camera, the light and the wood texture (px, bound, nearest filters). */
static void tex_lit_begin(int w, int h, unsigned char px[16 * 16 * 3])
{
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(45, (double)w / h, 1, 100);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglEnable(GL_DEPTH_TEST);
    rayglLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    static const GLfloat lpos[4] = {0.5f, 1, 1, 1}, amb[4] = {0.25f, 0.25f, 0.25f, 1};
    static const GLfloat none[4] = {0, 0, 0, 1};
    rayglLightfv(GL_LIGHT0, GL_POSITION, lpos);
    rayglLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    rayglEnable(GL_LIGHTING);
    rayglEnable(GL_LIGHT0);
    rayglMaterialfv(GL_FRONT, GL_SPECULAR, none);
    wood(px);
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
}

/* Texturing on, and the squares placed before the camera. */
static void tex_lit_place(void)
{
    rayglEnable(GL_TEXTURE_2D);
    rayglTranslatef(0, 0, -4);
    rayglRotatef(-30, 1, 0, 0);
}
