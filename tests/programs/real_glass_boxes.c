/* real_glass_boxes.c: rows of translucent frosted-glass boxes over a lit
 * floor (issue 22, "the frame budget cuts real programs"), two frames.
 *
 * One 256 x 256 RGBA texture (its alpha from 0.3 to 0.8), mipmapped by
 * gluBuild2DMipmaps, modulated over each box's colour and blended
 * (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA) over an opaque floor; a box is a
 * display list of six faces, each its own GL_QUADS, as glutSolidCube
 * draws one, called 300 times a frame. Back faces are culled and the
 * boxes lie apart on the screen, so every pixel blends at most one face
 * over the floor: GL's order of blending does not matter.
 *
 * Before issue 22 every face charged the texture's 349,524 bytes of
 * levels against the frame's texture budget again: the frame was cut
 * after about 770 faces and lost its last 170 boxes. */
#include <math.h>

#include "real.h"

#include <raygl/gl.h>

enum { NX = 20, NY = 15, TEX = 256 };

static GLuint box_list, tex;

static void face(const float n[3], const float c[4][3])
{
    static const float uv[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    glBegin(GL_QUADS);
    glNormal3fv(n);
    for (int k = 0; k < 4; k++) {
        glTexCoord2fv(uv[k]);
        glVertex3fv(c[k]);
    }
    glEnd();
}

static void box(void)
{
    const float s = 0.5f;
    const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const float c[6][4][3] = {
        {{s, -s, s}, {s, -s, -s}, {s, s, -s}, {s, s, s}},
        {{-s, -s, -s}, {-s, -s, s}, {-s, s, s}, {-s, s, -s}},
        {{-s, s, s}, {s, s, s}, {s, s, -s}, {-s, s, -s}},
        {{-s, -s, -s}, {s, -s, -s}, {s, -s, s}, {-s, -s, s}},
        {{-s, -s, s}, {s, -s, s}, {s, s, s}, {-s, s, s}},
        {{s, -s, -s}, {-s, -s, -s}, {-s, s, -s}, {s, s, -s}},
    };
    for (int f = 0; f < 6; f++)
        face(n[f], c[f]);
}

/* Frosted glass: a soft diagonal ripple in colour and alpha, a bright
 * frame at the edges. */
static void glass(void)
{
    static GLubyte px[TEX][TEX][4];
    for (int y = 0; y < TEX; y++)
        for (int x = 0; x < TEX; x++) {
            double u = (x + 0.5) / TEX, v = (y + 0.5) / TEX;
            double ripple = 0.5 + 0.5 * sin(2 * M_PI * (3 * u + 2 * v));
            double edge = fmin(fmin(u, 1 - u), fmin(v, 1 - v)) < 0.08 ? 1 : 0;
            GLubyte *p = px[y][x];
            p[0] = (GLubyte)(200 + 55 * edge);
            p[1] = (GLubyte)(220 + 35 * ripple * (1 - edge) + 35 * edge);
            p[2] = 255;
            p[3] = (GLubyte)(255 * (edge ? 0.8 : 0.3 + 0.3 * ripple));
        }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGBA, TEX, TEX, GL_RGBA, GL_UNSIGNED_BYTE, px);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void draw(int frame, int w, int h)
{
    if (frame == 0) {
        glass();
        box_list = glGenLists(1);
        glNewList(box_list, GL_COMPILE);
        box();
        glEndList();
    }
    glViewport(0, 0, w, h);
    glClearColor(0.1f, 0.1f, 0.12f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-10, 10, -7.5, 7.5, -20, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, 0);

    /* The floor: an opaque lit quad behind the boxes. */
    const GLfloat pos[4] = {0.2f, 0.4f, 1, 0}, grey[4] = {0.55f, 0.5f, 0.45f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    glNormal3f(0, 0, 1);
    glBegin(GL_QUADS);
    glVertex3f(-10, -7.5f, -15);
    glVertex3f(10, -7.5f, -15);
    glVertex3f(10, 7.5f, -15);
    glVertex3f(-10, 7.5f, -15);
    glEnd();
    glDisable(GL_LIGHTING);

    /* The boxes, unlit, each in its own colour. */
    glEnable(GL_CULL_FACE);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    for (int y = 0; y < NY; y++)
        for (int x = 0; x < NX; x++) {
            int n = y * NX + x;
            glColor4f(0.5f + 0.5f * (float)(n % 3) / 2, 0.5f + 0.5f * (float)(n % 5) / 4,
                      0.5f + 0.5f * (float)(n % 4) / 3, 1);
            glPushMatrix();
            glTranslatef(-9.5f + (float)x, -7.0f + (float)y, 0);
            glRotatef(30 + 10.0f * (float)frame, 0, 1, 0);
            glRotatef(25, 1, 0, 0);
            glScalef(0.45f, 0.45f, 0.45f);
            glCallList(box_list);
            glPopMatrix();
        }
}

RGL_REAL_MAIN(draw, 2)
