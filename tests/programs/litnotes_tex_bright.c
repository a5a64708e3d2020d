/* litnotes_tex_bright.c: textured GL_MODULATE faces lit past white. GL
 * clamps the lit colour of each vertex to 1 before the texture multiplies
 * it (left quad: white material plus emission, over 1 in every channel);
 * POV-Ray's pigment times finish would show it brighter. The right quad is
 * lit below white: POV-Ray lights it as usual. docs/mapping.md "Faces lit
 * and fogged as GL does them".
 */
#include "harness.h"

#include <raygl/gl.h>

static void quad(float x)
{
    glPushMatrix();
    glTranslatef(x, 0, -5);
    glRotatef(-20, 0, 1, 0);
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    glTexCoord2f(0, 0);
    glVertex3f(-0.9f, -0.9f, 0);
    glTexCoord2f(1, 0);
    glVertex3f(0.9f, -0.9f, 0);
    glTexCoord2f(1, 1);
    glVertex3f(0.9f, 0.9f, 0);
    glTexCoord2f(0, 1);
    glVertex3f(-0.9f, 0.9f, 0);
    glEnd();
    glPopMatrix();
}

static int draw(int w, int h)
{
    static GLubyte tex[8][8][3];
    for (int i = 0; i < 8; i++)
        for (int j = 0; j < 8; j++) {
            int odd = (i / 2 + j / 2) % 2;
            tex[i][j][0] = odd ? 220 : 60;
            tex[i][j][1] = odd ? 160 : 120;
            tex[i][j][2] = odd ? 70 : 200;
        }
    glViewport(0, 0, w, h);
    glClearColor(0.1f, 0.1f, 0.15f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat pos[4] = {0, 0, 1, 0}, none[4] = {0, 0, 0, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT, GL_SPECULAR, none);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);

    const GLfloat white[4] = {1, 1, 1, 1}, glow[4] = {0.3f, 0.2f, 0.25f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
    glMaterialfv(GL_FRONT, GL_EMISSION, glow);
    quad(-1.05f);
    const GLfloat grey[4] = {0.6f, 0.6f, 0.6f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    glMaterialfv(GL_FRONT, GL_EMISSION, none);
    quad(1.05f);
    return 0;
}

RGL_TEST_MAIN(draw)
