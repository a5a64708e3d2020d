/* pixels_bitmap_odd.c: bitmap text as bitmap-font programs draw it: 8x13
 * glyphs with glBitmap at raster positions that are not whole pixels
 * (glRasterPos2f at x.3, x.5, x.7), fractional origins and advances, and
 * a raster position set in perspective (a label on a 3D point). GL puts
 * the bitmap's lower left at floor(raster position - origin) (GL 2.1
 * 3.7) and moves the raster position by the advance unrounded. */
#include "harness.h"

#include <raygl/gl.h>

static const GLubyte glyph[4][13] = {
    {0x00, 0x00, 0xc3, 0xc3, 0xc3, 0xff, 0xc3, 0xc3, 0x66, 0x3c, 0x18, 0x00, 0x00},
    {0x00, 0x00, 0xfe, 0xc3, 0xc3, 0xc3, 0xfe, 0xc3, 0xc3, 0xc3, 0xfe, 0x00, 0x00},
    {0x00, 0x00, 0x3c, 0x66, 0xc0, 0xc0, 0xc0, 0xc0, 0xc0, 0x66, 0x3c, 0x00, 0x00},
    {0x00, 0x00, 0xff, 0x18, 0x18, 0x18, 0x18, 0x18, 0x18, 0x18, 0xff, 0x00, 0x00},
};

static void label(const char *s, float xorig, float xmove)
{
    for (; *s; s++)
        glBitmap(8, 13, xorig, 2.5f, xmove, 0, glyph[(*s - 'A') % 4]);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.1f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    static const float sub[6] = {0, 0.3f, 0.5f, 0.7f, 0.999f, 0.25f};
    for (int i = 0; i < 6; i++) {
        glColor3f(1, 1.0f - 0.1f * (float)i, 0.3f);
        glRasterPos2f(10.0f + sub[i], 200.0f - 18.0f * (float)i + sub[5 - i]);
        label("ABCDABCD", i % 2 ? 0.5f : 0, 8.6f + 0.1f * (float)i);
    }

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 30);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.3f, -0.2f, -4);
    glRotatef(25, 0, 1, 0);
    for (int i = 0; i < 5; i++) {
        glColor3f(0.4f, 1, 1);
        glRasterPos3f(0.37f * (float)i, 0.21f * (float)i, -0.3f * (float)i);
        label("DCBA", 0, 9);
    }
    return 0;
}

RGL_TEST_MAIN(draw)
