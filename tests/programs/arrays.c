/* arrays.c: vertex arrays from client memory, written with plain gl* calls
 * and the drop-in header.
 *
 * Covers: glDrawArrays with strided arrays; vertex arrays of GL_SHORT,
 * GL_INT, GL_FLOAT and GL_DOUBLE, sizes 2, 3 and 4 (w != 1); colour arrays
 * of every type (normalised as GL does) with 3 and 4 components;
 * glDrawElements and glDrawRangeElements with ubyte, ushort and uint
 * indices (shared vertices); glArrayElement inside glBegin/glEnd;
 * glMultiDrawArrays and glMultiDrawElements; an edge-flag array with
 * polygon mode GL_LINE; a texture-coordinate array (no texture bound:
 * no effect); a display list compiled from an array draw (GL reads the
 * arrays at compile time) and called after the arrays changed.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

#include <GL/glext.h>
#include <raygl/gl.h>

/* A quad of size 20 at (x, y) as 4 interleaved records: 3 floats of
 * position, one pad float, 4 ubytes of colour. */
typedef struct rec {
    float pos[3];
    float pad;
    GLubyte col[4];
} rec;

static void quad_recs(rec *r, float x, float y, int seed)
{
    static const float dx[4] = {0, 20, 20, 0}, dy[4] = {0, 0, 20, 20};
    for (int i = 0; i < 4; i++) {
        r[i].pos[0] = x + dx[i];
        r[i].pos[1] = y + dy[i];
        r[i].pos[2] = 0;
        r[i].pad = -1;
        r[i].col[0] = (GLubyte)(60 * i + 40 * seed);
        r[i].col[1] = (GLubyte)(255 - 50 * i);
        r[i].col[2] = (GLubyte)(30 * seed);
        r[i].col[3] = 255;
    }
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.21f, 0.43f, 0.0f);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* Strided interleaved records, GL_QUADS by glDrawArrays. */
    rec r[12];
    for (int q = 0; q < 3; q++)
        quad_recs(r + 4 * q, 10.0f + 25.0f * (float)q, 210, q);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(rec), r[0].pos);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(rec), r[0].col);
    glDrawArrays(GL_QUADS, 0, 12);

    /* Vertex types and sizes: triangles in one colour each. */
    glDisableClientState(GL_COLOR_ARRAY);
    static const GLshort vs[6] = {90, 210, 110, 210, 100, 230};
    static const GLint vi[9] = {115, 210, 0, 135, 210, 0, 125, 230, 0};
    static const GLdouble vd[9] = {140, 210, 0, 160, 210, 0, 150, 230, 0};
    static const GLfloat v4[12] = {330, 420, 0, 2, 370, 420, 0, 2, 350, 460, 0, 2}; /* w=2 */
    glColor3f(1, 0.5f, 0);
    glVertexPointer(2, GL_SHORT, 0, vs);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColor3f(0, 0.5f, 1);
    glVertexPointer(3, GL_INT, 0, vi);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColor3f(0.5f, 1, 0);
    glVertexPointer(3, GL_DOUBLE, 0, vd);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glColor3f(1, 1, 1);
    glVertexPointer(4, GL_FLOAT, 0, v4);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    /* Colour types: a quad per type, one colour per corner. */
    glEnableClientState(GL_COLOR_ARRAY);
    static const GLfloat qv[8] = {0, 0, 22, 0, 22, 22, 0, 22};
    static const GLubyte cub[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 0};
    static const GLbyte cb[12] = {127, 0, 0, 0, 127, 0, 0, 0, 127, 127, 127, -128};
    static const GLushort cus[12] = {65535, 0, 0, 0, 65535, 0, 0, 0, 65535, 30000, 30000, 0};
    static const GLshort cs[12] = {32767, 0, 0, 0, 32767, 0, 0, 0, 32767, 20000, 0, 20000};
    static const GLuint cui[16] = {4294967295u, 0, 0, 4294967295u, 0, 4294967295u, 0,
                                   4294967295u, 0, 0, 4294967295u, 4294967295u, 2147483648u,
                                   2147483648u, 0, 4294967295u};
    static const GLint ci[12] = {2147483647, 0, 0, 0, 2147483647, 0, 0, 0, 2147483647,
                                 1000000000, 1000000000, 1000000000};
    static const GLfloat cf[16] = {1, 0.5f, 0, 1, 0, 1, 0.5f, 1, 0.5f, 0, 1, 1, 1, 1, 1, 1};
    static const GLdouble cd[12] = {0.2, 0.4, 0.6, 0.8, 0.6, 0.4, 0.1, 0.9, 0.1, 1, 0, 0.5};
    struct { GLint size; GLenum type; const void *p; } ctypes[8] = {
        {3, GL_UNSIGNED_BYTE, cub}, {3, GL_BYTE, cb},   {3, GL_UNSIGNED_SHORT, cus},
        {3, GL_SHORT, cs},          {4, GL_UNSIGNED_INT, cui}, {3, GL_INT, ci},
        {4, GL_FLOAT, cf},          {3, GL_DOUBLE, cd},
    };
    glVertexPointer(2, GL_FLOAT, 0, qv);
    for (int k = 0; k < 8; k++) {
        glPushMatrix();
        glTranslatef(10.0f + 38.0f * (float)k, 175, 0);
        glColorPointer(ctypes[k].size, ctypes[k].type, 0, ctypes[k].p);
        glDrawArrays(GL_QUADS, 0, 4);
        glPopMatrix();
    }

    /* Indexed: a grid of 4x3 shared vertices, two triangles per cell. */
    GLfloat gv[12][2];
    GLubyte gc[12][3];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            gv[j * 4 + i][0] = 12.0f * (float)i;
            gv[j * 4 + i][1] = 12.0f * (float)j;
            gc[j * 4 + i][0] = (GLubyte)(80 * i);
            gc[j * 4 + i][1] = (GLubyte)(120 * j);
            gc[j * 4 + i][2] = (GLubyte)(255 - 60 * i);
        }
    GLubyte i8[36];
    GLushort i16[36];
    GLuint i32[36];
    int n = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 3; i++) {
            int a = j * 4 + i;
            const int t[6] = {a, a + 1, a + 5, a, a + 5, a + 4};
            for (int k = 0; k < 6; k++) {
                i8[n] = (GLubyte)t[k];
                i16[n] = (GLushort)t[k];
                i32[n] = (GLuint)t[k];
                n++;
            }
        }
    glVertexPointer(2, GL_FLOAT, 0, gv);
    glColorPointer(3, GL_UNSIGNED_BYTE, 0, gc);
    glPushMatrix();
    glTranslatef(10, 120, 0);
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_BYTE, i8);
    glTranslatef(50, 0, 0);
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, i16);
    glTranslatef(50, 0, 0);
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, i32);
    glTranslatef(50, 0, 0);
    glDrawRangeElements(GL_TRIANGLES, 0, 11, n, GL_UNSIGNED_BYTE, i8);
    glTranslatef(50, 0, 0);
    glDrawRangeElements(GL_TRIANGLES, 0, 11, 18, GL_UNSIGNED_SHORT, i16 + 18);
    glTranslatef(50, 0, 0);
    glDrawRangeElements(GL_TRIANGLE_STRIP, 1, 6, 4, GL_UNSIGNED_INT,
                        (const GLuint[]){1, 5, 2, 6});
    glPopMatrix();

    /* glArrayElement between glBegin and glEnd. */
    glPushMatrix();
    glTranslatef(10, 80, 0);
    glBegin(GL_TRIANGLE_FAN);
    glArrayElement(5);
    for (int k = 0; k < 4; k++)
        glArrayElement((GLint[]){0, 2, 10, 8}[k]);
    glArrayElement(0);
    glEnd();
    glPopMatrix();

    /* Multi-draws. */
    glPushMatrix();
    glTranslatef(60, 80, 0);
    /* Two strips and a triangle out of one array: a zigzag of 12. */
    GLfloat zv[12][2];
    for (int k = 0; k < 12; k++) {
        zv[k][0] = 4.0f * (float)k;
        zv[k][1] = k % 2 ? 22.0f : (float)(k % 4);
    }
    glVertexPointer(2, GL_FLOAT, 0, zv);
    static const GLint mfirst[3] = {0, 5, 9};
    static const GLsizei mcount[3] = {4, 4, 3};
    glMultiDrawArrays(GL_TRIANGLE_STRIP, mfirst, mcount, 3);
    glVertexPointer(2, GL_FLOAT, 0, gv);
    glTranslatef(50, 0, 0);
    static const GLushort e0[3] = {0, 3, 11}, e1[4] = {1, 2, 6, 5};
    const void *const eidx[2] = {e0, e1};
    static const GLsizei ecount[2] = {3, 4};
    glMultiDrawElements(GL_POLYGON, ecount, GL_UNSIGNED_SHORT, eidx, 2);
    glPopMatrix();

    /* Edge flags with polygon mode GL_LINE: the inner diagonal is hidden. */
    static const GLfloat ev[12] = {0, 0, 30, 0, 30, 30, 0, 0, 30, 30, 0, 30};
    static const GLboolean ef[6] = {GL_TRUE, GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE, GL_TRUE};
    glDisableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_EDGE_FLAG_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, ev);
    glEdgeFlagPointer(0, ef);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glColor3f(1, 1, 0);
    glPushMatrix();
    glTranslatef(170, 70, 0);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glPopMatrix();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisableClientState(GL_EDGE_FLAG_ARRAY);

    /* Texture coordinates with no texture: no effect on the colours. */
    static const GLfloat tv[8] = {0, 0, 1, 0, 1, 1, 0, 1};
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glTexCoordPointer(2, GL_FLOAT, 0, tv);
    glVertexPointer(2, GL_FLOAT, 0, qv);
    glColor3f(0.7f, 0.2f, 0.9f);
    glPushMatrix();
    glTranslatef(220, 75, 0);
    glDrawArrays(GL_QUADS, 0, 4);
    glPopMatrix();
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);

    /* A list compiled from an array draw keeps the data of compile time. */
    GLfloat lv[6] = {0, 0, 30, 0, 15, 25};
    glVertexPointer(2, GL_FLOAT, 0, lv);
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glColor3f(0.2f, 1, 0.6f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndList();
    lv[4] = 100; /* after compile: the list keeps the old apex */
    for (int k = 0; k < 3; k++) {
        glPushMatrix();
        glTranslatef(10.0f + 40.0f * (float)k, 20, 0);
        glCallList(list);
        glPopMatrix();
    }
    glDeleteLists(list, 1);
    glDisableClientState(GL_VERTEX_ARRAY);
    return 0;
}

RGL_TEST_MAIN(draw)
