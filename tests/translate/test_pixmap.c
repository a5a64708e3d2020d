/* test_pixmap.c: pixel maps and colour-index pixels (interp_pixmap.c).
 *
 * glPixelMap's three forms fill the maps (integer entries of colour maps
 * normalised), a map GL refuses is refused; a colour index drawn in RGBA
 * takes the I_TO_* maps' entries, the index masked to each map's size;
 * GL_MAP_COLOR of pixel rectangles, and scales and biases of colour-index
 * ones, are noted, and nothing else is (scales and biases of RGBA pixels:
 * Mesa's, not noted).
 */
#include <GL/gl.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "tracegen.h"
#include "wire.h"

static void map_f(seq *s, GLenum map, int n, const float *v)
{
    uint8_t b[256 * 4];
    for (int i = 0; i < n; i++)
        rgl_put_f(b + 4 * i, v[i]);
    seq_cmd_bytes(s, RGL_OP_PixelMapfv, b, (size_t)n * 4, (const double[]){map, n}, 2);
}

static void setup(seq *s)
{
    CMD(s, Viewport, 0, 0, 16, 16);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD(s, Ortho, 0, 16, 0, 16, -1, 1);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT);
    static const float r[4] = {0.1f, 0.4f, 0.6f, 0.9f};
    map_f(s, GL_PIXEL_MAP_I_TO_R, 4, r);
    uint8_t g[2 * 2] = {0, 0, 0xff, 0xff}; /* ushort entries 0, 65535 */
    seq_cmd_bytes(s, RGL_OP_PixelMapusv, g, sizeof g, (const double[]){GL_PIXEL_MAP_I_TO_G, 2}, 2);
    static const float a[1] = {1};
    map_f(s, GL_PIXEL_MAP_I_TO_A, 1, a);
    CMD(s, RasterPos2f, 2.5, 2.5);
}

static void test_index(void)
{
    static const uint8_t idx[2] = {6, 1};
    uint32_t id = add_bytes(idx, sizeof idx);
    for (int c = 0; c < 3; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        setup(&s);
        if (c == 1)
            CMD(&s, PixelTransferi, GL_MAP_COLOR, 1);
        if (c == 2)
            CMD(&s, PixelTransferf, GL_GREEN_BIAS, 0.5);
        CMD(&s, DrawPixels, 2, 1, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, id);
        /* refused: a size not a power of two for an index map; too large */
        map_f(&s, GL_PIXEL_MAP_I_TO_B, 3, (const float[]){1, 1, 1});
        seq_cmd_bytes(&s, RGL_OP_PixelMapfv, NULL, 0, (const double[]){GL_PIXEL_MAP_R_TO_R, 257}, 2);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 2);
        CHECK_EQ_U(count(DIAG_NOTE_PIXELS_MAP_COLOR), c != 0);
        CHECK_EQ_U(count(DIAG_NOTE_PIXELS_OTHER), 0);
        CHECK(sc.overlay != NULL);
        if (sc.overlay && c == 0) {
            /* pixel (2, 2): index 6 & 3 = 2 -> 0.6, & 1 = 0 -> 0; (3, 2): 1 -> 0.4, 1 */
            const uint8_t *p = sc.overlay + (2 * (size_t)sc.overlay_w + 2) * 4;
            CHECK(p[0] == 153 && p[1] == 0 && p[2] == 0 && p[3] == 255);
            CHECK(p[4] == 102 && p[5] == 255 && p[6] == 0);
        }
        interp_destroy(ip);
    }
    free_res();
}

/* RGBA pixels under a scale and a bias: applied once, as Mesa does, and
 * not noted; under GL_MAP_COLOR: noted. */
static void test_rgba_transfer(void)
{
    static const uint8_t rgba[4] = {200, 100, 0, 255};
    uint32_t id = add_bytes(rgba, sizeof rgba);
    for (int c = 0; c < 2; c++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        setup(&s);
        CMD(&s, PixelTransferf, GL_RED_SCALE, 0.5);
        CMD(&s, PixelTransferf, GL_BLUE_BIAS, 0.25);
        if (c == 1)
            CMD(&s, PixelTransferi, GL_MAP_COLOR, 1);
        CMD(&s, DrawPixels, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, id);
        run(ip, &s);
        CHECK_EQ_U(count(DIAG_NOTE_PIXELS_MAP_COLOR), c == 1);
        CHECK(sc.overlay != NULL);
        if (sc.overlay && c == 0) { /* 200 x 0.5, 0 + 0.25 */
            const uint8_t *p = sc.overlay + (2 * (size_t)sc.overlay_w + 2) * 4;
            CHECK(p[0] == 100 && p[1] == 100 && (p[2] == 63 || p[2] == 64) && p[3] == 255);
        }
        interp_destroy(ip);
    }
    free_res();
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_res;
    test_index();
    test_rgba_transfer();
    scene_finish(&sc);
    return CHECK_RESULT("test_pixmap");
}
