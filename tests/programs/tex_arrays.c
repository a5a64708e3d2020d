/* tex_arrays.c: texture coordinates from a vertex array (glDrawArrays and
 * glDrawElements), with textures whose pixels need the unpack state: an
 * RGB image 5 texels wide at GL_UNPACK_ALIGNMENT 1, and one cut out of a
 * larger client image with GL_UNPACK_ROW_LENGTH, SKIP_ROWS and
 * SKIP_PIXELS at alignment 4; a glTexSubImage2D patch on top. */
#include "harness.h"
#include "tex_scene.h"

static int draw(int w, int h)
{
    tex_view(w, h);
    GLuint names[2];
    rayglGenTextures(2, names);

    /* 5 x 5 RGB, rows of 15 bytes: only right at alignment 1. */
    GLubyte odd[5 * 5 * 3];
    for (int i = 0; i < 25; i++) {
        odd[3 * i] = (GLubyte)(40 * (i % 5) + 20);
        odd[3 * i + 1] = (GLubyte)(40 * (i / 5) + 30);
        odd[3 * i + 2] = (GLubyte)((i * 53) % 256);
    }
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    rayglBindTexture(GL_TEXTURE_2D, names[0]);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 5, 5, 0, GL_RGB, GL_UNSIGNED_BYTE, odd);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    GLubyte patch[2 * 2 * 3] = {255, 0, 255, 255, 0, 255, 0, 0, 0, 255, 255, 255};
    rayglTexSubImage2D(GL_TEXTURE_2D, 0, 1, 2, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, patch);

    /* 6 x 4 luminance floats cut from a 10 x 8 image at (3, 2). */
    GLfloat big[10 * 8];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 10; x++)
            big[y * 10 + x] = (x >= 3 && x < 9 && y >= 2 && y < 6) ? (float)((x * 3 + y * 5) % 11) / 10
                                                                    : 1.0f;
    rayglPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 10);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 2);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    rayglBindTexture(GL_TEXTURE_2D, names[1]);
    rayglTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 6, 4, 0, GL_LUMINANCE, GL_FLOAT, big);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    rayglTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    rayglPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    rayglPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);

    static const GLfloat pos[8][2] = {{20, 20}, {150, 20}, {150, 220}, {20, 220},
                                      {170, 20}, {300, 20}, {300, 220}, {170, 220}};
    static const GLfloat st[8][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1},
                                     {-0.2f, 0}, {1.2f, 0}, {1.2f, 1.1f}, {-0.2f, 1.1f}};
    rayglEnableClientState(GL_VERTEX_ARRAY);
    rayglEnableClientState(GL_TEXTURE_COORD_ARRAY);
    rayglVertexPointer(2, GL_FLOAT, 0, pos);
    rayglTexCoordPointer(2, GL_FLOAT, 0, st);
    rayglEnable(GL_TEXTURE_2D);
    rayglTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    rayglBindTexture(GL_TEXTURE_2D, names[0]);
    rayglDrawArrays(GL_QUADS, 0, 4);
    rayglBindTexture(GL_TEXTURE_2D, names[1]);
    static const GLushort idx[6] = {4, 5, 6, 4, 6, 7};
    rayglDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, idx);
    rayglDisableClientState(GL_VERTEX_ARRAY);
    rayglDisableClientState(GL_TEXTURE_COORD_ARRAY);
    return 0;
}

RGL_TEST_MAIN(draw)
