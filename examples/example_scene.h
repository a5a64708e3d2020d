/* example_scene.h: the README example's scene, drawn with the raygl* twins of the
 * GL calls: a cube, a sphere and a cone on a checkered floor, lit by one
 * directional light and GL's default global ambient. GL draws no shadows;
 * the ray-traced frame has them (raygl2pov's default). examples/cube.c
 * draws it in a GLUT window; tests/programs/example_scene.c draws one frame
 * with OSMesa, for the image test and the docs' pictures
 * (tools/make-doc-images.sh).
 */
#ifndef RAYGL_EXAMPLE_SCENE_H
#define RAYGL_EXAMPLE_SCENE_H

#include <raygl.h>

/* A unit cube centred on the origin, one colour per face, face normals. */
static void example_cube(void)
{
    static const GLfloat p[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6},
                                    {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    static const GLfloat normals[6][3] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0},
                                          {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    static const GLfloat colors[6][3] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f},
                                         {0.2f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f},
                                         {0.8f, 0.3f, 0.8f}, {0.3f, 0.8f, 0.8f}};
    rayglBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        rayglColor3fv(colors[f]);
        rayglNormal3fv(normals[f]);
        for (int i = 0; i < 4; i++)
            rayglVertex3fv(p[faces[f][i]]);
    }
    rayglEnd();
}

static void example_floor(void)
{
    rayglNormal3f(0, 1, 0);
    rayglBegin(GL_QUADS);
    for (int i = -4; i < 4; i++)
        for (int j = -4; j < 4; j++) {
            float c = ((i + j) & 1) ? 0.85f : 0.4f;
            rayglColor3f(c, c, c);
            rayglVertex3f((float)i, -1.0f, (float)j);
            rayglVertex3f((float)i, -1.0f, (float)j + 1);
            rayglVertex3f((float)i + 1, -1.0f, (float)j + 1);
            rayglVertex3f((float)i + 1, -1.0f, (float)j);
        }
    rayglEnd();
}

/* Frame `frame` of the animation (the cube turns) in a w x h viewport. */
static void example_draw(int frame, int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(45, (double)w / (h ? h : 1), 0.5, 50);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    raygluLookAt(0, 3.2, 7.5, 0, -0.3, 0, 0, 1, 0);

    rayglClearColor(0.15f, 0.15f, 0.25f, 1);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglEnable(GL_DEPTH_TEST);
    rayglShadeModel(GL_SMOOTH);

    /* A directional light from the upper left, in world
     * coordinates (set after gluLookAt); white highlights. */
    rayglEnable(GL_LIGHTING);
    const GLfloat dir[4] = {-1.0f, 0.9f, 0.35f, 0.0f};
    rayglLightfv(GL_LIGHT0, GL_POSITION, dir);
    rayglEnable(GL_LIGHT0);
    const GLfloat spec[4] = {0.5f, 0.5f, 0.5f, 1};
    rayglMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    rayglMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 40);
    /* glColor sets the ambient and diffuse colours. */
    rayglEnable(GL_COLOR_MATERIAL);

    example_floor();

    rayglPushMatrix();
    rayglTranslatef(-1.6f, -0.3f, 0.2f);
    rayglRotatef(20.0f + 25.0f * (float)frame, 0, 1, 0);
    rayglScalef(0.7f, 0.7f, 0.7f);
    rayglEnable(GL_NORMALIZE); /* the scale shortens the normals, GL lights them as they are */
    example_cube();
    rayglDisable(GL_NORMALIZE);
    rayglPopMatrix();

    GLUquadric *q = raygluNewQuadric();
    rayglColor3f(0.85f, 0.3f, 0.2f);
    rayglPushMatrix();
    rayglTranslatef(0.6f, -0.1f, 1.1f);
    raygluSphere(q, 0.9, 48, 32);
    rayglPopMatrix();

    rayglColor3f(0.9f, 0.7f, 0.25f);
    rayglPushMatrix();
    rayglTranslatef(1.9f, -1.0f, -1.4f);
    rayglRotatef(-90, 1, 0, 0);
    raygluCylinder(q, 0.7, 0.0, 1.8, 48, 8);
    rayglPopMatrix();
    raygluDeleteQuadric(q);
}

#endif
