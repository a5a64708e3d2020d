/* conf_drawpixels_formats.c: glDrawPixels formats, types and unpack
 * state. The same 10 x 6 picture given as GL_RGB, GL_RGBA, GL_BGR,
 * GL_BGRA, GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_RED, GL_GREEN, GL_BLUE
 * (the missing colour channels 0, alpha 1) in GL_UNSIGNED_BYTE; GL_RGB in
 * GL_UNSIGNED_SHORT, GL_FLOAT, GL_BYTE (signed: negatives clamp to 0),
 * GL_UNSIGNED_BYTE_3_3_2 and GL_UNSIGNED_SHORT_5_6_5; and a sub-rectangle
 * picked by GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_PIXELS and
 * GL_UNPACK_SKIP_ROWS under the default alignment of 4 with rows of odd
 * length. Each drawn 3 times magnified (glPixelZoom) at whole pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

#define W 10
#define H 6

static float value(int x, int y, int c)
{
    return c == 0 ? 0.1f + 0.08f * (float)x : c == 1 ? 0.9f - 0.14f * (float)y
         : (x + y) % 2 ? 0.85f : 0.2f;
}

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.15f, 0.15f, 0.18f);
    glPixelZoom(3.0f, 3.0f);
    static GLubyte rgb[H][W][3], rgba[H][W][4], bgr[H][W][3], bgra[H][W][4], lum[H][W],
        luma[H][W][2], one[3][H][W];
    static GLushort rgb16[H][W][3];
    static GLfloat rgbf[H][W][3];
    static GLbyte rgbs[H][W][3];
    static GLubyte p332[H][W];
    static GLushort p565[H][W];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            float v[3] = {value(x, y, 0), value(x, y, 1), value(x, y, 2)};
            for (int c = 0; c < 3; c++) {
                GLubyte b = (GLubyte)(v[c] * 255.0f + 0.5f);
                rgb[y][x][c] = rgba[y][x][c] = b;
                bgr[y][x][2 - c] = bgra[y][x][2 - c] = b;
                one[c][y][x] = b;
                rgb16[y][x][c] = (GLushort)(v[c] * 65535.0f + 0.5f);
                rgbf[y][x][c] = v[c];
                rgbs[y][x][c] = (GLbyte)(c == 1 && x < 3 ? -40 : (int)(v[c] * 127.0f + 0.5f));
            }
            rgba[y][x][3] = bgra[y][x][3] = 255;
            lum[y][x] = (GLubyte)(255.0f * (v[0] + v[1]) / 2.0f);
            luma[y][x][0] = lum[y][x];
            luma[y][x][1] = 255;
            p332[y][x] = (GLubyte)((int)(v[0] * 7.0f + 0.5f) << 5 | (int)(v[1] * 7.0f + 0.5f) << 2 |
                                   (int)(v[2] * 3.0f + 0.5f));
            p565[y][x] = (GLushort)((int)(v[0] * 31.0f + 0.5f) << 11 | (int)(v[1] * 63.0f + 0.5f) << 5 |
                                    (int)(v[2] * 31.0f + 0.5f));
        }
    int px = 8, py = h - 26;
#define NEXT()                 \
    do {                       \
        px += 3 * W + 8;       \
        if (px + 3 * W > w) {  \
            px = 8;            \
            py -= 3 * H + 10;  \
        }                      \
        glRasterPos2i(px, py); \
    } while (0)
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(px, py);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    NEXT();
    glDrawPixels(W, H, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    NEXT();
    glDrawPixels(W, H, GL_BGR, GL_UNSIGNED_BYTE, bgr);
    NEXT();
    glDrawPixels(W, H, GL_BGRA, GL_UNSIGNED_BYTE, bgra);
    NEXT();
    glDrawPixels(W, H, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    NEXT();
    glDrawPixels(W, H, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, luma);
    NEXT();
    glDrawPixels(W, H, GL_RED, GL_UNSIGNED_BYTE, one[0]);
    NEXT();
    glDrawPixels(W, H, GL_GREEN, GL_UNSIGNED_BYTE, one[1]);
    NEXT();
    glDrawPixels(W, H, GL_BLUE, GL_UNSIGNED_BYTE, one[2]);
    NEXT();
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_SHORT, rgb16);
    NEXT();
    glDrawPixels(W, H, GL_RGB, GL_FLOAT, rgbf);
    NEXT();
    glDrawPixels(W, H, GL_RGB, GL_BYTE, rgbs);
    NEXT();
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_BYTE_3_3_2, p332);
    NEXT();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glDrawPixels(W, H, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p565);
    NEXT();
    /* Columns 3..8 of rows 2..5 of the RGB picture, rows of 10 pixels
     * (30 bytes: with alignment 4 GL would pad them to 32, so the picture
     * is repacked with that padding). */
    static GLubyte padded[H][32];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W * 3; x++)
            padded[y][x] = rgb[y][x / 3][x % 3];
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, W);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    glDrawPixels(6, 4, GL_RGB, GL_UNSIGNED_BYTE, padded);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
#undef NEXT
    glPixelZoom(1.0f, 1.0f);
    return 0;
}

RGL_TEST_MAIN(draw)
