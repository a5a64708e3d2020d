/* texcopy_scene.h: the scene of the texcopy_* texture image tests: an
 * orthographic 320 x 240 view and quads textured with GL_REPLACE and
 * GL_NEAREST, so each texel shows as a block of one colour.
 */
#ifndef RGL_TEXCOPY_SCENE_H
#define RGL_TEXCOPY_SCENE_H

#include <raygl/gl.h>

static inline void texcopy_view(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 320, 0, 240, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.13f, 0.37f, 0.0f);
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
}

/* A new texture bound to target, nearest filtering. */
static inline GLuint texcopy_texture(GLenum target)
{
    GLuint name;
    glGenTextures(1, &name);
    glBindTexture(target, name);
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    return name;
}

/* A quad from (x0, y0) to (x1, y1), texture coordinates s0..s1, t0..t1. */
static inline void texcopy_quad(float x0, float y0, float x1, float y1, float s0, float t0,
                                float s1, float t1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(s0, t0);
    glVertex2f(x0, y0);
    glTexCoord2f(s1, t0);
    glVertex2f(x1, y0);
    glTexCoord2f(s1, t1);
    glVertex2f(x1, y1);
    glTexCoord2f(s0, t1);
    glVertex2f(x0, y1);
    glEnd();
}

#endif
