/* texcopy_tex3d.c: 3D textures (GL 1.2) on quads of constant r. A 4 x 4 x 4
 * texture, each slice its own pattern, drawn with GL_NEAREST at r = 0.3
 * (slice 1) and r = 0.85 (slice 3); a 1 x 1 x 4 texture with GL_LINEAR at
 * r = 0.5, halfway between its slices 1 and 2 (a blend of the two), and at
 * r = 0.45 (45% / 55%).
 */
#include "harness.h"
#include "texcopy_scene.h"

/* A quad with texture coordinates (0..1, 0..1, r). */
static void quad3(float x0, float y0, float x1, float y1, float r)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, r);
    glVertex2f(x0, y0);
    glTexCoord3f(1, 0, r);
    glVertex2f(x1, y0);
    glTexCoord3f(1, 1, r);
    glVertex2f(x1, y1);
    glTexCoord3f(0, 1, r);
    glVertex2f(x0, y1);
    glEnd();
}

static int draw(int w, int h)
{
    texcopy_view(w, h);
    unsigned char vox[4][4][4][3];
    for (int z = 0; z < 4; z++)
        for (int y = 0; y < 4; y++)
            for (int x = 0; x < 4; x++) {
                int on = (x + y + z) % 2 == 0;
                vox[z][y][x][0] = (unsigned char)(on ? 60 * z + 40 : 20);
                vox[z][y][x][1] = (unsigned char)(on ? 200 - 40 * z : 30 * x);
                vox[z][y][x][2] = (unsigned char)(on ? 50 * y + 30 : 240 - 50 * z);
            }
    static const unsigned char ramp[4][3] = {{250, 20, 20}, {20, 200, 40}, {40, 60, 230},
                                             {230, 220, 30}};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    texcopy_texture(GL_TEXTURE_3D);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 4, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, vox);
    glEnable(GL_TEXTURE_3D);
    quad3(10, 20, 150, 120, 0.3f);
    quad3(170, 20, 310, 120, 0.85f);
    texcopy_texture(GL_TEXTURE_3D);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 1, 1, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, ramp);
    quad3(10, 140, 150, 220, 0.5f);
    glTexCoord3f(0, 0, 0.45f); /* one current r for every vertex */
    glBegin(GL_QUADS);
    glVertex2f(170, 140);
    glVertex2f(310, 140);
    glVertex2f(310, 220);
    glVertex2f(170, 220);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
