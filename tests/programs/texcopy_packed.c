/* texcopy_packed.c: packed pixel types (GL 1.2). Four 4 x 4 textures, one
 * per quad: GL_UNSIGNED_SHORT_5_6_5 (GL_RGB), GL_UNSIGNED_SHORT_4_4_4_4
 * (GL_RGBA), GL_UNSIGNED_INT_8_8_8_8_REV (GL_BGRA) and
 * GL_UNSIGNED_SHORT_1_5_5_5_REV (GL_BGRA), each texel a colour of its own.
 */
#include "harness.h"
#include "texcopy_scene.h"

static int draw(int w, int h)
{
    texcopy_view(w, h);
    GLushort p565[16], p4444[16], p1555[16];
    GLuint p8888[16];
    for (int i = 0; i < 16; i++) {
        unsigned r = (unsigned)(i * 5 + 3) % 16, g = (unsigned)(i * 7 + 1) % 16,
                 b = (unsigned)(15 - i);
        p565[i] = (GLushort)(r * 2 << 11 | g * 4 << 5 | b * 2);
        p4444[i] = (GLushort)(r << 12 | g << 8 | b << 4 | 15);
        /* BGRA, _REV: blue in the lowest bits, alpha in the highest. */
        p8888[i] = (GLuint)(b * 17) | (GLuint)(g * 17) << 8 | (GLuint)(r * 17) << 16 | 255u << 24;
        p1555[i] = (GLushort)(b * 2 | g * 2 << 5 | r * 2 << 10 | 1u << 15);
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glEnable(GL_TEXTURE_2D);
    texcopy_texture(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p565);
    texcopy_quad(10, 10, 150, 110, 0, 0, 1, 1);
    texcopy_texture(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, p4444);
    texcopy_quad(170, 10, 310, 110, 0, 0, 1, 1);
    texcopy_texture(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, p8888);
    texcopy_quad(10, 130, 150, 230, 0, 0, 1, 1);
    texcopy_texture(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV,
                 p1555);
    texcopy_quad(170, 130, 310, 230, 0, 0, 1, 1);
    return 0;
}

RGL_TEST_MAIN(draw)
