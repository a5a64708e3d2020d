/* lists_colours.c: display lists with a colour per vertex, each called
 * many times, unlit. In a prototype the translator carries such colours
 * as one image per mesh (docs/mapping.md section 9).
 *
 * Covers: a smooth-shaded patch of triangles whose corner colours vary
 * smoothly (the image path: per face a 2x2 block whose bilinear filtering
 * is GL's Gouraud interpolation), called 24 times rotated and scaled; a
 * flat-shaded fan whose provoking colours are saturated (the image path,
 * four equal texels per face); a triangle with red, green and blue
 * corners, whose fourth texel would leave 0..255 whichever corner comes
 * first (the texture_list is kept), called 6 times.
 */
#include "harness.h"

#include <math.h>
#include <raygl/gl.h>

static void patch_colour(float x, float y)
{
    glColor3f(0.15f + 0.7f * x, 0.2f + 0.6f * y * y, 0.85f - 0.5f * x * y);
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

    GLuint base = glGenLists(3);
    GLuint l_patch = base, l_fan = base + 1, l_rgb = base + 2;

    /* 4 x 3 cells of two triangles, 36 x 27 units. */
    glNewList(l_patch, GL_COMPILE);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLES);
    for (int j = 0; j < 3; j++)
        for (int i = 0; i < 4; i++) {
            float x0 = (float)i / 4, x1 = (float)(i + 1) / 4;
            float y0 = (float)j / 3, y1 = (float)(j + 1) / 3;
            patch_colour(x0, y0);
            glVertex2f(36 * x0, 27 * y0);
            patch_colour(x1, y0);
            glVertex2f(36 * x1, 27 * y0);
            patch_colour(x1, y1);
            glVertex2f(36 * x1, 27 * y1);
            patch_colour(x0, y0);
            glVertex2f(36 * x0, 27 * y0);
            patch_colour(x1, y1);
            glVertex2f(36 * x1, 27 * y1);
            patch_colour(x0, y1);
            glVertex2f(36 * x0, 27 * y1);
        }
    glEnd();
    glEndList();

    glNewList(l_fan, GL_COMPILE);
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1, 1, 1);
    glVertex2f(0, 0);
    for (int i = 0; i <= 6; i++) {
        static const float c[6][3] = {{1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 1, 1}, {0, 0, 1}, {1, 0, 1}};
        double a = 2 * 3.14159265358979 * i / 6;
        glColor3fv(c[i % 6]);
        glVertex2f((float)(16 * cos(a)), (float)(16 * sin(a)));
    }
    glEnd();
    glShadeModel(GL_SMOOTH);
    glEndList();

    glNewList(l_rgb, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex2f(0, 0);
    glColor3f(0, 1, 0);
    glVertex2f(30, 0);
    glColor3f(0, 0, 1);
    glVertex2f(12, 26);
    glEnd();
    glEndList();

    for (int i = 0; i < 24; i++) {
        glPushMatrix();
        glTranslatef(14.0f + 50.0f * (float)(i % 6), 10.0f + 36.0f * (float)(i / 6), 0);
        glTranslatef(18, 13, 0);
        glRotatef(7.0f * (float)i - 40.0f, 0, 0, 1);
        glScalef(0.75f + 0.02f * (float)i, 0.75f + 0.02f * (float)i, 1);
        glTranslatef(-18, -13, 0);
        glCallList(l_patch);
        glPopMatrix();
    }
    for (int i = 0; i < 6; i++) {
        glPushMatrix();
        glTranslatef(30.0f + 50.0f * (float)i, 180, 0);
        glRotatef(11.0f * (float)i, 0, 0, 1);
        glCallList(l_fan);
        glPopMatrix();
        glPushMatrix();
        glTranslatef(12.0f + 50.0f * (float)i, 205, 0);
        glRotatef(-9.0f * (float)i, 0, 0, 1);
        glCallList(l_rgb);
        glPopMatrix();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
