/* lists.c: display lists, written with plain gl* calls and the drop-in
 * header.
 *
 * Covers: one list called many times with different transforms (the
 * translator shares its output: one #declare, many objects); a list that
 * uses the current colour, called in several colours; a list that calls
 * lists; glCallLists with GL_UNSIGNED_BYTE, GL_BYTE, GL_SHORT, GL_2_BYTES,
 * GL_3_BYTES, GL_4_BYTES, GL_INT and GL_FLOAT names and glListBase;
 * GL_COMPILE_AND_EXECUTE; state changed inside a list (a colour and a
 * translation that stay after the call); glDeleteLists and a name reused;
 * a list that calls itself, cut at GL's nesting limit of 64; glCallList
 * between glBegin and glEnd (no GL error from the recorder).
 */
#include "harness.h"

#include <stdio.h>

#include <raygl/gl.h>

static void star(void)
{
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex2f(0, 0);
    for (int i = 0; i <= 10; i++) {
        static const float x[10] = {10, 3, 0, -3, -10, -4, -6, 0, 6, 4};
        static const float y[10] = {2, 3, 10, 3, 2, -2, -9, -5, -9, -2};
        glColor3f(i % 2 ? 1.0f : 0.2f, (float)(i % 10) / 10.0f, i % 3 ? 0.3f : 0.9f);
        glVertex2f(x[i % 10], y[i % 10]);
    }
    glEnd();
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
    glClearColor(0.05f, 0.05f, 0.1f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    GLuint base = glGenLists(8);
    GLuint l_star = base, l_quad = base + 1, l_pair = base + 2, l_red = base + 3,
           l_step = base + 4, l_cae = base + 5, l_tmp = base + 6, l_self = base + 7;

    glNewList(l_star, GL_COMPILE);
    star();
    glEndList();

    /* Uses the current colour; moves the modelview on by 14 in x. */
    glNewList(l_quad, GL_COMPILE);
    glBegin(GL_QUADS);
    glVertex2f(0, 0);
    glVertex2f(10, 0);
    glVertex2f(10, 10);
    glVertex2f(0, 10);
    glEnd();
    glTranslatef(14, 0, 0);
    glEndList();

    /* A list that calls lists. */
    glNewList(l_pair, GL_COMPILE);
    glPushMatrix();
    glCallList(l_star);
    glTranslatef(22, 0, 0);
    glScalef(0.6f, 0.6f, 1);
    glCallList(l_star);
    glPopMatrix();
    glEndList();

    /* State only: the colour stays after the call. */
    glNewList(l_red, GL_COMPILE);
    glColor3f(0.9f, 0.15f, 0.1f);
    glEndList();

    /* A small step for the self-calling list. */
    glNewList(l_step, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glVertex2f(0, 0);
    glVertex2f(3, 0);
    glVertex2f(1.5f, 6);
    glEnd();
    glTranslatef(4.5f, 0, 0);
    glEndList();

    /* One list called many times: a row of stars, rotated and scaled. */
    for (int i = 0; i < 12; i++) {
        glPushMatrix();
        glTranslatef(16.0f + 25.0f * (float)i, 220, 0);
        glRotatef(17.0f * (float)i, 0, 0, 1);
        glScalef(0.8f + 0.03f * (float)i, 0.8f + 0.03f * (float)i, 1);
        glCallList(l_star);
        glPopMatrix();
    }

    /* The quad list in several inherited colours, moving on by itself. */
    glPushMatrix();
    glTranslatef(10, 190, 0);
    for (int i = 0; i < 10; i++) {
        glColor3f((float)i / 9.0f, 1.0f - (float)i / 9.0f, 0.5f);
        glCallList(l_quad);
    }
    glColor3f(0.2f, 0.6f, 1.0f); /* the same colour twice: shared */
    glCallList(l_quad);
    glCallList(l_quad);
    glPopMatrix();

    /* Nested lists. */
    for (int i = 0; i < 4; i++) {
        glPushMatrix();
        glTranslatef(180.0f + 35.0f * (float)i, 165, 0);
        glCallList(l_pair);
        glPopMatrix();
    }

    /* glCallLists: names of every type, offset by glListBase. */
    glListBase(l_quad);
    static const GLubyte ub[3] = {0, 0, 0};
    static const GLbyte sb[2] = {0, 0};
    static const GLshort ss[2] = {0, 0};
    static const GLubyte two[4] = {0, 0, 0, 0};     /* GL_2_BYTES: 0, 0 */
    static const GLubyte three[3] = {0, 0, 0};      /* GL_3_BYTES: 0 */
    static const GLubyte four[4] = {0, 0, 0, 0};    /* GL_4_BYTES: 0 */
    static const GLint si[2] = {0, 0};
    static const GLfloat fl[2] = {0.0f, 0.0f};
    glPushMatrix();
    glTranslatef(10, 150, 0);
    glColor3f(1, 1, 0);
    glCallLists(3, GL_UNSIGNED_BYTE, ub);
    glColor3f(0, 1, 1);
    glCallLists(2, GL_BYTE, sb);
    glColor3f(1, 0, 1);
    glCallLists(2, GL_SHORT, ss);
    glColor3f(1, 1, 1);
    glCallLists(2, GL_2_BYTES, two);
    glColor3f(0.5f, 0.5f, 1);
    glCallLists(1, GL_3_BYTES, three);
    glCallLists(1, GL_4_BYTES, four);
    glColor3f(1, 0.5f, 0);
    glCallLists(2, GL_INT, si);
    glColor3f(0.5f, 1, 0.5f);
    glCallLists(2, GL_FLOAT, fl);
    glPopMatrix();
    /* Negative offsets from a base: GL_BYTE -1 from l_red is l_quad. */
    glListBase(l_red);
    static const GLbyte back[1] = {-2};
    glPushMatrix();
    glTranslatef(10, 130, 0);
    glCallLists(1, GL_BYTE, back); /* l_red - 2 = l_quad, in the current colour */
    glPopMatrix();
    glListBase(0);

    /* State changed inside a list lasts: the colour of the next quad. */
    glCallList(l_red);
    glBegin(GL_TRIANGLES);
    glVertex2f(180, 120);
    glVertex2f(230, 120);
    glVertex2f(205, 150);
    glEnd();

    /* GL_COMPILE_AND_EXECUTE draws while it compiles, then again. */
    glPushMatrix();
    glTranslatef(250, 120, 0);
    glNewList(l_cae, GL_COMPILE_AND_EXECUTE);
    glColor3f(0.3f, 1.0f, 0.3f);
    glBegin(GL_TRIANGLES);
    glVertex2f(0, 0);
    glVertex2f(25, 0);
    glVertex2f(0, 25);
    glEnd();
    glEndList();
    glTranslatef(30, 0, 0);
    glColor3f(0, 0, 1); /* overridden by the list's own colour */
    glCallList(l_cae);
    glPopMatrix();

    /* Delete a list and reuse its name with another body. */
    glNewList(l_tmp, GL_COMPILE);
    glColor3f(1, 0, 0);
    glRectf(0, 0, 200, 200); /* would cover everything: must not be drawn */
    glEndList();
    glDeleteLists(l_tmp, 1);
    glCallList(l_tmp); /* deleted: nothing */
    glNewList(l_tmp, GL_COMPILE);
    glColor3f(1, 0.8f, 0.2f);
    glRectf(10, 60, 60, 100);
    glEndList();
    glCallList(l_tmp);

    /* A list that calls itself: GL stops at 64 levels. */
    glNewList(l_self, GL_COMPILE);
    glCallList(l_step);
    glCallList(l_self);
    glEndList();
    glPushMatrix();
    glTranslatef(4, 10, 0);
    glScalef(1.0f, 3.0f, 1.0f);
    glColor3f(0.9f, 0.9f, 0.9f);
    glCallList(l_self);
    glPopMatrix();

    /* glCallList between glBegin and glEnd (a list of vertices only): the
     * recorder must not read matrices back there (a GL error). */
    GLuint l_verts = glGenLists(1);
    glNewList(l_verts, GL_COMPILE);
    glVertex2f(100, 60);
    glVertex2f(130, 60);
    glVertex2f(115, 85);
    glEndList();
    while (glGetError() != GL_NO_ERROR)
        ;
    glColor3f(0.6f, 0.3f, 1.0f);
    glBegin(GL_TRIANGLES);
    glCallList(l_verts);
    glEnd();
    if (glGetError() != GL_NO_ERROR) {
        fprintf(stderr, "lists: a GL error around glCallList inside glBegin/glEnd\n");
        return 1;
    }

    glDeleteLists(base, 8);
    glDeleteLists(l_verts, 1);
    return 0;
}

RGL_TEST_MAIN(draw)
