/* conf_pixel_zoom.c: glDrawPixels under glPixelZoom. One 12 x 8 image drawn
 * at zoom (1, 1), (2, 3), (-1, 1) (mirrored: drawn leftward from the
 * position), (1, -1) (downward), (2/3, 2/3) (shrunk: GL writes the
 * pixels whose centres fall in a source pixel's zoomed rectangle, so one
 * source pixel in three is skipped), (4/3, 5/3) and (-2, -2). Window
 * pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.12f, 0.1f);
    static GLubyte img[8][12][4];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 12; x++) {
            img[y][x][0] = (GLubyte)(30 + 20 * x);
            img[y][x][1] = (GLubyte)(y == 0 ? 255 : 40 + 25 * y);
            img[y][x][2] = (GLubyte)(x == 0 ? 255 : (x + y) % 2 ? 200 : 70);
            img[y][x][3] = 255;
        }
    /* Thirds: from a whole pixel no rectangle edge of theirs passes
     * through a pixel centre (halves would). */
    static const float zoom[7][2] = {{1, 1}, {2, 3}, {-1, 1}, {1, -1},
                                     {2.0f / 3.0f, 2.0f / 3.0f}, {4.0f / 3.0f, 5.0f / 3.0f}, {-2, -2}};
    static const int at[7][2] = {{10, 200}, {40, 170}, {90, 200}, {110, 220},
                                 {140, 200}, {170, 160}, {260, 200}};
    for (int i = 0; i < 7; i++) {
        glRasterPos2i(at[i][0], at[i][1]);
        glPixelZoom(zoom[i][0], zoom[i][1]);
        glDrawPixels(12, 8, GL_RGBA, GL_UNSIGNED_BYTE, img);
    }
    glPixelZoom(1.0f, 1.0f);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
