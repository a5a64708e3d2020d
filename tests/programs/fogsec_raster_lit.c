/* fogsec_raster_lit.c: the raster colour under lighting (issue 13).
 *
 * GL lights the raster position as a vertex (GL 2.1 2.13): glRasterPos
 * with lighting on takes the lit colour of the current normal, material
 * and colour material at that point. A lit sphere, then a row of 24 x 24
 * solid bitmaps placed by glRasterPos3f with lighting still on: normals
 * turning from the light to away from it, a point light whose distance
 * matters, a colour-material row, and one with lighting off (the current
 * colour) for comparison. Drawn with the depth test off, so they lie on
 * top (their depth is another matter: docs/mapping.md section 16).
 */
#include "lit_scene.h"

#include <string.h>

static GLubyte block[24 * 3];

static void mark(float x, float y, float z, float nx, float ny, float nz)
{
    glNormal3f(nx, ny, nz);
    glRasterPos3f(x, y, z);
    glBitmap(24, 24, 12.0f, 12.0f, 0.0f, 0.0f, block);
}

static int draw(int w, int h)
{
    memset(block, 0xff, sizeof block);
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat dir[4] = {0.6f, 0.8f, 0.5f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glEnable(GL_LIGHT0);
    GLfloat point[4] = {1.5f, -1.0f, -4.0f, 1.0f}, red[4] = {0.9f, 0.3f, 0.2f, 1.0f};
    glLightfv(GL_LIGHT1, GL_POSITION, point);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, red);
    glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.6f);
    glEnable(GL_LIGHT1);
    lit_material(0.3f, 0.6f, 0.85f, 0.5f, 20.0f);
    lit_sphere(-1.4f, 0.3f, -6.0f, 0.9f);

    glDisable(GL_DEPTH_TEST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* Top row: the normal turns away from the light. */
    for (int k = 0; k < 5; k++) {
        float a = (float)k * 0.75f;
        mark(0.2f + 0.5f * (float)k, 1.0f, -6.0f, sinf(a), cosf(a), 0.3f);
    }
    /* Middle row: toward the point light, nearer and nearer. */
    lit_material(0.8f, 0.8f, 0.8f, 0.0f, 1.0f);
    for (int k = 0; k < 5; k++)
        mark(0.2f + 0.5f * (float)k, 0.2f, -6.0f + 0.4f * (float)k, 0.0f, -0.3f, 1.0f);
    /* Colour material: the current colour is the diffuse and ambient. */
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glColor3f(0.9f, 0.7f, 0.1f);
    mark(0.4f, -0.6f, -6.0f, 0.3f, 0.6f, 0.8f);
    glColor3f(0.2f, 0.9f, 0.4f);
    mark(1.2f, -0.6f, -6.0f, 0.3f, 0.6f, 0.8f);
    glDisable(GL_COLOR_MATERIAL);
    /* Lighting off: the current colour. */
    glDisable(GL_LIGHTING);
    glColor3f(0.9f, 0.2f, 0.6f);
    mark(2.0f, -0.6f, -6.0f, 0.0f, 0.0f, 1.0f);
    return 0;
}

RGL_TEST_MAIN(draw)
