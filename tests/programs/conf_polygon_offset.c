/* conf_polygon_offset.c: glPolygonOffset with GL_POLYGON_OFFSET_FILL on
 * coplanar faces. A slanted floor in perspective, then decals in its plane
 * drawn after it under GL_LESS: with glPolygonOffset(-1, -1) they are
 * pulled toward the eye and show whole; with glPolygonOffset(1, 1) pushed
 * back, hidden. A second floor drawn offset (2, 2), then its decal with no
 * offset: the decal shows. (A decal with no offset on a floor with none
 * ties with it: left out, as either renderer may show either.) Unlit. */
#include "harness.h"

#include <raygl/gl.h>

static void quad(float x0, float z0, float x1, float z1, float y)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y, z0);
    glVertex3f(x1, y, z0);
    glVertex3f(x1, y, z1);
    glVertex3f(x0, y, z1);
    glEnd();
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, 0.0017f, 0.0f);
    gluLookAt(0.0, 3.0, 4.0, 0.0, 0.0, -3.0, 0.0, 1.0, 0.0);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glColor3f(0.5f, 0.5f, 0.5f);
    quad(-4.0f, 1.0f, -0.2f, -8.0f, 0.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -1.0f);
    glColor3f(0.9f, 0.3f, 0.2f);
    quad(-3.5f, 0.0f, -2.2f, -2.0f, 0.0f);
    glColor3f(0.2f, 0.8f, 0.3f);
    quad(-1.9f, -3.0f, -0.6f, -6.5f, 0.0f);
    glPolygonOffset(1.0f, 1.0f);
    glColor3f(0.9f, 0.9f, 0.1f);
    quad(-3.5f, -3.0f, -2.2f, -6.0f, 0.0f);

    glPolygonOffset(2.0f, 2.0f);
    glColor3f(0.4f, 0.4f, 0.6f);
    quad(0.2f, 1.0f, 4.0f, -8.0f, 0.0f);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColor3f(0.3f, 0.6f, 0.9f);
    quad(0.8f, -0.5f, 3.2f, -4.0f, 0.0f);
    return 0;
}

RGL_TEST_MAIN(draw)
