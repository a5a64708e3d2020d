/* snaptex_ext.c: the EXT names of the texture calls, which are recorded as
 * rows of their own and must draw as the core names do (texcopy_copy's
 * render to texture, texcopy_tex3d's slices): glBindTextureEXT,
 * glCopyTexImage2DEXT, glCopyTexSubImage2DEXT, glTexSubImage2DEXT,
 * glTexImage3DEXT, glTexSubImage3DEXT, glBlendEquationEXT; and the EXT
 * array draws (glDrawArraysEXT, glDrawRangeElementsEXT,
 * glMultiDrawArraysEXT, glMultiDrawElementsEXT, glArrayElementEXT), one
 * 3D-textured quad each. Texels magnified with GL_NEAREST and GL_REPLACE.
 */
#include "harness.h"
#include "texcopy_scene.h"

static void rect(float x0, float y0, float x1, float y1, float r, float g, float b)
{
    glColor3f(r, g, b);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
}

static void quad3(float x0, float y0, float x1, float y1, float r)
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
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    rect(16, 16, 20, 20, 0.9f, 0.2f, 0.1f);
    rect(20, 16, 24, 20, 0.1f, 0.8f, 0.2f);
    rect(16, 20, 20, 24, 0.2f, 0.3f, 0.9f);
    rect(20, 20, 24, 24, 0.95f, 0.9f, 0.2f);
    rect(40, 40, 43, 43, 0.1f, 0.9f, 0.9f);
    glEnd();

    GLuint tex[2];
    glGenTextures(2, tex);
    glBindTextureEXT(GL_TEXTURE_2D, tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glCopyTexImage2DEXT(GL_TEXTURE_2D, 0, GL_RGB, 16, 16, 8, 8, 0);
    glCopyTexSubImage2DEXT(GL_TEXTURE_2D, 0, 0, 5, 40, 40, 3, 3);
    static const unsigned char patch[2][2][3] = {{{250, 250, 250}, {10, 10, 10}},
                                                 {{10, 10, 10}, {250, 250, 250}}};
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2DEXT(GL_TEXTURE_2D, 0, 5, 0, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, patch);

    unsigned char vox[2][3][3][3];
    for (int z = 0; z < 2; z++)
        for (int y = 0; y < 3; y++)
            for (int x = 0; x < 3; x++) {
                vox[z][y][x][0] = (unsigned char)(z ? 230 - 60 * x : 30 + 60 * y);
                vox[z][y][x][1] = (unsigned char)((x + y + z) % 2 ? 200 : 40);
                vox[z][y][x][2] = (unsigned char)(z ? 40 + 70 * y : 220 - 70 * x);
            }
    static const unsigned char slab[3] = {240, 120, 0};
    glBindTextureEXT(GL_TEXTURE_3D, tex[1]);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage3DEXT(GL_TEXTURE_3D, 0, GL_RGB, 3, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, vox);
    glTexSubImage3DEXT(GL_TEXTURE_3D, 0, 1, 1, 1, 1, 1, 1, GL_RGB, GL_UNSIGNED_BYTE, slab);

    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBlendEquationEXT(GL_FUNC_ADD);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glBindTextureEXT(GL_TEXTURE_2D, tex[0]);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex2f(12, 40);
    glTexCoord2f(1, 0);
    glVertex2f(156, 40);
    glTexCoord2f(1, 1);
    glVertex2f(156, 184);
    glTexCoord2f(0, 1);
    glVertex2f(12, 184);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_3D);
    quad3(166, 20, 310, 110, 0.25f);
    /* Five quads from one array, each drawn by an EXT draw. */
    static GLfloat v[5][4][2], tc[5][4][3];
    for (int q = 0; q < 5; q++) {
        float x0 = 166 + 29.0f * (float)q, x1 = x0 + 26;
        const float xy[4][2] = {{x0, 130}, {x1, 130}, {x1, 220}, {x0, 220}};
        const float st[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 4; k++) {
            v[q][k][0] = xy[k][0];
            v[q][k][1] = xy[k][1];
            tc[q][k][0] = st[k][0];
            tc[q][k][1] = st[k][1];
            tc[q][k][2] = q % 2 ? 0.25f : 0.75f;
        }
    }
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, v);
    glTexCoordPointer(3, GL_FLOAT, 0, tc);
    glDrawArraysEXT(GL_QUADS, 0, 4);
    static const GLushort idx1[4] = {4, 5, 6, 7};
    glDrawRangeElementsEXT(GL_QUADS, 4, 7, 4, GL_UNSIGNED_SHORT, idx1);
    const GLint first[1] = {8};
    const GLsizei count[1] = {4};
    glMultiDrawArraysEXT(GL_QUADS, first, count, 1);
    static const GLuint idx3[4] = {12, 13, 14, 15};
    const void *const idxs[1] = {idx3};
    glMultiDrawElementsEXT(GL_QUADS, count, GL_UNSIGNED_INT, idxs, 1);
    glBegin(GL_QUADS);
    for (int k = 16; k < 20; k++)
        glArrayElementEXT(k);
    glEnd();
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    return 0;
}

RGL_TEST_MAIN(draw)
