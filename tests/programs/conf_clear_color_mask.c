/* conf_clear_color_mask.c: glClear under glColorMask. Rectangles drawn on
 * a grey background, then the colour buffer cleared to another colour
 * with green masked off: every pixel takes the clear colour's red and
 * blue and keeps its own green (the rectangles stay visible as green
 * differences). Then a clear with all channels masked (nothing changes),
 * and a last rectangle drawn unmasked. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.4f, 0.4f, 0.4f);
    glColor3f(0.9f, 0.9f, 0.1f);
    conf_box(20, 30, 150, 200, 0.0f);
    glColor3f(0.1f, 0.2f, 0.9f);
    conf_box(170, 30, 300, 200, 0.0f);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glClearColor(0.8f, 0.0f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glClearColor(0.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glColor3f(0.2f, 0.8f, 0.8f);
    conf_box(100, 90, 220, 140, 0.0f);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
