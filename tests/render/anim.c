/* anim.c: the animated test trace (anim.h). */
#include "anim.h"

#include <GL/gl.h>

static void quad(seq *s, const double c[3], double v[4][3])
{
    CMD(s, Color3f, c[0], c[1], c[2]);
    for (int i = 0; i < 4; i++)
        CMD(s, Vertex3f, v[i][0], v[i][1], v[i][2]);
}

void anim_frame(seq *s, int i, int n, int w, int h)
{
    static const double p[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                   {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int f[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6},
                                {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    static const double col[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                     {1, 1, 0}, {1, 0, 1}, {0, 1, 1}};
    CMD(s, Viewport, 0, 0, w, h);
    CMD(s, MatrixMode, GL_PROJECTION);
    CMD0(s, LoadIdentity);
    CMD(s, Perspective, ANIM_FOVY, (double)w / h, 0.5, 50);
    CMD(s, MatrixMode, GL_MODELVIEW);
    CMD0(s, LoadIdentity);
    CMD(s, LookAt, ANIM_EYE, 0, 0, 0, 0, 1, 0);
    CMD(s, Enable, GL_DEPTH_TEST);
    CMD(s, ClearColor, 0.15, 0.15, 0.25, 1);
    CMD(s, Clear, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    CMD(s, Begin, GL_QUADS);
    for (int x = -4; x < 4; x++)
        for (int z = -4; z < 4; z++) {
            double g = ((x + z) & 1) ? 0.85 : 0.35, c[3] = {g, g, g};
            double v[4][3] = {{x, -1, z}, {x, -1, z + 1}, {x + 1, -1, z + 1}, {x + 1, -1, z}};
            quad(s, c, v);
        }
    CMD0(s, End);
    CMD(s, Rotatef, 360.0 * i / n, 0.3, 1, 0.2);
    CMD(s, Begin, GL_QUADS);
    for (int k = 0; k < 6; k++) {
        double v[4][3];
        for (int m = 0; m < 4; m++)
            for (int c = 0; c < 3; c++)
                v[m][c] = p[f[k][m]][c] * 0.8;
        quad(s, col[k], v);
    }
    CMD0(s, End);
}
