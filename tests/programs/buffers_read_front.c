/* buffers_read_front.c: the front buffer read back (glReadBuffer(GL_FRONT);
 * GLUT double-buffered window under Xvfb). A pattern of quads on pixel
 * boundaries is drawn into the front buffer only, after both were cleared;
 * from the front buffer a 60 x 40 region is copied into the back buffer,
 * which the frame shows, with glCopyPixels and an 8 x 8 one into a texture
 * with glCopyTexImage2D, drawn magnified with GL_NEAREST. The recorder
 * reads each source from the program's read buffer at the call; the
 * front-only quads are not in the picture.
 */
#include "harness.h"

#include <raygl/gl.h>

static void rect(float x0, float y0, float x1, float y1, float r, float g, float b)
{
    glColor3f(r, g, b);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    glDrawBuffer(GL_FRONT_AND_BACK);
    glClearColor(0.25f, 0.25f, 0.25f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawBuffer(GL_FRONT);
    glBegin(GL_QUADS);
    rect(16, 16, 20, 20, 0.9f, 0.2f, 0.1f);
    rect(20, 16, 24, 20, 0.1f, 0.8f, 0.2f);
    rect(16, 20, 20, 24, 0.2f, 0.3f, 0.9f);
    rect(20, 20, 24, 24, 0.95f, 0.9f, 0.2f);
    rect(30, 10, 70, 40, 0.8f, 0.5f, 0.2f);
    rect(40, 20, 60, 50, 0.3f, 0.9f, 0.9f);
    glEnd();
    glFinish();

    glDrawBuffer(GL_BACK);
    glReadBuffer(GL_FRONT);
    glWindowPos2i(200, 150);
    glCopyPixels(12, 12, 60, 40, GL_COLOR);

    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 8, 8, 0);
    glReadBuffer(GL_BACK);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(20, 60);
    glTexCoord2f(1, 0);
    glVertex2f(148, 60);
    glTexCoord2f(1, 1);
    glVertex2f(148, 188);
    glTexCoord2f(0, 1);
    glVertex2f(20, 188);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    return 0;
}

RGL_TEST_MAIN(draw)
