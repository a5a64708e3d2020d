/* conf_rasterpos_invalid.c: the raster position's validity. glRasterPos
 * of a point outside the view volume makes the position invalid: the
 * glBitmap and glDrawPixels after it draw nothing and glBitmap's move is
 * not applied, until a glRasterPos inside the volume. A position moved out
 * of the window by glBitmap's own move stays valid: glyphs moved back in
 * are drawn. glWindowPos is always valid, also outside the window: an
 * image placed partly left of it shows its right part. Over a plain
 * background. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static const GLubyte glyph[8] = {0xff, 0xc3, 0xa5, 0x99, 0x99, 0xa5, 0xc3, 0xff};

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.12f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    static GLubyte img[16][24][3];
    for (int y = 0; y < 16; y++)
        for (int x = 0; x < 24; x++) {
            img[y][x][0] = (GLubyte)(60 + 8 * x);
            img[y][x][1] = (GLubyte)(40 + 12 * y);
            img[y][x][2] = 150;
        }
    glColor3f(1.0f, 0.8f, 0.2f);
    glRasterPos2i(20, 200);
    glBitmap(8, 8, 0, 0, 12, 0, glyph);
    glRasterPos3f(60.0f, 200.0f, 5.0f); /* beyond the near plane: invalid */
    glBitmap(8, 8, 0, 0, 12, 0, glyph);
    glBitmap(8, 8, 0, 0, 12, 0, glyph);
    glDrawPixels(24, 16, GL_RGB, GL_UNSIGNED_BYTE, img);
    glRasterPos2i(-5, 160); /* left of the window: invalid */
    glBitmap(8, 8, 0, 0, 30, 0, glyph);
    glRasterPos2i(100, 200); /* valid again */
    glBitmap(8, 8, 0, 0, 12, 0, glyph);
    glDrawPixels(24, 16, GL_RGB, GL_UNSIGNED_BYTE, img);

    glColor3f(0.3f, 1.0f, 0.6f);
    glRasterPos2i(290, 120);
    for (int i = 0; i < 4; i++)
        glBitmap(8, 8, 0, 0, 20, 0, glyph); /* the last two land past the right edge */
    glBitmap(0, 0, 0, 0, -100, -20, NULL);  /* back in: still valid */
    for (int i = 0; i < 3; i++)
        glBitmap(8, 8, 0, 0, 12, 0, glyph);

    glWindowPos2i(-10, 40);
    glDrawPixels(24, 16, GL_RGB, GL_UNSIGNED_BYTE, img);
    glWindowPos2i(w - 12, 60);
    glDrawPixels(24, 16, GL_RGB, GL_UNSIGNED_BYTE, img);
    glColor3f(0.9f, 0.3f, 0.9f);
    glWindowPos2i(-4, 90);
    glBitmap(8, 8, 0, 0, 0, 0, glyph);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
