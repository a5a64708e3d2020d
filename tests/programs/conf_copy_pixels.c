/* conf_copy_pixels.c: glCopyPixels right after drawing. Coloured
 * rectangles drawn, then a region holding parts of them copied to another
 * place with glRasterPos (the copy shows what was drawn just before it),
 * and a second copy of a region that includes the first copy. Unlit,
 * window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.12f);
    glColor3f(0.9f, 0.3f, 0.2f);
    conf_box(10, 130, 80, 220, 0.0f);
    glColor3f(0.2f, 0.8f, 0.3f);
    conf_box(50, 150, 130, 200, 0.0f);
    glColor3f(0.3f, 0.4f, 0.9f);
    conf_box(20, 140, 60, 170, 0.0f);
    glRasterPos2i(170, 130);
    glCopyPixels(10, 130, 120, 90, GL_COLOR);
    glRasterPos2i(100, 10);
    glCopyPixels(150, 120, 160, 100, GL_COLOR);
    (void)w;
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
