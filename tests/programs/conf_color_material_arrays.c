/* conf_color_material_arrays.c: GL_COLOR_MATERIAL fed by a colour array.
 * A lit grid of quads drawn with glDrawArrays from vertex, normal and
 * colour arrays under GL_COLOR_MATERIAL (GL_AMBIENT_AND_DIFFUSE): each
 * vertex's colour array entry is its material. Beside it the same grid
 * with GL_COLOR_MATERIAL off (the material's own colour, the array
 * ignored by lighting). Directional light, local viewer. */
#include "lit_scene.h"

#define N 16

static GLfloat pos[2][N * N * 4][3], nor[2][N * N * 4][3], col[2][N * N * 4][3];

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat white[4] = {1, 1, 1, 1}, dir[4] = {0.3f, 0.6f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glEnable(GL_LIGHT0);
    for (int g = 0; g < 2; g++) {
        int k = 0;
        for (int j = 0; j < N; j++)
            for (int i = 0; i < N; i++) {
                static const int ci[4] = {0, 1, 1, 0}, cj[4] = {0, 0, 1, 1};
                for (int c = 0; c < 4; c++, k++) {
                    float u = (float)(i + ci[c]) / N, v = (float)(j + cj[c]) / N;
                    pos[g][k][0] = (g ? 0.15f : -2.15f) + 2.0f * u;
                    pos[g][k][1] = -1.0f + 2.0f * v;
                    pos[g][k][2] = -5.0f - 0.6f * u;
                    nor[g][k][0] = 0.3f * (u - 0.5f);
                    nor[g][k][1] = 0.3f * (v - 0.5f);
                    nor[g][k][2] = 1.0f;
                    col[g][k][0] = 0.2f + 0.7f * u;
                    col[g][k][1] = 0.8f - 0.5f * v;
                    col[g][k][2] = 0.3f + 0.4f * u * v;
                }
            }
    }
    lit_material(0.5f, 0.5f, 0.5f, 0.0f, 1.0f);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glVertexPointer(3, GL_FLOAT, 0, pos[0]);
    glNormalPointer(GL_FLOAT, 0, nor[0]);
    glColorPointer(3, GL_FLOAT, 0, col[0]);
    glDrawArrays(GL_QUADS, 0, N * N * 4);
    glDisable(GL_COLOR_MATERIAL);
    lit_material(0.5f, 0.5f, 0.5f, 0.0f, 1.0f);
    glVertexPointer(3, GL_FLOAT, 0, pos[1]);
    glNormalPointer(GL_FLOAT, 0, nor[1]);
    glColorPointer(3, GL_FLOAT, 0, col[1]);
    glDrawArrays(GL_QUADS, 0, N * N * 4);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    return 0;
}

RGL_TEST_MAIN(draw)
