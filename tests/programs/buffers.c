/* buffers.c: buffer objects with the fixed-function arrays, written with
 * plain gl* calls and the drop-in header (GL 1.5 names and the ARB ones).
 *
 * Covers: glBufferData with data and with NULL then glBufferSubData;
 * pointers that are offsets into a GL_ARRAY_BUFFER, with strides;
 * glDrawElements, glDrawRangeElements and glMultiDrawElements with indices
 * in a GL_ELEMENT_ARRAY_BUFFER (offsets); a buffer written through
 * glMapBuffer; glInterleavedArrays from a buffer; client arrays again after
 * binding buffer 0; a buffer redefined after a draw (the draw keeps what it
 * read); glDeleteBuffers.
 */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

#include <stdio.h>
#include <string.h>

#include <GL/glext.h>
#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.21f, 0.43f, 0.0f);
    glClearColor(0.0f, 0.05f, 0.1f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    GLuint b[4];
    glGenBuffers(4, b);

    /* Buffer 0: positions (2 floats) then colours (4 ubytes) of a 4x3
     * grid, in two blocks. */
    GLfloat pos[12][2];
    GLubyte col[12][4];
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            pos[j * 4 + i][0] = 20.0f * (float)i;
            pos[j * 4 + i][1] = 20.0f * (float)j;
            GLubyte *c = col[j * 4 + i];
            c[0] = (GLubyte)(70 * i);
            c[1] = (GLubyte)(250 - 100 * j);
            c[2] = (GLubyte)(40 + 50 * i);
            c[3] = 255;
        }
    glBindBuffer(GL_ARRAY_BUFFER, b[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof pos + sizeof col, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof pos, pos);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof pos, sizeof col, col);

    GLushort idx[36];
    int n = 0;
    for (int j = 0; j < 2; j++)
        for (int i = 0; i < 3; i++) {
            int a = j * 4 + i;
            const int t[6] = {a, a + 1, a + 5, a, a + 5, a + 4};
            for (int k = 0; k < 6; k++)
                idx[n++] = (GLushort)t[k];
        }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, (const void *)sizeof pos);
    glPushMatrix();
    glTranslatef(10, 180, 0);
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, (const void *)0);
    glTranslatef(75, 0, 0);
    glDrawRangeElements(GL_TRIANGLES, 0, 11, 18, GL_UNSIGNED_SHORT,
                        (const void *)(18 * sizeof(GLushort)));
    glTranslatef(75, 0, 0);
    static const GLsizei mcount[2] = {6, 12};
    const void *const moff[2] = {(const void *)0, (const void *)(24 * sizeof(GLushort))};
    glMultiDrawElements(GL_TRIANGLES, mcount, GL_UNSIGNED_SHORT, moff, 2);
    glTranslatef(75, 0, 0);
    glDrawArrays(GL_LINE_STRIP, 0, 12);
    glPopMatrix();

    /* Buffer 2, ARB names: filled through a mapping, interleaved C3F_V3F
     * with a stride of 32 bytes (8 floats, 2 unused). */
    glBindBufferARB(GL_ARRAY_BUFFER_ARB, b[2]);
    glBufferDataARB(GL_ARRAY_BUFFER_ARB, 6 * 8 * sizeof(GLfloat), NULL, GL_DYNAMIC_DRAW_ARB);
    GLfloat *m = glMapBufferARB(GL_ARRAY_BUFFER_ARB, GL_WRITE_ONLY_ARB);
    if (!m) {
        fprintf(stderr, "buffers: glMapBufferARB failed\n");
        return 1;
    }
    static const float fx[6] = {0, 40, 50, 30, 0, -10}, fy[6] = {0, 0, 25, 45, 40, 20};
    for (int i = 0; i < 6; i++) {
        GLfloat *v = m + 8 * i;
        v[0] = (float)i / 5.0f;
        v[1] = 1.0f - (float)i / 5.0f;
        v[2] = 0.5f;
        v[3] = 20 + fx[i];
        v[4] = 100 + fy[i];
        v[5] = 0;
        v[6] = v[7] = -99;
    }
    if (!glUnmapBufferARB(GL_ARRAY_BUFFER_ARB)) {
        fprintf(stderr, "buffers: glUnmapBufferARB failed\n");
        return 1;
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glInterleavedArrays(GL_C3F_V3F, 8 * sizeof(GLfloat), (const void *)0);
    glDrawArrays(GL_POLYGON, 0, 6);
    /* The same buffer again, mapped read-write, moved right by 80. */
    m = glMapBuffer(GL_ARRAY_BUFFER, GL_READ_WRITE);
    if (!m) {
        fprintf(stderr, "buffers: glMapBuffer failed\n");
        return 1;
    }
    for (int i = 0; i < 6; i++)
        m[8 * i + 3] += 80;
    glUnmapBuffer(GL_ARRAY_BUFFER);
    glDrawArrays(GL_POLYGON, 0, 6);

    /* Redefined after a draw: the first draw keeps what it read. */
    static const GLfloat tri1[6] = {180, 100, 220, 100, 200, 140};
    static const GLfloat tri2[6] = {230, 100, 270, 100, 250, 140};
    glDisableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, b[3]);
    glBufferData(GL_ARRAY_BUFFER, sizeof tri1, tri1, GL_STREAM_DRAW);
    glVertexPointer(2, GL_FLOAT, 0, (const void *)0);
    glColor3f(1, 0.4f, 0.2f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBufferData(GL_ARRAY_BUFFER, sizeof tri2, tri2, GL_STREAM_DRAW);
    glColor3f(0.3f, 1, 1);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    /* Client memory again once buffer 0 is bound. */
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    static const GLfloat cv[8] = {20, 20, 60, 20, 60, 60, 20, 60};
    glVertexPointer(2, GL_FLOAT, 0, cv);
    glColor3f(1, 1, 1);
    glDrawArrays(GL_QUADS, 0, 4);

    glDisableClientState(GL_VERTEX_ARRAY);
    glDeleteBuffers(4, b);
    return 0;
}

RGL_TEST_MAIN(draw)
