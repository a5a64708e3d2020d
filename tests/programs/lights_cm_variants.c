/* lights_cm_variants.c: glColorMaterial as real programs use it, inside
 * display lists and with vertex arrays: (top row) the current colour set
 * before glEnable(GL_COLOR_MATERIAL) in a list and no colour per vertex;
 * unsigned-byte colour arrays of three components; GL_C4UB_V3F interleaved
 * arrays; (bottom row) GL_FRONT_AND_BACK GL_DIFFUSE with glColor3ub per
 * vertex in a list; glDrawElements with a colour array in a list; a list
 * that only enables colour material, called before immediate drawing.
 */
#include "lights_conform.h"

static void quad_pos(float x, float y, GLfloat out[4][3])
{
    for (int k = 0; k < 4; k++)
        conform_corner(k, x, y, 1.0f, out[k]);
}

static int draw(int w, int h)
{
    conform_begin(w, h);
    GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, grey);
    glNormal3f(0, 0, 1);
    GLfloat v[4][3];
    GLubyte ub[4][3];
    for (int k = 0; k < 4; k++)
        for (int c = 0; c < 3; c++)
            ub[k][c] = (GLubyte)(conform_colours[k][c] * 255 + 0.5f);
    GLuint list = glGenLists(4);

    /* 1: colour before the enable, none per vertex */
    glNewList(list, GL_COMPILE);
    glColor3f(0.9f, 0.6f, 0.2f);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    quad_pos(-2.6f, 0.3f, v);
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++)
        glVertex3fv(v[k]);
    glEnd();
    glDisable(GL_COLOR_MATERIAL);
    glEndList();
    glCallList(list);

    /* 2: unsigned-byte colour array, three components */
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    static GLfloat v2[4][3];
    quad_pos(-0.8f, 0.3f, v2);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v2);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, ub);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);

    /* 3: interleaved GL_C4UB_V3F */
    static struct { GLubyte c[4]; GLfloat p[3]; } il[4];
    GLfloat v3[4][3];
    quad_pos(1.0f, 0.3f, v3);
    for (int k = 0; k < 4; k++) {
        memcpy(il[k].c, ub[k], 3);
        il[k].c[3] = 255;
        memcpy(il[k].p, v3[k], sizeof il[k].p);
    }
    glInterleavedArrays(GL_C4UB_V3F, 0, il);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisable(GL_COLOR_MATERIAL);

    /* 4: FRONT_AND_BACK DIFFUSE, glColor3ub in a list */
    glNewList(list + 1, GL_COMPILE);
    glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    quad_pos(-2.6f, -1.3f, v);
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glColor3ubv(ub[k]);
        glVertex3fv(v[k]);
    }
    glEnd();
    glDisable(GL_COLOR_MATERIAL);
    glEndList();
    glCallList(list + 1);

    /* 5: glDrawElements with a colour array, compiled into a list */
    static GLfloat v5[4][3];
    static const GLubyte idx[6] = {0, 1, 2, 0, 2, 3};
    quad_pos(-0.8f, -1.3f, v5);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, v5);
    glColorPointer(4, GL_FLOAT, 0, conform_colours);
    glNewList(list + 2, GL_COMPILE);
    glEnable(GL_COLOR_MATERIAL);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
    glDisable(GL_COLOR_MATERIAL);
    glEndList();
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glCallList(list + 2);

    /* 6: a list that only turns colour material on */
    glNewList(list + 3, GL_COMPILE);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glEndList();
    glCallList(list + 3);
    quad_pos(1.0f, -1.3f, v);
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glColor4fv(conform_colours[k]);
        glVertex3fv(v[k]);
    }
    glEnd();
    glDisable(GL_COLOR_MATERIAL);
    return 0;
}

RGL_TEST_MAIN(draw)
