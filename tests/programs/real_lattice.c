/* real_lattice.c: a screensaver-style lattice: one mipmapped 256 x 256
 * texture (gluBuild2DMipmaps), sphere-mapped (GL_SPHERE_MAP texgen) with
 * GL_MODULATE on lit tori; the tori of 20 sizes and tilts compiled into 20
 * display lists in frame 0, then called about 450 times a frame across a
 * 3D grid that the camera flies through. One directional light. Three
 * frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static void torus(float R, float r, int slices, int rings)
{
    for (int i = 0; i < slices; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= rings; j++)
            for (int k = 1; k >= 0; k--) {
                double s = 2 * M_PI * (i + k) / slices, t = 2 * M_PI * j / rings;
                double cx = cos(s), cy = sin(s);
                glNormal3d(cos(t) * cx, cos(t) * cy, sin(t));
                glVertex3d((R + r * cos(t)) * cx, (R + r * cos(t)) * cy, r * sin(t));
            }
        glEnd();
    }
}

static void draw(int frame, int w, int h)
{
    static GLuint lists, tex;
    if (frame == 0) {
        static GLubyte img[256][256][3];
        for (int y = 0; y < 256; y++)
            for (int x = 0; x < 256; x++) {
                float u = (float)x / 255.0f - 0.5f, v = (float)y / 255.0f - 0.5f;
                float d = sqrtf(u * u + v * v);
                img[y][x][0] = (GLubyte)(120 + 120 * cosf(18.0f * d));
                img[y][x][1] = (GLubyte)(110 + 100 * sinf(9.0f * u + 4.0f * v));
                img[y][x][2] = (GLubyte)(200 - 150 * d);
            }
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, 256, 256, GL_RGB, GL_UNSIGNED_BYTE, img);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        lists = glGenLists(20);
        for (int i = 0; i < 20; i++) {
            glNewList(lists + (GLuint)i, GL_COMPILE);
            glPushMatrix();
            glRotatef(18.0f * (float)i, 1.0f, 0.3f, 0.0f);
            torus(0.32f + 0.01f * (float)(i % 5), 0.09f + 0.005f * (float)(i % 4), 18, 10);
            glPopMatrix();
            glEndList();
        }
    }
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(60, (double)w / h, 0.3, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const GLfloat pos[4] = {0.3f, 1.0f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    const GLfloat mat[4] = {0.9f, 0.9f, 0.9f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, mat);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_2D);
    glTranslatef(0.0013f, 0.0017f, -1.5f + 0.4f * (float)frame);
    glRotatef(12.0f + 3.0f * (float)frame, 1, 0, 0);
    glRotatef(20.0f, 0, 1, 0);
    int k = 0;
    for (int x = -4; x <= 4; x++)
        for (int y = -3; y <= 3; y++)
            for (int z = -1; z >= -7; z--) {
                glPushMatrix();
                glTranslatef(1.1f * (float)x, 1.1f * (float)y, 1.1f * (float)z);
                glCallList(lists + (GLuint)(k++ % 20));
                glPopMatrix();
            }
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
}

RGL_REAL_MAIN(draw, 3)
