/* pstipple_screendoor.c: polygon stipple (issue 14): "screen-door
 * transparency". A lit sphere behind an unlit quad stippled with a 50%
 * checkerboard, which shows the sphere through every other pixel; a
 * second quad with a halftone mask of dots (a 25% pattern, rows differing)
 * under a perspective tilt, which GL keeps to window pixels, and a GLU
 * sphere under it; and a triangle drawn with the stipple off (whole). The mask is passed under a non-
 * default unpack state (GL_UNPACK_LSB_FIRST, a row length and skipped
 * rows) to exercise the recorder's read of it. */
#include "lit_scene.h"

static GLubyte checker[128], halftone[4 + 8 * 6 * 8];

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {1.0f, 1.2f, 1.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.8f, 0.25f, 0.2f, 0.6f, 40.0f);
    lit_sphere(-0.9f, 0.0f, -6.0f, 1.3f);
    lit_sphere(1.3f, 0.2f, -7.0f, 1.2f);
    glDisable(GL_LIGHTING);

    for (int r = 0; r < 32; r++)
        for (int b = 0; b < 4; b++)
            checker[r * 4 + b] = (r % 2) ? 0x55 : 0xAA;
    glEnable(GL_POLYGON_STIPPLE);
    glPolygonStipple(checker);
    glColor3f(0.2f, 0.8f, 0.9f);
    glBegin(GL_QUADS);
    glVertex3f(-2.3f, -1.2f, -4.0f);
    glVertex3f(-0.2f, -1.2f, -4.0f);
    glVertex3f(-0.2f, 1.1f, -4.0f);
    glVertex3f(-2.3f, 1.1f, -4.0f);
    glEnd();

    /* Halftone dots: rows of 8 bytes (row length 64 pixels), the first
     * 4 bytes skipped, least significant bit first. */
    for (int r = 0; r < 32; r++)
        for (int b = 0; b < 4; b++)
            halftone[4 + r * 8 + b] = (r % 4 == 0) ? 0x11 : (r % 4 == 2) ? 0x44 : (r % 8 == 1) ? 0x02 : 0x00;
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 64);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 32);
    glPolygonStipple(halftone);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glColor3f(1.0f, 0.9f, 0.3f);
    glBegin(GL_QUADS);
    glVertex3f(0.1f, -1.4f, -4.5f);
    glVertex3f(2.4f, -1.4f, -5.5f);
    glVertex3f(2.4f, 1.5f, -5.5f);
    glVertex3f(0.1f, 1.5f, -4.5f);
    glEnd();

    /* A GLU sphere (a POV-Ray solid) under the halftone. */
    GLUquadric *q = gluNewQuadric();
    if (q) {
        glColor3f(0.4f, 1.0f, 0.4f);
        glPushMatrix();
        glTranslatef(1.9f, -1.3f, -4.2f);
        gluSphere(q, 0.35, 32, 16);
        glPopMatrix();
        gluDeleteQuadric(q);
    }
    glDisable(GL_POLYGON_STIPPLE);
    glColor3f(0.9f, 0.4f, 0.9f);
    glBegin(GL_TRIANGLES);
    glVertex3f(-0.6f, -1.9f, -5.0f);
    glVertex3f(0.6f, -1.9f, -5.0f);
    glVertex3f(0.0f, -1.3f, -5.0f);
    glEnd();
    return 0;
}

RGL_TEST_MAIN(draw)
