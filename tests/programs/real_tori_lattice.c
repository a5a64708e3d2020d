/* real_tori_lattice.c: a screensaver-style lattice of shiny tori (issue 22,
 * "the frame budget cuts real programs"), two frames.
 *
 * As an xscreensaver hack sets up once and then draws: the first frame
 * builds 20 display lists, each a torus of its own proportions and
 * colour (quad strips with normals, as glutSolidTorus draws one), and one
 * 256 x 256 environment image mipmapped by gluBuild2DMipmaps
 * (GL_LINEAR_MIPMAP_LINEAR), sphere-mapped (GL_SPHERE_MAP texgen) and
 * modulated over the lit colour; every frame then calls the lists 100
 * times, each torus turned by its own angle. The second frame draws from
 * the lists and texture the first left (carried state).
 *
 * Before issue 22 the translator charged the texture's 349,524 bytes of
 * levels against the frame's texture budget at every one of the 1,000
 * textured strips, so the frame was cut inside a display list after
 * about 770 of them. The hack this follows calls its lists 450 times a
 * frame: 100 calls keep POV-Ray's time for the test near 2 minutes a
 * frame (docs/mapping.md "Bounds"). */
#include <math.h>
#include <stdbool.h>

#include "real.h"

#include <raygl/gl.h>

enum { NLISTS = 20, NX = 10, NY = 5, NZ = 2, RINGS = 10, SIDES = 7, TEX = 256 };

static GLuint base, tex;

/* A torus around z: ring radius R, tube radius r, as freeglut's. */
static void torus(double r, double R)
{
    for (int i = 0; i < RINGS; i++) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= SIDES; j++) {
            for (int k = 0; k <= 1; k++) {
                double phi = 2 * M_PI * (i + k) / RINGS, theta = 2 * M_PI * j / SIDES;
                double cp = cos(phi), sp = sin(phi), ct = cos(theta), st = sin(theta);
                glNormal3d(cp * ct, sp * ct, st);
                glVertex3d(cp * (R + r * ct), sp * (R + r * ct), r * st);
            }
        }
        glEnd();
    }
}

/* A sky over a chequered ground with a bright sun: what a sphere map of
 * a room or a sky looks like, detailed enough that minification shows. */
static void environment(void)
{
    static GLubyte px[TEX][TEX][3];
    for (int y = 0; y < TEX; y++)
        for (int x = 0; x < TEX; x++) {
            double u = (x + 0.5) / TEX * 2 - 1, v = (y + 0.5) / TEX * 2 - 1;
            GLubyte *p = px[y][x];
            if (v > -0.1) { /* sky */
                double sun = exp(-((u - 0.35) * (u - 0.35) + (v - 0.5) * (v - 0.5)) * 40);
                p[0] = (GLubyte)fmin(255, 70 + 60 * v + 185 * sun);
                p[1] = (GLubyte)fmin(255, 110 + 70 * v + 150 * sun);
                p[2] = (GLubyte)fmin(255, 200 + 40 * v + 55 * sun);
            } else { /* ground */
                bool check = ((x / 16) + (y / 16)) % 2 == 0;
                p[0] = check ? 190 : 60;
                p[1] = check ? 170 : 45;
                p[2] = check ? 120 : 35;
            }
        }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gluBuild2DMipmaps(GL_TEXTURE_2D, GL_RGB, TEX, TEX, GL_RGB, GL_UNSIGNED_BYTE, px);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void init(void)
{
    environment();
    base = glGenLists(NLISTS);
    for (int i = 0; i < NLISTS; i++) {
        const GLfloat colour[4] = {0.55f + 0.45f * (float)((i * 7) % 5) / 4,
                                   0.55f + 0.45f * (float)((i * 3) % 4) / 3,
                                   0.55f + 0.45f * (float)((i * 11) % 6) / 5, 1};
        glNewList(base + (GLuint)i, GL_COMPILE);
        glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, colour);
        torus(0.12 + 0.012 * (i % 5), 0.32 + 0.01 * (i % 4));
        glEndList();
    }
}

static void draw(int frame, int w, int h)
{
    if (frame == 0)
        init();
    glViewport(0, 0, w, h);
    glClearColor(0.02f, 0.02f, 0.06f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const GLfloat pos[4] = {0.3f, 0.6f, 1, 0}, white[4] = {1, 1, 1, 1};
    const GLfloat amb[4] = {0.25f, 0.25f, 0.25f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, white);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_SPHERE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_2D);
    glTranslatef(0.0013f, 0.0017f, -11);
    glRotatef(8, 1, 0, 0);
    for (int z = 0; z < NZ; z++)
        for (int y = 0; y < NY; y++)
            for (int x = 0; x < NX; x++) {
                int n = (z * NY + y) * NX + x;
                glPushMatrix();
                glTranslatef(1.2f * ((float)x - (NX - 1) / 2.0f) + 0.6f * (float)z,
                             1.3f * ((float)y - (NY - 1) / 2.0f) + 0.65f * (float)z, -2.5f * (float)z);
                glRotatef(37.0f * (float)(n % 11) + 15.0f * (float)frame, 0.3f, 1, 0.2f);
                glRotatef(23.0f * (float)(n % 7), 1, 0, 0);
                glCallList(base + (GLuint)(n % NLISTS));
                glPopMatrix();
            }
}

RGL_REAL_MAIN(draw, 2)
