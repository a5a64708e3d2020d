/* tex_depth_compare.c: depth-texture comparison (GL 1.4 ARB_shadow, GL 2.1
 * 3.8.14; issue 22). A 4 x 4 GL_DEPTH_COMPONENT texture of depths k/15,
 * none of them within 1/255 of an r below, on quads whose r is constant
 * (glTexCoord3f): GL_COMPARE_R_TO_TEXTURE with GL_LEQUAL at r 0.43
 * (GL_NEAREST, luminance), GL_GEQUAL at r 0.43, GL_LESS at r 0.75 with
 * GL_LINEAR (Mesa filters the four results), and GL_NOTEQUAL under
 * GL_INTENSITY modulating a coloured quad; the last quad without the
 * comparison shows the depths. Unlit, in pixels. */
#define GL_GLEXT_PROTOTYPES 1
#include "harness.h"

#include <raygl/gl.h>
#include <GL/glext.h>

static void quad(float x0, float y0, float x1, float y1, float r)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0, 0, r);
    glVertex2f(x0, y0);
    glTexCoord3f(1, 0, r);
    glVertex2f(x1, y0);
    glTexCoord3f(1, 1, r);
    glVertex2f(x1, y1);
    glTexCoord3f(0, 1, r);
    glVertex2f(x0, y1);
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, 320, 0, 240);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.13f, 0.37f, 0.0f);
    glClearColor(0.2f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    GLfloat depth[16];
    for (int i = 0; i < 16; i++)
        depth[i] = (float)((i * 7) % 16) / 15.0f;
    GLuint names[5];
    glGenTextures(5, names);
    static const GLint func[5] = {GL_LEQUAL, GL_GEQUAL, GL_LESS, GL_NOTEQUAL, 0};
    static const float r[5] = {0.43f, 0.43f, 0.75f, 0.6f, 0.5f};
    glEnable(GL_TEXTURE_2D);
    for (int k = 0; k < 5; k++) {
        glBindTexture(GL_TEXTURE_2D, names[k]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                     depth);
        GLint f = k == 2 ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
        if (func[k]) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, func[k]);
        }
        if (k == 3) {
            glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
            glColor3f(1.0f, 0.7f, 0.2f);
        } else {
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        }
        float x = 6 + 63.0f * k;
        quad(x, 60, x + 56, 180, r[k]);
    }
    return 0;
}

RGL_TEST_MAIN(draw)
