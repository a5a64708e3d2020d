/* texcopy_depth.c: depth textures (GL 1.4 ARB_depth_texture). A 4 x 4
 * GL_DEPTH_COMPONENT texture of float depths, drawn as luminance (the
 * default GL_DEPTH_TEXTURE_MODE), then, after GL_DEPTH_TEXTURE_MODE
 * GL_ALPHA, modulating a coloured quad by its alpha with blending.
 */
#include "harness.h"
#include "texcopy_scene.h"

static int draw(int w, int h)
{
    texcopy_view(w, h);
    GLfloat depth[16];
    for (int i = 0; i < 16; i++)
        depth[i] = (float)((i * 7) % 16) / 15.0f;
    texcopy_texture(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 depth);
    glEnable(GL_TEXTURE_2D);
    texcopy_quad(10, 30, 150, 210, 0, 0, 1, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor3f(1.0f, 0.8f, 0.2f);
    texcopy_quad(170, 30, 310, 210, 0, 0, 1, 1);
    return 0;
}

RGL_TEST_MAIN(draw)
