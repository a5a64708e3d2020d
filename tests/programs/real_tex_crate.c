/* real_tex_crate.c: the classic textured-crate lesson: a cube with a
 * mipmapped 64 x 64 wood-like texture (gluBuild2DMipmaps,
 * GL_LINEAR_MIPMAP_NEAREST), GL_MODULATE under one positional light with
 * ambient, turning frame by frame; in frame 2 and 3 a second, translucent
 * glass cube (GL_SRC_ALPHA, GL_ONE, depth writes off) beside it, as the
 * lesson's blending key turns it on. Five frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

static void cube(void)
{
    static const float n[6][3] = {{0, 0, 1}, {0, 0, -1}, {0, 1, 0}, {0, -1, 0}, {1, 0, 0}, {-1, 0, 0}};
    static const float v[6][4][3] = {
        {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}},
        {{-1, -1, -1}, {-1, 1, -1}, {1, 1, -1}, {1, -1, -1}},
        {{-1, 1, -1}, {-1, 1, 1}, {1, 1, 1}, {1, 1, -1}},
        {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1}},
        {{1, -1, -1}, {1, 1, -1}, {1, 1, 1}, {1, -1, 1}},
        {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, 1}, {-1, 1, -1}}};
    static const float t[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    glBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        glNormal3fv(n[f]);
        for (int k = 0; k < 4; k++) {
            glTexCoord2fv(t[k]);
            glVertex3fv(v[f][k]);
        }
    }
    glEnd();
}

static void draw(int frame, int w, int h)
{
    static GLuint tex;
    if (frame == 0) {
        static GLubyte img[64][64][3];
        for (int y = 0; y < 64; y++)
            for (int x = 0; x < 64; x++) {
                float g = 0.5f + 0.5f * sinf(0.35f * (float)x + 2.0f * sinf(0.11f * (float)y));
                int edge = x < 4 || y < 4 || x > 59 || y > 59;
                img[y][x][0] = (GLubyte)(edge ? 90 : 150 + 70 * g);
                img[y][x][1] = (GLubyte)(edge ? 60 : 100 + 50 * g);
                img[y][x][2] = (GLubyte)(edge ? 30 : 50 + 20 * g);
            }
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 64, 64, GL_RGB, GL_UNSIGNED_BYTE, img);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    }
    glViewport(0, 0, w, h);
    glClearColor(0.0f, 0.0f, 0.0f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 0.1, 100);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const GLfloat amb[4] = {0.5f, 0.5f, 0.5f, 1}, dif[4] = {1, 1, 1, 1}, pos[4] = {0, 0, 2, 1};
    glLightfv(GL_LIGHT1, GL_AMBIENT, amb);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, dif);
    glLightfv(GL_LIGHT1, GL_POSITION, pos);
    glEnable(GL_LIGHT1);
    glEnable(GL_LIGHTING);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPushMatrix();
    glTranslatef(-1.2f, 0.0013f, -7.0f);
    glRotatef(20.0f + 12.0f * (float)frame, 1, 0, 0);
    glRotatef(30.0f + 17.0f * (float)frame, 0, 1, 0);
    cube();
    glPopMatrix();
    if (frame == 2 || frame == 3) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE);
        glDepthMask(GL_FALSE);
        glColor4f(1, 1, 1, 0.5f);
        glEnable(GL_COLOR_MATERIAL);
        glPushMatrix();
        glTranslatef(1.6f, 0.0013f, -7.5f);
        glRotatef(-25.0f + 12.0f * (float)frame, 1, 1, 0);
        cube();
        glPopMatrix();
        glDisable(GL_COLOR_MATERIAL);
        glDepthMask(GL_TRUE);
        glDisable(GL_BLEND);
    }
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_LIGHTING);
    glDepthFunc(GL_LESS);
}

RGL_REAL_MAIN(draw, 5)
