/* snaptex_frames.c: textures made in frame 0 and only used in frame 1, so
 * that frame 1 translated alone (raygl2pov --frames 1) draws them from the
 * recorder's frame-start snapshot: a rectangle texture left bound and
 * enabled from frame 0 (frame 1 neither binds nor enables it), and a 3D
 * texture frame 1 binds by name. GL_REPLACE, GL_NEAREST, texels magnified
 * to blocks (texcopy_scene.h).
 */
#include "real.h"
#include "texcopy_scene.h"

static GLuint rect_tex, vol_tex;

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

static void make_textures(void)
{
    unsigned char px[5][6][3];
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 6; x++) {
            px[y][x][0] = (unsigned char)(40 * x + 20);
            px[y][x][1] = (unsigned char)(50 * y + 10);
            px[y][x][2] = (unsigned char)((x + y) % 2 ? 220 : 60);
        }
    unsigned char vox[2][3][3][3];
    for (int z = 0; z < 2; z++)
        for (int y = 0; y < 3; y++)
            for (int x = 0; x < 3; x++) {
                vox[z][y][x][0] = (unsigned char)(z ? 230 - 60 * x : 30 + 60 * y);
                vox[z][y][x][1] = (unsigned char)((x + y + z) % 2 ? 200 : 40);
                vox[z][y][x][2] = (unsigned char)(z ? 40 + 70 * y : 220 - 70 * x);
            }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    vol_tex = texcopy_texture(GL_TEXTURE_3D);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB, 3, 3, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, vox);
    rect_tex = texcopy_texture(GL_TEXTURE_RECTANGLE_ARB);
    glTexImage2D(GL_TEXTURE_RECTANGLE_ARB, 0, GL_RGB, 6, 5, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    glEnable(GL_TEXTURE_RECTANGLE_ARB);
}

static void draw(int frame, int w, int h)
{
    texcopy_view(w, h);
    if (frame == 0)
        make_textures();
    /* Bound and enabled since frame 0. */
    texcopy_quad(10, 20, 154, 200, 0, 0, 6, 5);
    glDisable(GL_TEXTURE_RECTANGLE_ARB);
    glBindTexture(GL_TEXTURE_3D, vol_tex);
    glEnable(GL_TEXTURE_3D);
    quad3(166, 20, 310, 110, 0.25f);
    quad3(166, 130, 310, 220, 0.75f);
    glDisable(GL_TEXTURE_3D);
    glEnable(GL_TEXTURE_RECTANGLE_ARB); /* as frame 1 finds it */
}

RGL_REAL_MAIN(draw, 2)
