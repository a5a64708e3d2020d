/* conf_point_sprite.c: point sprites. 16-pixel points with GL_POINT_SPRITE
 * and GL_COORD_REPLACE on a 4 x 4 texture of distinct texels (GL_NEAREST,
 * GL_REPLACE): each point shows the whole texture, s left to right and t
 * bottom to top (GL_POINT_SPRITE_COORD_ORIGIN GL_LOWER_LEFT); then the
 * same points without the sprite (the texel at the point's own coordinate,
 * flat). Window pixels. */
#include "harness.h"

#include <raygl/gl.h>

#include "conf.h"

static int draw(int w, int h)
{
    conf_pixels(w, h, 0.1f, 0.1f, 0.15f);
    GLubyte texels[4][4][3];
    for (int y = 0; y < 4; y++)
        for (int x = 0; x < 4; x++) {
            texels[y][x][0] = (GLubyte)(40 + 70 * x);
            texels[y][x][1] = (GLubyte)(230 - 60 * y);
            texels[y][x][2] = (GLubyte)((x + y) % 2 ? 220 : 30);
        }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glPointSize(16.0f);
    glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_LOWER_LEFT);
    glEnable(GL_POINT_SPRITE);
    glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
    glBegin(GL_POINTS);
    for (int i = 0; i < 8; i++) {
        glTexCoord2f(0.1f + 0.1f * (float)i, 0.6f);
        glVertex2f(24.0f + 36.0f * (float)i, 170.0f);
    }
    glEnd();
    glDisable(GL_POINT_SPRITE);
    glBegin(GL_POINTS);
    for (int i = 0; i < 8; i++) {
        glTexCoord2f(0.1f + 0.1f * (float)i, 0.6f);
        glVertex2f(24.0f + 36.0f * (float)i, 70.0f);
    }
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glPointSize(1.0f);
    (void)h;
    return 0;
}

RGL_TEST_MAIN(draw)
