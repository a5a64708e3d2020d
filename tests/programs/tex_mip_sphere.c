/* tex_mip_sphere.c: a sphere of GL_TRIANGLES with latitude-longitude
 * coordinates (the texture 6 times around), unlit, REPLACE, a fine
 * 64 x 64 texture mipmapped (gluBuild2DMipmaps, GL_LINEAR_MIPMAP_LINEAR):
 * minified most toward the rim, where level 0 alone aliases and GL blends
 * small levels. Each triangle lies on its own plane: the writer takes its
 * level of detail at its centroid (docs/mapping.md section 24).
 * Triangles, not quads, so that GL and POV-Ray split nothing differently. */
#include <math.h>
#include <stdbool.h>

#include "harness.h"
#include "raygl.h"

enum { T = 64 };

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);
    static unsigned char px[T * T * 3];
    for (int y = 0; y < T; y++)
        for (int x = 0; x < T; x++) {
            unsigned char *p = px + (y * T + x) * 3;
            bool fine = (x + y) % 2 == 0, coarse = (x / 8 + y / 8) % 2 == 0;
            p[0] = (unsigned char)(fine ? 230 : 30);
            p[1] = (unsigned char)(coarse ? 210 : 50);
            p[2] = (unsigned char)(coarse ? 60 : 190);
        }
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    raygluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, T, T, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    rayglEnable(GL_TEXTURE_2D);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglOrtho(0, 320, 0, 240, -200, 200);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(160, 120, 0);
    rayglRotatef(30, 1, 0.3f, 0);
    enum { SL = 48, ST = 24 };
    rayglBegin(GL_TRIANGLES);
    for (int j = 0; j < ST; j++)
        for (int i = 0; i < SL; i++) {
            static const int corner[6][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
            for (int k = 0; k < 6; k++) {
                int a = i + corner[k][0], b = j + corner[k][1];
                double lon = 2 * M_PI * a / SL, lat = M_PI * b / ST - M_PI / 2;
                rayglTexCoord2f(6.0f * a / SL, 3.0f * b / ST);
                rayglVertex3f((float)(100 * cos(lat) * sin(lon)), (float)(100 * sin(lat)),
                              (float)(100 * cos(lat) * cos(lon)));
            }
        }
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
