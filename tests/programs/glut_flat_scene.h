/* glut_flat_scene.h: the scene of the GL_FLAT GLUT tests (glut_lit_flat,
 * glut_lit_flat_shapes): four cells, one directional light, materials
 * with no specular, so that each face's colour is constant in POV-Ray as
 * in GL. Include after the GL headers. */
#ifndef RGL_GLUT_FLAT_SCENE_H
#define RGL_GLUT_FLAT_SCENE_H

/* Clears, sets the camera and the light, GL_FLAT. */
static void flat_scene_begin(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45.0, (double)w / (double)h, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glShadeModel(GL_FLAT);
    GLfloat dir[4] = {1.0f, 1.5f, 2.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, dir);
    glEnable(GL_LIGHT0);
}

/* Places cell k of a 2 x 2 grid, turned to show its top, with a material
 * of diffuse colour (r, g, b). */
static void flat_cell(int k, float r, float g, float b)
{
    glLoadIdentity();
    glTranslatef(-1.6f + 3.2f * (float)(k % 2), 1.2f - 2.4f * (float)(k / 2), -8.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-30.0f, 0.0f, 1.0f, 0.0f);
    GLfloat diffuse[4] = {r, g, b, 1.0f}, ambient[4] = {0.3f * r, 0.3f * g, 0.3f * b, 1.0f};
    GLfloat none[4] = {0.0f, 0.0f, 0.0f, 1.0f};
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, ambient);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, none);
}

#endif
