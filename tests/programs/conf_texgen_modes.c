/* conf_texgen_modes.c: texture coordinate generation. Three tessellated
 * squares under a perspective camera, a 8 x 8 checker texture (GL_NEAREST,
 * GL_REPEAT): GL_OBJECT_LINEAR with oblique planes for s and t; GL_EYE_LINEAR
 * whose planes were given under another modelview (GL keeps them in eye
 * space as given, transformed by the inverse of the modelview then), the
 * square drawn under a turned one; GL_OBJECT_LINEAR on s alone, t from
 * glTexCoord (one coordinate generated, the other current). Unlit. */
#include "harness.h"

#include <raygl/gl.h>

static void square(float t_current)
{
    for (int j = 0; j < 8; j++) {
        glBegin(GL_QUAD_STRIP);
        for (int i = 0; i <= 8; i++) {
            float x = -1.0f + 0.25f * (float)i;
            glTexCoord2f(0.0f, t_current * (float)j);
            glVertex3f(x, -1.0f + 0.25f * (float)j, 0.0f);
            glTexCoord2f(0.0f, t_current * (float)(j + 1));
            glVertex3f(x, -1.0f + 0.25f * (float)(j + 1), 0.0f);
        }
        glEnd();
    }
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40.0, (double)w / (double)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    GLubyte checker[8][8][3];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            int on = (x + y) % 2;
            checker[y][x][0] = (GLubyte)(on ? 230 : 40);
            checker[y][x][1] = (GLubyte)(on ? 200 : 60 + 20 * x);
            checker[y][x][2] = (GLubyte)(on ? 60 : 180);
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);

    const GLfloat ps[4] = {0.35f, 0.1f, 0.0f, 0.5f}, pt[4] = {-0.1f, 0.4f, 0.0f, 0.25f};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, ps);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, pt);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glLoadIdentity();
    glTranslatef(-2.4f, 0.0013f, -7.0f);
    glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    square(0.0f);

    /* Eye planes given under a translated, turned modelview. */
    glLoadIdentity();
    glTranslatef(0.3f, -0.2f, 0.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    const GLfloat es[4] = {0.4f, 0.0f, 0.0f, 0.1f}, et[4] = {0.0f, 0.45f, 0.1f, 0.0f};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, es);
    glTexGenfv(GL_T, GL_EYE_PLANE, et);
    glLoadIdentity();
    glTranslatef(0.0011f, 0.0013f, -7.0f);
    glRotatef(-20.0f, 1.0f, 0.0f, 0.0f);
    square(0.0f);

    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glDisable(GL_TEXTURE_GEN_T);
    glLoadIdentity();
    glTranslatef(2.4f, 0.0013f, -7.0f);
    glRotatef(-25.0f, 0.0f, 1.0f, 0.0f);
    square(0.125f);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_2D);
    return 0;
}

RGL_TEST_MAIN(draw)
