/* texcopy_rect.c: a rectangle texture (ARB_texture_rectangle): 6 x 5
 * texels, not a power of two, addressed in texels (s 0..6, t 0..5), with
 * GL_CLAMP_TO_EDGE past its edges on the second quad (s -2..8).
 */
#include "harness.h"
#include "texcopy_scene.h"

static int draw(int w, int h)
{
    texcopy_view(w, h);
    unsigned char px[5][6][3];
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 6; x++) {
            px[y][x][0] = (unsigned char)(40 * x + 20);
            px[y][x][1] = (unsigned char)(50 * y + 10);
            px[y][x][2] = (unsigned char)((x + y) % 2 ? 220 : 60);
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    texcopy_texture(GL_TEXTURE_RECTANGLE_ARB);
    glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGB, 6, 5, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    glTexParameteri(GL_TEXTURE_RECTANGLE_ARB, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glEnable(GL_TEXTURE_RECTANGLE_ARB);
    texcopy_quad(10, 20, 154, 200, 0, 0, 6, 5);
    texcopy_quad(166, 20, 310, 200, -2, 0, 8, 5);
    return 0;
}

RGL_TEST_MAIN(draw)
