/* cmat_raster.c: glRasterPos under lighting with colour material enabled
 * after a glMaterial (docs/mapping.md section 32). Mesa lights the raster
 * position from its state flushed as a draw flushes it: a glColor between
 * the glEnable and the glRasterPos that changed the colour is copied into
 * the material first (the red block), the material kept where none came
 * (the green one), and after the glRasterPos a glColor is copied at once
 * (the blue block, and the sphere drawn after it). Large solid bitmaps
 * at 3D raster positions over the lit pair; local viewer.
 */
#include "lit_scene.h"

#define SIDE 40

static GLubyte block[SIDE * SIDE / 8];

static void square(float x, float y)
{
    glNormal3f(0.0f, 0.0f, 1.0f);
    glRasterPos3f(x, y, -4.5f);
    glBitmap(SIDE, SIDE, 0.0f, 0.0f, 0.0f, 0.0f, block);
}

static int draw(int w, int h)
{
    for (size_t i = 0; i < sizeof block; i++)
        block[i] = 0xff;
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {0.4f, 0.7f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    lit_material(0.45f, 0.45f, 0.45f, 0.2f, 20.0f);
    glEnable(GL_COLOR_MATERIAL);
    glColor3f(0.9f, 0.15f, 0.1f);
    square(-1.5f, 1.0f);
    glDisable(GL_COLOR_MATERIAL);

    lit_material(0.25f, 0.7f, 0.3f, 0.2f, 20.0f);
    glEnable(GL_COLOR_MATERIAL);
    square(-0.4f, 1.0f);
    glColor3f(0.2f, 0.35f, 0.95f);
    square(0.7f, 1.0f);
    lit_sphere(-0.95f, -0.2f, -5.0f, 0.75f);
    glDisable(GL_COLOR_MATERIAL);

    lit_material(0.6f, 0.5f, 0.3f, 0.4f, 30.0f);
    lit_torus(1.0f, -0.3f, -5.2f, 0.62f, 0.26f, 0.3f, 0.8f, 0.55f);
    return 0;
}

RGL_TEST_MAIN(draw)
