/* real_pipes.c: the pipes screensaver: pipes of gluCylinder segments along
 * the axes of a grid, a gluSphere at every bend, each pipe its own shiny
 * colour, growing by two segments a frame (the frames draw the pipes so
 * far, as the saver redraws them). Two lights, local viewer,
 * GL_NORMALIZE. Four frames. */
#include "real.h"

#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    /* Each pipe: a start cell and the axis of each step (0 +x, 1 -x, 2 +y,
     * 3 -y, 4 +z, 5 -z). */
    static const int start[3][3] = {{-2, -1, -1}, {1, 1, -2}, {-1, 2, 1}};
    static const int steps[3][8] = {{0, 0, 2, 2, 4, 0, 3, 4}, {1, 5, 5, 3, 1, 3, 4, 1},
                                    {3, 3, 0, 5, 5, 0, 2, 0}};
    static const GLfloat col[3][4] = {{0.9f, 0.2f, 0.2f, 1}, {0.2f, 0.7f, 0.9f, 1},
                                      {0.9f, 0.8f, 0.2f, 1}};
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(6.01, 5, 9, 0, 0, 0, 0, 1, 0);
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    const GLfloat p0[4] = {5, 8, 6, 1}, p1[4] = {-6, -2, 4, 0}, dim[4] = {0.3f, 0.3f, 0.35f, 1};
    glLightfv(GL_LIGHT0, GL_POSITION, p0);
    glLightfv(GL_LIGHT1, GL_POSITION, p1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, dim);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    const GLfloat spec[4] = {0.8f, 0.8f, 0.8f, 1};
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 50);
    GLUquadric *q = gluNewQuadric();
    int n = 2 + 2 * frame;
    for (int p = 0; p < 3; p++) {
        glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, col[p]);
        float c[3] = {(float)start[p][0], (float)start[p][1], (float)start[p][2]};
        for (int s = 0; s < n; s++) {
            int a = steps[p][s];
            glPushMatrix();
            glTranslatef(c[0], c[1], c[2]);
            gluSphere(q, 0.3, 20, 14);
            /* gluCylinder runs along +z: turn it onto the step's axis. */
            static const float rot[6][4] = {{90, 0, 1, 0}, {-90, 0, 1, 0}, {-90, 1, 0, 0},
                                            {90, 1, 0, 0},  {0, 0, 0, 1},  {180, 0, 1, 0}};
            glRotatef(rot[a][0], rot[a][1], rot[a][2], rot[a][3]);
            gluCylinder(q, 0.2, 0.2, 1.0, 20, 1);
            glPopMatrix();
            c[a / 2] += a % 2 ? -1.0f : 1.0f;
        }
    }
    gluDeleteQuadric(q);
}

RGL_REAL_MAIN(draw, 4)
