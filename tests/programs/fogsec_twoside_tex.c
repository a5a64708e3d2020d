/* fogsec_twoside_tex.c: lit_two_sided.c's bowl and tube, textured
 * (GL_MODULATE, object-linear texgen) with GL_SEPARATE_SPECULAR_COLOR:
 * GL textures both sides and adds the specular term after the texture.
 * Grey materials, a lighter one in front (a coloured material under
 * GL_MODULATE is another matter: issue 14). */
#include <GL/gl.h>

static void fogsec_texture(void);
static void fogsec_grey(void);
#define LIT_TWO_SIDED_EXTRA fogsec_texture()
#define LIT_TWO_SIDED_MATERIALS fogsec_grey()
#include "lit_two_sided.c"

static void fogsec_grey(void)
{
    GLfloat fd[4] = {0.8f, 0.8f, 0.8f, 1.0f}, bd[4] = {0.45f, 0.45f, 0.45f, 1.0f};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, fd);
    glMaterialfv(GL_BACK, GL_AMBIENT_AND_DIFFUSE, bd);
}

static void fogsec_texture(void)
{
    static GLubyte tex[8][8][3];
    for (int y = 0; y < 8; y++)
        for (int x = 0; x < 8; x++) {
            GLubyte v = (GLubyte)((x + y) % 2 ? 255 : 110);
            tex[y][x][0] = v;
            tex[y][x][1] = v;
            tex[y][x][2] = (GLubyte)((x + y) % 2 ? 255 : 180);
        }
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 8, 0, GL_RGB, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    GLfloat sp[4] = {1.5f, 0.0f, 0.0f, 0.0f}, tp[4] = {0.0f, 1.5f, 0.0f, 0.0f};
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, tp);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_2D);
}
