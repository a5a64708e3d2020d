/* fogsec_pixels_depth.c: the depth of a pixel rectangle against geometry
 * drawn before and after it (issue 13).
 *
 * Under gluPerspective with the depth test on, a 96 x 64 glDrawPixels
 * image at a glRasterPos3f at depth 6, and unlit quads around it: one
 * drawn before, nearer (it hides the image's lower left), one drawn
 * before, farther (the image covers it), one drawn after, farther (GL's
 * depth test against the image's depth hides it there), one drawn after,
 * nearer (it covers the image's upper right). GL gives the image's pixels
 * the raster position's depth (GL 2.1 3.6.5).
 */
#include "harness.h"

#include <raygl/gl.h>

/* A quad at depth d whose corners look as (x0, y0) .. (x1, y1) would at
 * depth 6, the image's. */
static void quad(float x0, float y0, float x1, float y1, float d, float r, float g, float b)
{
    float k = d / 6.0f;
    glColor3f(r, g, b);
    glBegin(GL_QUADS);
    glVertex3f(x0 * k, y0 * k, -d);
    glVertex3f(x1 * k, y0 * k, -d);
    glVertex3f(x1 * k, y1 * k, -d);
    glVertex3f(x0 * k, y1 * k, -d);
    glEnd();
}

static GLubyte image[64][96][3];

static int draw(int w, int h)
{
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 96; x++) {
            image[y][x][0] = (GLubyte)(x * 255 / 95);
            image[y][x][1] = (GLubyte)(y * 255 / 63);
            image[y][x][2] = (GLubyte)((x + y) % 16 < 8 ? 200 : 60);
        }
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    /* The image spans (-1, -1) .. (1, 0.33) at depth 6 (48 pixels a unit). */
    quad(-1.6f, -1.4f, -0.3f, -0.4f, 4.5f, 0.9f, 0.3f, 0.2f); /* before, nearer */
    quad(-0.5f, -0.2f, 1.5f, 1.2f, 8.0f, 0.2f, 0.7f, 0.3f);   /* before, farther */

    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos3f(-1.0f, -1.0f, -6.0f);
    glDrawPixels(96, 64, GL_RGB, GL_UNSIGNED_BYTE, image);

    quad(-0.2f, -1.5f, 0.8f, -0.3f, 7.0f, 0.8f, 0.8f, 0.2f); /* after, farther */
    quad(0.4f, 0.0f, 1.4f, 0.8f, 5.0f, 0.3f, 0.4f, 0.9f);    /* after, nearer */
    return 0;
}

RGL_TEST_MAIN(draw)
