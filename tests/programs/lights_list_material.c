/* lights_list_material.c: glMaterial between the vertices of a primitive,
 * compiled into a display list and called twice (top and middle rows), and
 * drawn directly (bottom row): a quad whose four vertices have four
 * GL_DIFFUSE colours, a quad whose vertices change GL_AMBIENT_AND_DIFFUSE,
 * and two quads of one glBegin(GL_QUADS) with a material change between
 * them. GL lights each vertex with the material current at it.
 */
#include "lights_conform.h"

static void material_quads(void)
{
    float p[3];
    glBegin(GL_QUADS);
    glNormal3f(0, 0, 1);
    for (int k = 0; k < 4; k++) {
        glMaterialfv(GL_FRONT, GL_DIFFUSE, conform_colours[k]);
        conform_corner(k, -2.6f, 0.1f, 1.1f, p);
        glVertex3fv(p);
    }
    glEnd();
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, conform_colours[3 - k]);
        conform_corner(k, -1.3f, 0.1f, 1.1f, p);
        glVertex3fv(p);
    }
    glEnd();
    glBegin(GL_QUADS);
    GLfloat grey[4] = {0.6f, 0.6f, 0.6f, 1};
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, grey);
    for (int k = 0; k < 4; k++) {
        conform_corner(k, 0.0f, 0.1f, 1.1f, p);
        glVertex3fv(p);
    }
    glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, conform_colours[2]);
    for (int k = 0; k < 4; k++) {
        conform_corner(k, 1.3f, 0.1f, 1.1f, p);
        glVertex3fv(p);
    }
    glEnd();
}

static int draw(int w, int h)
{
    conform_begin(w, h);
    GLuint list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    material_quads();
    glEndList();
    glPushMatrix();
    glTranslatef(0.0f, 0.6f, 0.0f);
    glCallList(list);
    glTranslatef(0.0f, -1.3f, 0.0f);
    glCallList(list);
    glTranslatef(0.0f, -1.3f, 0.0f);
    material_quads();
    glPopMatrix();
    return 0;
}

RGL_TEST_MAIN(draw)
