/* conf_lists_nested.c: display lists calling lists, glCallLists and
 * glListBase. A list draws one rectangle; a second calls it twice with a
 * translation between (the translation stays after the call, as GL keeps
 * any state a list changes); a third sets a colour and calls the second
 * inside a push/pop. Then glCallLists with an offset table in each index
 * type (GL_UNSIGNED_BYTE, GL_BYTE, GL_UNSIGNED_SHORT, GL_INT, GL_FLOAT,
 * GL_2_BYTES) under a glListBase, one of them naming an undefined list
 * (GL skips it), a list redefined after glDeleteLists, one made with
 * GL_COMPILE_AND_EXECUTE, and glListBase left non-zero while glCallList
 * (which ignores it) runs. Unlit, window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.08f, 0.08f, 0.1f);
    GLuint base = glGenLists(12);
    glNewList(base, GL_COMPILE);
    conf_box(0, 0, 14, 20, 0.0f);
    glEndList();
    glNewList(base + 1, GL_COMPILE);
    glCallList(base);
    glTranslatef(18.0f, 0.0f, 0.0f);
    glCallList(base);
    glEndList();
    glNewList(base + 2, GL_COMPILE);
    glColor3f(0.9f, 0.6f, 0.2f);
    glPushMatrix();
    glCallList(base + 1);
    glCallList(base + 1);
    glPopMatrix();
    glEndList();
    /* Lists base + 3 .. base + 8: a colour each, then the rectangle, then
     * a step right. */
    for (int i = 0; i < 6; i++) {
        glNewList(base + 3 + (GLuint)i, GL_COMPILE);
        glColor3f(0.2f + 0.13f * (float)i, 0.9f - 0.12f * (float)i, 0.3f + 0.1f * (float)i);
        glCallList(base);
        glTranslatef(22.0f, 0.0f, 0.0f);
        glEndList();
    }

    glTranslatef(10.0f, 200.0f, 0.0f);
    glCallList(base + 2);
    glCallList(base + 2); /* the matrix the first call left: 36 further */
    glLoadIdentity();
    glTranslatef(10.0f, 170.0f, 0.0f);
    glColor3f(0.3f, 0.5f, 0.9f);
    glCallList(base + 1);

    glListBase(base + 3);
    static const GLubyte ub[3] = {0, 1, 2};
    static const GLbyte sb[3] = {3, 4, 5};
    static const GLushort us[3] = {5, 4, 3};
    static const GLint in[4] = {0, 40, 2, 1}; /* list base + 43 is undefined */
    static const GLfloat fl[3] = {1.0f, 3.0f, 5.0f};
    static const GLubyte two[6] = {0, 2, 0, 4, 0, 0};
    glLoadIdentity();
    glTranslatef(10.0f, 140.0f, 0.0f);
    glCallLists(3, GL_UNSIGNED_BYTE, ub);
    glCallLists(3, GL_BYTE, sb);
    glLoadIdentity();
    glTranslatef(10.0f, 110.0f, 0.0f);
    glCallLists(3, GL_UNSIGNED_SHORT, us);
    glCallLists(4, GL_INT, in);
    glLoadIdentity();
    glTranslatef(10.0f, 80.0f, 0.0f);
    glCallLists(3, GL_FLOAT, fl);
    glCallLists(3, GL_2_BYTES, two);

    glListBase(100);
    glLoadIdentity();
    glTranslatef(10.0f, 50.0f, 0.0f);
    glCallList(base + 1); /* glCallList ignores the base */
    glListBase(0);

    glDeleteLists(base, 1);
    glNewList(base, GL_COMPILE);
    conf_box(0, 0, 30, 10, 0.0f);
    glEndList();
    glColor3f(0.9f, 0.9f, 0.9f);
    glTranslatef(60.0f, 0.0f, 0.0f);
    glCallList(base + 1); /* calls the new base */
    glLoadIdentity();
    glTranslatef(10.0f, 20.0f, 0.0f);
    glNewList(base + 9, GL_COMPILE_AND_EXECUTE);
    glColor3f(0.8f, 0.3f, 0.8f);
    conf_box(0, 0, 100, 12, 0.0f);
    glEndList();
    glTranslatef(120.0f, 0.0f, 0.0f);
    glCallList(base + 9);
    glDeleteLists(base, 12);
    return 0;
}

RGL_TEST_MAIN(draw)
