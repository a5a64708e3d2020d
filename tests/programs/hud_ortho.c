/* hud_ortho.c: a HUD of bitmap text over an orthographic scene (issue
 * 27). glOrtho with the near plane behind the eye, unlit quads at three
 * depths in front of it, then two lines of text from a hand-made 5 x 7
 * font with glBitmap under a window-pixel projection, depth test off, as
 * a CAD viewer or a 2D game draws its status line. The tests translate it
 * with --camera-orthographic --camera-location 0,0,0 (the same view from
 * the eye, without GL's clipping planes: the HUD was placed on the camera
 * plane, where POV-Ray meets nothing) and with --quality 4 (POV-Ray
 * computes no image maps below quality 6: the frame was black). */
#include "harness.h"

#include <raygl/gl.h>

/* Rows bottom first, bit 7 the leftmost pixel, as glBitmap reads them. */
static const GLubyte font[][7] = {
    {0x88, 0x88, 0xf8, 0x88, 0x88, 0x50, 0x20}, /* A */
    {0xf0, 0x88, 0x88, 0xf0, 0x88, 0x88, 0xf0}, /* B */
    {0x70, 0x88, 0x80, 0x80, 0x80, 0x88, 0x70}, /* C */
};

static void text(const char *s)
{
    for (; *s; s++)
        glBitmap(5, 7, 0.0f, 0.0f, 7.0f, 0.0f, font[*s - 'A']);
}

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

static int draw(int w, int h)
{
    double a = (double)w / (double)h;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-2.0 * a, 2.0 * a, -2.0, 2.0, -5.0, 5.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.15f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    /* Off the pixel grid by a fraction, so no edge lies on a pixel edge. */
    glColor3f(0.8f, 0.3f, 0.2f);
    quad(-2.013f, -1.213f, 0.413f, 1.013f, -1.0f);
    glColor3f(0.2f, 0.7f, 0.3f);
    quad(-0.813f, -1.613f, 1.613f, 0.613f, -2.0f);
    glColor3f(0.9f, 0.8f, 0.3f);
    quad(0.213f, -0.413f, 2.413f, 1.613f, -0.5f);

    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(1.0f, 1.0f, 1.0f);
    /* Off whole pixels: GL floors the raster position. */
    glRasterPos2f(10.3f, (float)h - 19.7f);
    text("ABCABCCBA");
    glColor3f(1.0f, 0.9f, 0.2f);
    glRasterPos2f((float)(w / 2) + 0.3f, 12.3f);
    text("CABBAC");
    return 0;
}

RGL_TEST_MAIN(draw)
