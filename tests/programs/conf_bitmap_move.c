/* conf_bitmap_move.c: glBitmap's moves and origin. A row of 8 x 8 glyphs
 * with xmove 10 (the raster position advances after each), then ymove -12
 * with xmove 0 (a column), a negative xmove (right to left), fractional
 * moves of (5.5, 0.75) (GL draws each glyph at the floor of its raster
 * position less its origin, so they step 5 or 6 pixels and climb a pixel
 * every few), a glyph with its origin (xorig, yorig) set, a NULL bitmap of
 * size 0 that only moves the position, and the colour: taken at
 * glRasterPos, so a glColor after it does not change the glyphs until the
 * next glRasterPos. Over a plain background; the raster positions a
 * quarter pixel off the grid (conf_bitmap_integer: on it). */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static const GLubyte glyph[8] = {0xff, 0x81, 0xbd, 0xa5, 0xa5, 0xbd, 0x81, 0xff};
static const GLubyte arrow[8] = {0x18, 0x18, 0x18, 0x18, 0xff, 0x7e, 0x3c, 0x18};

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.12f, 0.12f, 0.16f);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(1.0f, 0.9f, 0.3f);
    glRasterPos2f(10.25f, 210.25f);
    for (int i = 0; i < 8; i++)
        glBitmap(8, 8, 0, 0, 10, 0, glyph);
    glColor3f(0.3f, 1.0f, 0.5f);
    glRasterPos2f(10.25f, 190.25f);
    for (int i = 0; i < 6; i++)
        glBitmap(8, 8, 0, 0, 0, -12, arrow);
    glColor3f(0.9f, 0.4f, 0.9f);
    glRasterPos2f(300.25f, 190.25f);
    for (int i = 0; i < 8; i++)
        glBitmap(8, 8, 0, 0, -14, 0, glyph);
    glColor3f(0.4f, 0.8f, 1.0f);
    glRasterPos2f(40.75f, 150.25f);
    for (int i = 0; i < 12; i++)
        glBitmap(8, 8, 0, 0, 5.5f, 0.75f, arrow);
    glColor3f(1.0f, 0.5f, 0.2f);
    glRasterPos2f(80.25f, 60.25f);
    glBitmap(8, 8, 4.0f, 4.0f, 0, 0, glyph); /* origin in its middle: drawn from 76, 56 */
    glBitmap(0, 0, 0, 0, 40, 10, NULL);    /* only moves */
    glBitmap(8, 8, 0, 0, 0, 0, glyph);     /* from 120, 70 */
    glRasterPos2f(160.25f, 60.25f);
    glColor3f(0.0f, 0.0f, 1.0f); /* after the position: the glyphs stay orange */
    for (int i = 0; i < 5; i++)
        glBitmap(8, 8, 0, 0, 9, 0, glyph);
    glRasterPos2f(160.25f, 40.25f); /* now blue */
    for (int i = 0; i < 5; i++)
        glBitmap(8, 8, 0, 0, 9, 0, glyph);
    (void)w;
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
