/* lights_cm_arrays.c: GL_COLOR_MATERIAL fed by colour arrays (issue 22):
 * each vertex's colour sets the material term glColorMaterial names, lit
 * per vertex by GL. Top row, glDrawArrays of GL_FRONT GL_DIFFUSE,
 * GL_EMISSION and GL_AMBIENT from a float colour array; the emission
 * quad is lit past white at its corners, where GL clamps each vertex's
 * colour before interpolating (the quad's middle stays below white).
 * Bottom row, GL_AMBIENT_AND_DIFFUSE on both faces: colours from a buffer
 * object, from GL_C4F_N3F_V3F interleaved arrays, and from unsigned bytes
 * through glDrawRangeElements. Flat quads lit by one directional light
 * (lights_conform.h), no specular. */
#define GL_GLEXT_PROTOTYPES 1
#include "lights_conform.h"

#include <GL/glext.h>

static GLfloat quads[6][4][3];

static void vertices(int q)
{
    glVertexPointer(3, GL_FLOAT, 0, quads[q]);
}

static int draw(int w, int h)
{
    conform_begin(w, h);
    static const GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1}, black[4] = {0, 0, 0, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, grey);
    glNormal3f(0, 0, 1);
    for (int q = 0; q < 6; q++)
        for (int k = 0; k < 4; k++)
            conform_corner(k, -2.6f + 1.8f * (q % 3), q < 3 ? 0.3f : -1.3f, 1.0f, quads[q][k]);
    static const GLenum modes[3] = {GL_DIFFUSE, GL_EMISSION, GL_AMBIENT};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_FLOAT, 0, conform_colours);
    for (int q = 0; q < 3; q++) {
        glColorMaterial(GL_FRONT, modes[q]);
        glEnable(GL_COLOR_MATERIAL);
        vertices(q);
        glDrawArrays(GL_QUADS, 0, 4);
        glDisable(GL_COLOR_MATERIAL);
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, grey);
        glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
    }
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    GLuint buf;
    glGenBuffers(1, &buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf);
    glBufferData(GL_ARRAY_BUFFER, sizeof conform_colours, conform_colours, GL_STATIC_DRAW);
    glColorPointer(4, GL_FLOAT, 0, (void *)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    vertices(3);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);

    static GLfloat il[4][10];
    for (int k = 0; k < 4; k++) {
        memcpy(il[k], conform_colours[k], 4 * sizeof(GLfloat));
        il[k][4] = 0, il[k][5] = 0, il[k][6] = 1;
        memcpy(il[k] + 7, quads[4][k], 3 * sizeof(GLfloat));
    }
    glInterleavedArrays(GL_C4F_N3F_V3F, 0, il);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);

    static GLubyte ub[4][4];
    for (int k = 0; k < 4; k++)
        for (int c = 0; c < 4; c++)
            ub[k][c] = (GLubyte)(conform_colours[k][c] * 255 + 0.5f);
    static const GLushort idx[6] = {0, 1, 2, 0, 2, 3};
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    vertices(5);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, ub);
    glDrawRangeElements(GL_TRIANGLES, 0, 3, 6, GL_UNSIGNED_SHORT, idx);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_COLOR_MATERIAL);
    return 0;
}

RGL_TEST_MAIN(draw)
