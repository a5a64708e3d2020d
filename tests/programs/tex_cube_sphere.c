/* tex_cube_sphere.c: a cube map (six 8 x 8 faces, each its own colour
 * with checks, GL_CLAMP_TO_EDGE, GL_NEAREST) on a sphere of GL_TRIANGLES
 * through GL_REFLECTION_MAP texgen on s, t and r, REPLACE, in
 * perspective; beside it a quad with explicit (s, t, r) across two faces.
 * GL interpolates the per-vertex direction and picks the face per pixel
 * (GL 2.1 3.8.6); so must the translation. Issue 14. */
#include <math.h>
#include <stdbool.h>

#include "harness.h"
#include "raygl.h"

enum { F = 8 };

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(40, (double)w / h, 1, 50);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0, 0, -6);
    rayglEnable(GL_DEPTH_TEST);
    static const unsigned char base[6][3] = {{230, 60, 60},  {60, 200, 60}, {70, 90, 230},
                                             {230, 210, 60}, {60, 210, 220}, {220, 70, 220}};
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_CUBE_MAP, name);
    for (int k = 0; k < 6; k++) {
        unsigned char px[F * F * 3];
        for (int y = 0; y < F; y++)
            for (int x = 0; x < F; x++)
                for (int c = 0; c < 3; c++) {
                    bool dark = (x / 2 + y / 2) % 2 != 0;
                    px[(y * F + x) * 3 + c] = (unsigned char)(dark ? base[k][c] / 2 : base[k][c]);
                }
        rayglTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + (GLenum)k, 0, GL_RGB, F, F, 0, GL_RGB,
                        GL_UNSIGNED_BYTE, px);
    }
    rayglTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    rayglTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    rayglTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    rayglEnable(GL_TEXTURE_CUBE_MAP);
    /* the sphere, reflection-mapped */
    rayglTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    rayglTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    rayglTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    rayglEnable(GL_TEXTURE_GEN_S);
    rayglEnable(GL_TEXTURE_GEN_T);
    rayglEnable(GL_TEXTURE_GEN_R);
    rayglPushMatrix();
    rayglTranslatef(-0.9f, 0, 0);
    rayglRotatef(20, 1, 0.5f, 0);
    enum { SL = 24, ST = 12 };
    rayglBegin(GL_TRIANGLES);
    for (int j = 0; j < ST; j++)
        for (int i = 0; i < SL; i++) {
            static const int corner[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
            for (int k = 0; k < 6; k++) {
                int a = i + corner[k][0], b = j + corner[k][1];
                double lon = 2 * M_PI * a / SL, lat = M_PI * b / ST - M_PI / 2;
                float n[3] = {(float)(cos(lat) * sin(lon)), (float)sin(lat),
                              (float)(cos(lat) * cos(lon))};
                rayglNormal3fv(n);
                rayglVertex3f(n[0], n[1], n[2]);
            }
        }
    rayglEnd();
    rayglPopMatrix();
    /* the quad, explicit coordinates: from +X's face across to +Z's */
    rayglDisable(GL_TEXTURE_GEN_S);
    rayglDisable(GL_TEXTURE_GEN_T);
    rayglDisable(GL_TEXTURE_GEN_R);
    rayglBegin(GL_TRIANGLES);
    static const float q[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    for (int k = 0; k < 6; k++) {
        float u = q[k][0], v = q[k][1];
        rayglTexCoord3f(1 - 1.6f * u, 0.8f * v - 0.4f, 0.2f + 0.9f * u);
        rayglVertex3f(0.5f + 1.4f * u, -1 + 2 * v, 0);
    }
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
