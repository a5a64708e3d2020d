/* fogsec_arrays.c: fog coordinates and secondary colours from client
 * arrays (glFogCoordPointer, glSecondaryColorPointer, GL 1.4), unlit
 * (issue 13).
 *
 * A grid of quads under gluPerspective drawn with glDrawArrays: each
 * quad one primary colour, its fog coordinates (GL_LINEAR fog, within
 * GL_FOG_START..GL_FOG_END) from a float array, rising from left to
 * right; then a fan of triangles with GL_COLOR_SUM whose secondary
 * colours come from an unsigned-byte array and whose element indices go
 * through glDrawElements.
 */
#include "harness.h"

#include <raygl/gl.h>

#define COLS 12
#define ROWS 6

static GLfloat grid_v[ROWS * COLS * 4][3];
static GLfloat grid_c[ROWS * COLS * 4][3];
static GLfloat grid_f[ROWS * COLS * 4];

static int draw(int w, int h)
{
    int n = 0;
    for (int j = 0; j < ROWS; j++)
        for (int i = 0; i < COLS; i++) {
            static const int corner[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
            for (int k = 0; k < 4; k++, n++) {
                float x = -6.0f + (float)(i + corner[k][0]);
                float z = -3.0f - 2.5f * (float)(j + corner[k][1]);
                grid_v[n][0] = x;
                grid_v[n][1] = -1.5f;
                grid_v[n][2] = z;
                int odd = (i + j) % 2;
                grid_c[n][0] = odd ? 0.8f : 0.2f;
                grid_c[n][1] = odd ? 0.5f : 0.4f;
                grid_c[n][2] = odd ? 0.2f : 0.7f;
                grid_f[n] = 0.8f * (float)(i + corner[k][0]); /* 0 .. 9.6 */
            }
        }
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / (double)h, 1.0, 60.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.05f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    GLfloat fogc[4] = {0.85f, 0.85f, 0.8f, 1.0f};
    glFogfv(GL_FOG_COLOR, fogc);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, 0.0f);
    glFogf(GL_FOG_END, 10.0f);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glEnable(GL_FOG);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, grid_v);
    glColorPointer(3, GL_FLOAT, 0, grid_c);
    glFogCoordPointer(GL_FLOAT, 0, grid_f);
    glDrawArrays(GL_QUADS, 0, n);
    glDisableClientState(GL_FOG_COORD_ARRAY);
    glDisable(GL_FOG);

    /* The colour sum from an array of secondary colours. */
    static const GLfloat fan_v[6][3] = {{0.0f, 0.6f, -5.0f}, {-1.6f, 0.0f, -5.0f},
                                        {-0.8f, 1.7f, -5.0f}, {0.8f, 1.7f, -5.0f},
                                        {1.6f, 0.0f, -5.0f}, {0.0f, -0.2f, -5.0f}};
    static const GLfloat fan_c[6][3] = {{0.2f, 0.2f, 0.2f}, {0.5f, 0.1f, 0.1f}, {0.1f, 0.5f, 0.1f},
                                        {0.1f, 0.1f, 0.5f}, {0.4f, 0.4f, 0.0f}, {0.0f, 0.3f, 0.3f}};
    static const GLubyte fan_s[6][3] = {{50, 50, 50}, {0, 200, 0}, {200, 0, 100},
                                        {120, 120, 0}, {0, 0, 220}, {240, 100, 30}};
    static const GLushort fan_i[7] = {0, 1, 2, 3, 4, 5, 1};
    glEnable(GL_COLOR_SUM);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, fan_v);
    glColorPointer(3, GL_FLOAT, 0, fan_c);
    glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, fan_s);
    glDrawElements(GL_TRIANGLE_FAN, 7, GL_UNSIGNED_SHORT, fan_i);
    glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_COLOR_SUM);
    return 0;
}

RGL_TEST_MAIN(draw)
