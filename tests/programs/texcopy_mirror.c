/* texcopy_mirror.c: EXT_texture_mirror_clamp. A 4 x 4 texture with
 * GL_MIRROR_CLAMP_TO_EDGE_EXT on s and t over coordinates -1.5..1.5: the
 * image, mirrored once to its left and below, then its edge texels.
 */
#include "harness.h"
#include "texcopy_scene.h"

static int draw(int w, int h)
{
    texcopy_view(w, h);
    unsigned char px[4][4][4];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            px[y][x][0] = (unsigned char)(60 * x + 30);
            px[y][x][1] = (unsigned char)(60 * y + 20);
            px[y][x][2] = (unsigned char)(x == 0 && y == 0 ? 250 : 40);
            px[y][x][3] = 255;
        }
    texcopy_texture(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRROR_CLAMP_TO_EDGE_EXT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_MIRROR_CLAMP_TO_EDGE_EXT);
    glEnable(GL_TEXTURE_2D);
    texcopy_quad(16, 12, 304, 228, -1.5f, -1.5f, 1.5f, 1.5f);
    return 0;
}

RGL_TEST_MAIN(draw)
