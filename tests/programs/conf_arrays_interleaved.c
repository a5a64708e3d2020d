/* conf_arrays_interleaved.c: glInterleavedArrays formats and strides. Rows
 * of rectangles drawn from GL_V2F (the current colour), GL_V3F,
 * GL_C4UB_V2F, GL_C4UB_V3F, GL_C3F_V3F and GL_T2F_C3F_V3F (texturing off:
 * the coordinates unused) arrays, each also with a stride of its own
 * (a struct with padding); then separate pointers into one struct array
 * with GL_SHORT positions and GL_FLOAT colours, and a GL_DOUBLE position
 * array. Unlit, window pixels. */
#include "harness.h"

#include <string.h>
#include <raygl/gl.h>

#include "conf.h"

static void corners(float x0, float y0, float v[4][2])
{
    const float xs[4] = {x0, x0 + 40, x0 + 40, x0}, ys[4] = {y0, y0, y0 + 28, y0 + 28};
    for (int k = 0; k < 4; k++) {
        v[k][0] = xs[k] + 0.25f;
        v[k][1] = ys[k] + 0.25f;
    }
}

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.12f);
    float v[4][2];

    struct { GLfloat x, y; } v2f[4];
    corners(6, 200, v);
    memcpy(v2f, v, sizeof v2f);
    glColor3f(0.8f, 0.8f, 0.3f);
    glInterleavedArrays(GL_V2F, 0, v2f);
    glDrawArrays(GL_QUADS, 0, 4);

    struct { GLfloat x, y, z; GLfloat pad; } v3f[4];
    corners(56, 200, v);
    for (int k = 0; k < 4; k++) {
        v3f[k].x = v[k][0], v3f[k].y = v[k][1], v3f[k].z = 0.0f, v3f[k].pad = -1.0f;
    }
    glColor3f(0.3f, 0.8f, 0.8f);
    glInterleavedArrays(GL_V3F, sizeof v3f[0], v3f);
    glDrawArrays(GL_QUADS, 0, 4);

    struct { GLubyte c[4]; GLfloat x, y; } c4ub_v2f[4];
    corners(106, 200, v);
    for (int k = 0; k < 4; k++) {
        c4ub_v2f[k].c[0] = (GLubyte)(50 + 60 * k), c4ub_v2f[k].c[1] = 90, c4ub_v2f[k].c[2] = 200,
        c4ub_v2f[k].c[3] = 255;
        c4ub_v2f[k].x = v[k][0], c4ub_v2f[k].y = v[k][1];
    }
    glInterleavedArrays(GL_C4UB_V2F, 0, c4ub_v2f);
    glDrawArrays(GL_QUADS, 0, 4);

    struct { GLubyte c[4]; GLfloat x, y, z; GLfloat pad[2]; } c4ub_v3f[4];
    corners(156, 200, v);
    for (int k = 0; k < 4; k++) {
        c4ub_v3f[k].c[0] = 200, c4ub_v3f[k].c[1] = (GLubyte)(40 + 50 * k), c4ub_v3f[k].c[2] = 60,
        c4ub_v3f[k].c[3] = 255;
        c4ub_v3f[k].x = v[k][0], c4ub_v3f[k].y = v[k][1], c4ub_v3f[k].z = 0.2f;
        c4ub_v3f[k].pad[0] = c4ub_v3f[k].pad[1] = 9.0f;
    }
    glInterleavedArrays(GL_C4UB_V3F, sizeof c4ub_v3f[0], c4ub_v3f);
    glDrawArrays(GL_QUADS, 0, 4);

    struct { GLfloat c[3]; GLfloat x, y, z; } c3f_v3f[4];
    corners(206, 200, v);
    for (int k = 0; k < 4; k++) {
        c3f_v3f[k].c[0] = 0.2f + 0.2f * (float)k, c3f_v3f[k].c[1] = 0.8f, c3f_v3f[k].c[2] = 0.4f;
        c3f_v3f[k].x = v[k][0], c3f_v3f[k].y = v[k][1], c3f_v3f[k].z = -0.3f;
    }
    glInterleavedArrays(GL_C3F_V3F, 0, c3f_v3f);
    glDrawArrays(GL_QUADS, 0, 4);

    struct { GLfloat t[2]; GLfloat c[3]; GLfloat x, y, z; } t2f_c3f_v3f[4];
    corners(256, 200, v);
    for (int k = 0; k < 4; k++) {
        t2f_c3f_v3f[k].t[0] = 5.0f, t2f_c3f_v3f[k].t[1] = -3.0f;
        t2f_c3f_v3f[k].c[0] = 0.9f, t2f_c3f_v3f[k].c[1] = 0.3f + 0.15f * (float)k,
        t2f_c3f_v3f[k].c[2] = 0.8f;
        t2f_c3f_v3f[k].x = v[k][0], t2f_c3f_v3f[k].y = v[k][1], t2f_c3f_v3f[k].z = 0.0f;
    }
    glInterleavedArrays(GL_T2F_C3F_V3F, 0, t2f_c3f_v3f);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);

    /* Separate pointers into one array of structs: short positions (in a
     * scaled modelview, so the quarter pixel is kept), float colours. */
    struct { GLshort p[2]; GLfloat c[3]; GLbyte pad; } mixed[8];
    for (int r = 0; r < 2; r++) {
        corners(6 + 50 * (float)r, 120, v);
        for (int k = 0; k < 4; k++) {
            mixed[r * 4 + k].p[0] = (GLshort)(4 * v[k][0]);
            mixed[r * 4 + k].p[1] = (GLshort)(4 * v[k][1]);
            mixed[r * 4 + k].c[0] = 0.3f + 0.5f * (float)r;
            mixed[r * 4 + k].c[1] = 0.2f + 0.2f * (float)k;
            mixed[r * 4 + k].c[2] = 0.9f - 0.5f * (float)r;
            mixed[r * 4 + k].pad = 0;
        }
    }
    glPushMatrix();
    glScalef(0.25f, 0.25f, 1.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_SHORT, sizeof mixed[0], mixed[0].p);
    glColorPointer(3, GL_FLOAT, sizeof mixed[0], mixed[0].c);
    glDrawArrays(GL_QUADS, 0, 8);
    glPopMatrix();
    glDisableClientState(GL_COLOR_ARRAY);

    GLdouble dv[4][3];
    corners(156, 120, v);
    for (int k = 0; k < 4; k++)
        dv[k][0] = v[k][0], dv[k][1] = v[k][1], dv[k][2] = 0.5;
    glColor3f(0.9f, 0.5f, 0.3f);
    glVertexPointer(3, GL_DOUBLE, 0, dv);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_VERTEX_ARRAY);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
