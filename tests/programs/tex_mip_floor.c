/* tex_mip_floor.c: a receding textured floor, mipmapped (issue 14): a
 * 64 x 64 texture of fine stripes and checks (1 and 4 texels) built with
 * gluBuild2DMipmaps, GL_LINEAR_MIPMAP_LINEAR, repeated 12 times over a
 * floor seen at a grazing angle in perspective. GL's far floor is the
 * smooth grey of the small levels; level 0 alone aliases into noise. */
#include <stdbool.h>

#include "harness.h"
#include "raygl.h"

enum { T = 64 };

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.3f, 0.4f, 0.6f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(50, (double)w / h, 0.5, 200);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    raygluLookAt(0, 1.5, 6, 0, 0.4, -10, 0, 1, 0);
    rayglEnable(GL_DEPTH_TEST);
    static unsigned char px[T * T * 3];
    for (int y = 0; y < T; y++)
        for (int x = 0; x < T; x++) {
            unsigned char *p = px + (y * T + x) * 3;
            bool fine = (x + y) % 2 == 0, coarse = (x / 4 + y / 4) % 2 == 0;
            p[0] = (unsigned char)(fine ? 240 : 20);
            p[1] = (unsigned char)(coarse ? 200 : 60);
            p[2] = (unsigned char)(x % 2 ? 180 : 40);
        }
    GLuint name;
    rayglGenTextures(1, &name);
    rayglBindTexture(GL_TEXTURE_2D, name);
    raygluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, T, T, GL_RGB, GL_UNSIGNED_BYTE, px);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    rayglEnable(GL_TEXTURE_2D);
    rayglBegin(GL_QUADS);
    rayglTexCoord2f(0, 0);
    rayglVertex3f(-20, 0, 8);
    rayglTexCoord2f(12, 0);
    rayglVertex3f(20, 0, 8);
    rayglTexCoord2f(12, 12);
    rayglVertex3f(20, 0, -60);
    rayglTexCoord2f(0, 12);
    rayglVertex3f(-20, 0, -60);
    rayglEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
