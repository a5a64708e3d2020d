/* lights_list_color_material.c: glColorMaterial inside a display list and
 * with vertex arrays. Top row: a list that enables GL_COLOR_MATERIAL
 * (GL_AMBIENT_AND_DIFFUSE), draws a quad with a colour per vertex, and a
 * second quad after glColorMaterial(GL_FRONT, GL_DIFFUSE); called once.
 * Bottom row: the same quads from client arrays (glColorPointer,
 * glNormalPointer, glVertexPointer, glDrawArrays), the first directly,
 * the second compiled into a list.
 */
#include "lights_conform.h"

static GLfloat verts[2][4][3], cols[4][4], norms[4][3];

static void quad_arrays(int q)
{
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, verts[q]);
    glNormalPointer(GL_FLOAT, 0, norms);
    glColorPointer(4, GL_FLOAT, 0, cols);
    glDrawArrays(GL_QUADS, 0, 4);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_NORMAL_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
}

static int draw(int w, int h)
{
    conform_begin(w, h);
    GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    for (int k = 0; k < 4; k++) {
        memcpy(cols[k], conform_colours[k], sizeof cols[k]);
        norms[k][0] = norms[k][1] = 0;
        norms[k][2] = 1;
    }
    GLuint list = glGenLists(2);
    glNewList(list, GL_COMPILE);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    float p[3];
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    for (int k = 0; k < 4; k++) {
        glColor4fv(conform_colours[k]);
        conform_corner(k, -2.0f, 0.2f, 1.4f, p);
        glVertex3fv(p);
    }
    glEnd();
    glColorMaterial(GL_FRONT, GL_DIFFUSE);
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glColor4fv(conform_colours[3 - k]);
        conform_corner(k, 0.4f, 0.2f, 1.4f, p);
        glVertex3fv(p);
    }
    glEnd();
    glDisable(GL_COLOR_MATERIAL);
    glEndList();
    glCallList(list);

    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    for (int q = 0; q < 2; q++)
        for (int k = 0; k < 4; k++)
            conform_corner(k, q ? 0.4f : -2.0f, -1.6f, 1.4f, verts[q][k]);
    glColorMaterial(GL_FRONT, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    quad_arrays(0);
    glNewList(list + 1, GL_COMPILE);
    quad_arrays(1);
    glEndList();
    glCallList(list + 1);
    glDisable(GL_COLOR_MATERIAL);
    return 0;
}

RGL_TEST_MAIN(draw)
