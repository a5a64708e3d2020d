/* lights_conform.h: shared parts of the lighting conformance programs
 * (tests/programs/lights_*.c): a camera as lit_scene.h's, one directional
 * light along the view, and flat quads whose lighting is linear in the
 * material (no specular), so that GL's per-vertex lighting and POV-Ray's
 * per-pixel lighting agree exactly.
 */
#ifndef RGL_TEST_LIGHTS_CONFORM_H
#define RGL_TEST_LIGHTS_CONFORM_H

#include "lit_scene.h"

#include <string.h>

static inline void conform_begin(int w, int h)
{
    lit_begin(w, h);
    GLfloat pos[4] = {0.3f, 0.4f, 1.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    GLfloat zero[4] = {0, 0, 0, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, zero);
}

/* The corners of a quad of size s at (x, y, -6), counter-clockwise. */
static inline void conform_corner(int k, float x, float y, float s, float out[3])
{
    static const float c[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    out[0] = x + s * c[k][0];
    out[1] = y + s * c[k][1];
    out[2] = -6.0f;
}

/* Corner colours bilinear in the quad (c0 + c2 = c1 + c3), so that either
 * diagonal split interpolates them alike. */
static const GLfloat conform_colours[4][4] = {
    {0.8f, 0.2f, 0.2f, 1}, {0.2f, 0.8f, 0.2f, 1}, {0.2f, 0.8f, 0.8f, 1}, {0.8f, 0.2f, 0.8f, 1},
};

#endif
