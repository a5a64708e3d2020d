/* tex_1d.c: a 1D texture (16 texels, GL_LUMINANCE_ALPHA bytes with
 * GL_LUMINANCE internal format, then a GL_RGB float one) on two quads,
 * nearest filtering, repeat and clamp. */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    GLubyte la[16 * 2];
    for (int i = 0; i < 16; i++) {
        la[2 * i] = (GLubyte)(i * 16 + 8);
        la[2 * i + 1] = 255;
    }
    GLfloat rgb[16 * 3];
    for (int i = 0; i < 16; i++) {
        rgb[3 * i] = (float)i / 15;
        rgb[3 * i + 1] = (float)((i * 7) % 16) / 15;
        rgb[3 * i + 2] = 1 - (float)i / 15;
    }
    GLuint names[2];
    rayglGenTextures(2, names);
    rayglBindTexture(GL_TEXTURE_1D, names[0]);
    rayglTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 16, 0, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
    rayglTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglBindTexture(GL_TEXTURE_1D, names[1]);
    rayglTexImage1D(GL_TEXTURE_1D, 0, GL_RGB, 16, 0, GL_RGB, GL_FLOAT, rgb);
    rayglTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    rayglEnable(GL_TEXTURE_1D);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    for (int k = 0; k < 2; k++) {
        rayglBindTexture(GL_TEXTURE_1D, names[k]);
        float y0 = k ? 130.0f : 20.0f, y1 = y0 + 90;
        rayglBegin(GL_QUADS);
        rayglColor3f(1, 1, 1);
        rayglTexCoord1f(-0.3f);
        rayglVertex2f(20, y0);
        rayglColor3f(1, 0.7f, 0.4f);
        rayglTexCoord1f(1.4f);
        rayglVertex2f(300, y0);
        rayglTexCoord1f(1.4f);
        rayglVertex2f(300, y1);
        rayglColor3f(1, 1, 1);
        rayglTexCoord1f(-0.3f);
        rayglVertex2f(20, y1);
        rayglEnd();
    }
    return 0;
}

RGL_TEST_MAIN(draw)
