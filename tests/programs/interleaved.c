/* interleaved.c: glInterleavedArrays with each of its 14 formats, in a
 * grid, written with the raygl* API.
 *
 * Each cell draws a fan of 6 vertices from one interleaved block in its
 * format: colours where the format has them (C4UB, C3F, C4F), positions of
 * 2, 3 or 4 components (V4F with w = 1 and w = 2), normals and texture
 * coordinates where it has them (unlit and untextured: no effect, but the
 * offsets of everything after them must be right). Odd cells use an
 * explicit stride with padding after each vertex.
 */
#include "harness.h"

#include <string.h>

#include "raygl.h"

typedef struct fmt {
    GLenum format;
    int t, c, n, v; /* floats of texcoord, colour (0 or 3, 4 floats; -1: 4 ubytes), normal, vertex */
} fmt;

static const fmt formats[14] = {
    {GL_V2F, 0, 0, 0, 2},
    {GL_V3F, 0, 0, 0, 3},
    {GL_C4UB_V2F, 0, -1, 0, 2},
    {GL_C4UB_V3F, 0, -1, 0, 3},
    {GL_C3F_V3F, 0, 3, 0, 3},
    {GL_N3F_V3F, 0, 0, 3, 3},
    {GL_C4F_N3F_V3F, 0, 4, 3, 3},
    {GL_T2F_V3F, 2, 0, 0, 3},
    {GL_T4F_V4F, 4, 0, 0, 4},
    {GL_T2F_C4UB_V3F, 2, -1, 0, 3},
    {GL_T2F_C3F_V3F, 2, 3, 0, 3},
    {GL_T2F_N3F_V3F, 2, 0, 3, 3},
    {GL_T2F_C4F_N3F_V3F, 2, 4, 3, 3},
    {GL_T4F_C4F_N3F_V4F, 4, 4, 3, 4},
};

static unsigned char block[6 * 128];

static void put_f(unsigned char **p, float v)
{
    memcpy(*p, &v, sizeof v);
    *p += sizeof v;
}

static int draw(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglOrtho(0, 320, 0, 240, -1, 1);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.21f, 0.43f, 0.0f);
    rayglClearColor(0.1f, 0.1f, 0.1f, 0.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);

    static const float fx[6] = {0, 28, 34, 18, -2, -6}, fy[6] = {0, -4, 20, 34, 26, 12};
    for (int k = 0; k < 14; k++) {
        const fmt *f = &formats[k];
        int pad = k % 2 ? 12 : 0;
        float cx = 20.0f + 60.0f * (float)(k % 5), cy = 170.0f - 70.0f * (float)(k / 5);
        unsigned char *p = block;
        size_t vsize = 0;
        for (int i = 0; i < 6; i++) {
            unsigned char *start = p;
            float r = (float)((i * 40 + k * 17) % 256) / 255.0f;
            float g = (float)((i * 90 + k * 31) % 256) / 255.0f;
            float b = (float)((255 - i * 30 - k * 11 + 512) % 256) / 255.0f;
            for (int t = 0; t < f->t; t++)
                put_f(&p, 0.25f * (float)t);
            if (f->c == -1) {
                *p++ = (unsigned char)(r * 255);
                *p++ = (unsigned char)(g * 255);
                *p++ = (unsigned char)(b * 255);
                *p++ = 255;
            } else if (f->c >= 3) {
                put_f(&p, r);
                put_f(&p, g);
                put_f(&p, b);
                if (f->c == 4)
                    put_f(&p, 1);
            }
            for (int n = 0; n < f->n; n++)
                put_f(&p, n == 2 ? 1.0f : 0.0f);
            /* V4F cells put the point at w = 2: coordinates doubled. */
            float s = f->v == 4 && k == 13 ? 2.0f : 1.0f;
            put_f(&p, (cx + fx[i]) * s);
            put_f(&p, (cy + fy[i]) * s);
            if (f->v >= 3)
                put_f(&p, 0);
            if (f->v == 4)
                put_f(&p, s);
            vsize = (size_t)(p - start);
            memset(p, 0xAB, (size_t)pad); /* garbage between vertices */
            p += pad;
        }
        if (f->c == 0)
            rayglColor3f(0.9f, 0.8f - 0.05f * (float)k, 0.2f + 0.05f * (float)k);
        rayglInterleavedArrays(f->format, pad ? (GLsizei)(vsize + (size_t)pad) : 0, block);
        rayglDrawArrays(GL_TRIANGLE_FAN, 0, 6);
    }
    rayglDisableClientState(GL_VERTEX_ARRAY);
    rayglDisableClientState(GL_COLOR_ARRAY);
    rayglDisableClientState(GL_NORMAL_ARRAY);
    rayglDisableClientState(GL_TEXTURE_COORD_ARRAY);
    return 0;
}

RGL_TEST_MAIN(draw)
