/* texcopy_copy.c: render to texture. A pattern of unlit quads on pixel
 * boundaries is drawn, copied into two textures with glCopyTexImage2D (one
 * GL_RGB, one GL_LUMINANCE: luminance keeps red), a corner of it replaced
 * with glCopyTexSubImage2D, the frame cleared, and the textures drawn
 * magnified with GL_NEAREST on two quads. The recorder reads each copied
 * rectangle back at the call.
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
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    /* An 8 x 8 pattern at (16, 16): quadrants, a bar and a dot. */
    glBegin(GL_QUADS);
    rect(16, 16, 20, 20, 0.9f, 0.2f, 0.1f);
    rect(20, 16, 24, 20, 0.1f, 0.8f, 0.2f);
    rect(16, 20, 20, 24, 0.2f, 0.3f, 0.9f);
    rect(20, 20, 24, 24, 0.95f, 0.9f, 0.2f);
    rect(17, 22, 23, 23, 0.6f, 0.1f, 0.7f);
    rect(22, 17, 23, 18, 1.0f, 1.0f, 1.0f);
    /* The sub-image's source, elsewhere. */
    rect(40, 40, 43, 43, 0.1f, 0.9f, 0.9f);
    glEnd();

    GLuint tex[2];
    glGenTextures(2, tex);
    for (int k = 0; k < 2; k++) {
        glBindTexture(GL_TEXTURE_2D, tex[k]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, k == 0 ? GL_RGB : GL_LUMINANCE, 16, 16, 8, 8, 0);
    }
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 5, 40, 40, 3, 3);

    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (int k = 0; k < 2; k++) {
        float x0 = k == 0 ? 12.0f : 164.0f;
        glBindTexture(GL_TEXTURE_2D, tex[k]);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0);
        glVertex2f(x0, 40);
        glTexCoord2f(1, 0);
        glVertex2f(x0 + 144, 40);
        glTexCoord2f(1, 1);
        glVertex2f(x0 + 144, 184);
        glTexCoord2f(0, 1);
        glVertex2f(x0, 184);
        glEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
