/* pixels_draw.c: glDrawPixels over an unlit scene. A 16 x 12 RGB image
 * (GL_UNSIGNED_BYTE, unpack alignment 1) drawn at a raster position given
 * in perspective object coordinates with glPixelZoom(4, 3); the same image
 * as GL_FLOAT RGBA with a negative zoom (-2, -2: drawn left and down from
 * the position) and the red scale and blue bias of glPixelTransfer; a
 * GL_LUMINANCE image placed by glWindowPos2f at a fractional position.
 */
#include "harness.h"

#include <raygl/gl.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, (double)w / (double)h, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3f(0.8f, 0.3f, 0.1f);
    glVertex3f(-2.0f, -1.5f, -5.0f);
    glColor3f(0.1f, 0.7f, 0.3f);
    glVertex3f(2.0f, -1.4f, -5.0f);
    glColor3f(0.2f, 0.3f, 0.9f);
    glVertex3f(0.1f, 1.8f, -5.0f);
    glEnd();

    static GLubyte rgb[12][16][3];
    static GLfloat rgba[12][16][4];
    static GLubyte lum[8][10];
    for (int y = 0; y < 12; y++)
        for (int x = 0; x < 16; x++) {
            rgb[y][x][0] = (GLubyte)(x * 16);
            rgb[y][x][1] = (GLubyte)(y * 20);
            rgb[y][x][2] = (GLubyte)((x + y) % 2 ? 230 : 40);
            for (int k = 0; k < 3; k++)
                rgba[y][x][k] = rgb[y][x][k] / 255.0f;
            rgba[y][x][3] = 1.0f;
        }
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 10; x++)
            lum[y][x] = (GLubyte)(25 * x + 5 * y);

    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos3f(-1.6f, 0.2f, -5.0f);
    glPixelZoom(4.0f, 3.0f);
    glDrawPixels(16, 12, GL_RGB, GL_UNSIGNED_BYTE, rgb);

    glRasterPos3f(1.8f, 1.2f, -5.0f);
    glPixelZoom(-2.0f, -2.0f);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_BLUE_BIAS, 0.25f);
    glDrawPixels(16, 12, GL_RGBA, GL_FLOAT, rgba);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_BLUE_BIAS, 0.0f);

    glPixelZoom(2.0f, 2.0f);
    glWindowPos2f((float)w - 40.25f, 10.25f);
    glDrawPixels(10, 8, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glPixelZoom(1.0f, 1.0f);
    return 0;
}

RGL_TEST_MAIN(draw)
