/* real_tex_lit.c: a lit, textured crate face turning under a local-viewer
 * light (GL_MODULATE over a white material, GL_NEAREST), two frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    static GLubyte tex[16][16][3];
    for (int i = 0; i < 16; i++)
        for (int j = 0; j < 16; j++) {
            int board = (i % 8 == 0 || j % 8 == 0);
            tex[i][j][0] = board ? 90 : 200;
            tex[i][j][1] = board ? 60 : 150;
            tex[i][j][2] = board ? 30 : 90;
        }
    glViewport(0, 0, w, h);
    glClearColor(0.15f, 0.15f, 0.2f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(40, (double)w / h, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, -5);
    glRotatef(-20.0f + 25.0f * (float)frame, 0, 1, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat pos[4] = {0, 0, 5, 0}, white[4] = {1, 1, 1, 1}, none[4] = {0, 0, 0, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, white);
    glMaterialfv(GL_FRONT, GL_SPECULAR, none);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 0, GL_RGB, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glNormal3f(0, 0, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex3f(-1.2f, -1.2f, 0);
    glTexCoord2f(1, 0);
    glVertex3f(1.2f, -1.2f, 0);
    glTexCoord2f(1, 1);
    glVertex3f(1.2f, 1.2f, 0);
    glTexCoord2f(0, 1);
    glVertex3f(-1.2f, 1.2f, 0);
    glEnd();
}

RGL_REAL_MAIN(draw, 2)
