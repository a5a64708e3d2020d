/* conf_bitmap_integer.c: bitmaps at whole-pixel raster positions, as text
 * in a HUD is drawn: gluOrtho2D(0, w, 0, h) and glRasterPos2i(x, y) for a
 * row of 8 x 8 glyphs every 10 pixels up the window and across it. GL's
 * window position of (x, y) is x, y up to its float rounding, and the
 * glyph's lower left pixel the floor of that: every row lands on its y
 * (Mesa rounds to it here, up or down, and takes the floor after). Over a
 * plain background. */
#include "harness.h"

#include <raygl/gl.h>

static const GLubyte glyph[8] = {0xff, 0x81, 0xbd, 0xa5, 0xa5, 0xbd, 0x81, 0xff};

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, (double)w, 0.0, (double)h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int y = 2; y + 8 < h; y += 10) {
        glColor3f(0.4f + 0.6f * (float)y / (float)h, 0.9f, 0.5f);
        for (int x = 3 + (y / 10) % 7; x + 8 < w; x += 13) {
            glRasterPos2i(x, y);
            glBitmap(8, 8, 0, 0, 0, 0, glyph);
        }
    }
    return 0;
}

RGL_TEST_MAIN(draw)
