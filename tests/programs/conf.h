/* conf.h: what the conformance-style programs (conf_*.c) share. Each
 * program probes one GL feature's corner semantics the way a conformance
 * suite does, on flat unlit rectangles in window pixels unless it says
 * otherwise, so that the comparison can be tight (issue 22).
 *
 * Included after <raygl/gl.h>, so the calls here are recorded too. Edges
 * lie a quarter pixel off the pixel grid (conf_box), never through a pixel
 * centre, where GL and POV-Ray break ties apart. */
#ifndef RGL_TEST_CONF_H
#define RGL_TEST_CONF_H

/* The viewport w x h, glOrtho in window pixels with eye z from -1 (far,
 * window depth 1) to 1 (near, window depth 0), identity modelview, the
 * clear colour (r, g, b) and both buffers cleared. */
static inline void conf_pixels(int w, int h, float r, float g, float b)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(r, g, b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

/* The rectangle of pixels x0..x1 - 1, y0..y1 - 1 (edges a quarter pixel
 * inside the pixel grid) at eye z, one GL_QUADS, counter-clockwise. */
static inline void conf_box(int x0, int y0, int x1, int y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f((float)x0 + 0.25f, (float)y0 + 0.25f, z);
    glVertex3f((float)x1 + 0.25f, (float)y0 + 0.25f, z);
    glVertex3f((float)x1 + 0.25f, (float)y1 + 0.25f, z);
    glVertex3f((float)x0 + 0.25f, (float)y1 + 0.25f, z);
    glEnd();
}

#endif
