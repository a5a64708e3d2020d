/* conf_matrix_ops.c: the matrix calls, each on an asymmetric L-shaped
 * polygon in its own cell of a 4 x 3 grid (so a wrong sign, a transposed
 * matrix or a mirrored turn shows): glLoadMatrixf, glLoadMatrixd,
 * glMultMatrixf of a shear, glMultTransposeMatrixf and
 * glLoadTransposeMatrixd of the same matrices stored transposed,
 * glRotatef about an odd axis (1, 2, 3) and about a non-unit (0, 0, -4)
 * one, glRotated by 390 degrees, glScalef(-1, -1, 1), glScaled with an
 * unequal scale, nested glPushMatrix/glPopMatrix, and glLoadIdentity then
 * glTranslate inside a push. Unlit, gluOrtho2D in cell units. */
#include "harness.h"

#include <raygl/gl.h>

/* The L in a unit cell's inner square, centred on (0, 0). */
static void ell(float r, float g, float b)
{
    glColor3f(r, g, b);
    glBegin(GL_POLYGON);
    glVertex2f(-0.30f, -0.32f);
    glVertex2f(0.34f, -0.32f);
    glVertex2f(0.34f, -0.12f);
    glVertex2f(-0.10f, -0.12f);
    glVertex2f(-0.10f, 0.36f);
    glVertex2f(-0.30f, 0.36f);
    glEnd();
}

/* The modelview at the centre of cell (i, j), 0.0011 off the pixel grid. */
static void cell(int i, int j)
{
    glLoadIdentity();
    glTranslatef((float)i + 0.5011f, (float)j + 0.5013f, 0.0f);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0.0, 4.0, 0.0, 3.0);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* A turn of 30 degrees with a translation, column-major. */
    const float c = 0.8660254f, s = 0.5f;
    const GLfloat m[16] = {c, s, 0, 0, -s, c, 0, 0, 0, 0, 1, 0, 0.5011f, 2.5013f, 0, 1};
    const GLdouble md[16] = {0.8, 0, 0, 0, 0, 1.1, 0, 0, 0, 0, 1, 0, 1.5011, 2.5013, 0, 1};
    const GLfloat shear[16] = {1, 0, 0, 0, 0.5f, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    GLfloat shear_t[16], m_t[16];
    for (int r = 0; r < 4; r++)
        for (int k = 0; k < 4; k++) {
            shear_t[r * 4 + k] = shear[k * 4 + r];
            m_t[r * 4 + k] = m[k * 4 + r];
        }
    GLdouble md_t[16];
    for (int r = 0; r < 4; r++)
        for (int k = 0; k < 4; k++)
            md_t[r * 4 + k] = md[k * 4 + r];

    glLoadMatrixf(m);
    ell(0.9f, 0.3f, 0.2f);
    glLoadMatrixd(md);
    ell(0.3f, 0.8f, 0.3f);
    cell(2, 2);
    glMultMatrixf(shear);
    ell(0.3f, 0.4f, 0.9f);
    cell(3, 2);
    glMultTransposeMatrixf(shear_t);
    glRotatef(-20.0f, 0.0f, 0.0f, 1.0f);
    ell(0.9f, 0.8f, 0.2f);

    glLoadTransposeMatrixf(m_t);
    glTranslatef(0.0f, -1.0f, 0.0f);
    ell(0.8f, 0.3f, 0.8f);
    glLoadTransposeMatrixd(md_t);
    glTranslatef(0.0f, -1.0f, 0.0f);
    ell(0.3f, 0.8f, 0.8f);
    cell(2, 1);
    glRotatef(40.0f, 1.0f, 2.0f, 3.0f);
    ell(0.9f, 0.6f, 0.4f);
    cell(3, 1);
    glRotatef(35.0f, 0.0f, 0.0f, -4.0f);
    ell(0.6f, 0.9f, 0.4f);

    cell(0, 0);
    glRotated(390.0, 0.0, 0.0, 1.0);
    ell(0.5f, 0.6f, 0.9f);
    cell(1, 0);
    glScalef(-1.0f, -1.0f, 1.0f);
    ell(0.9f, 0.5f, 0.6f);
    cell(2, 0);
    glPushMatrix();
    glScaled(1.3, 0.7, 1.0);
    glPushMatrix();
    glRotatef(90.0f, 0.0f, 0.0f, 1.0f);
    glPopMatrix();
    ell(0.7f, 0.7f, 0.7f);
    glPopMatrix();
    cell(3, 0);
    glPushMatrix();
    glLoadIdentity();
    glTranslatef(3.5011f, 0.5013f, 0.0f);
    glRotatef(180.0f, 0.0f, 1.0f, 0.0f);
    ell(0.9f, 0.9f, 0.5f);
    glPopMatrix();
    (void)w;
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
