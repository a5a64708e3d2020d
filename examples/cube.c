/* cube.c: the README's example. A GLUT program written with the raygl*
 * twins: a spinning cube with one colour per face over a checkered floor.
 * Each glutSwapBuffers (rayglutSwapBuffers) ends a frame of the trace.
 *
 *   RAYGL_TRACE=cube.raygl ./cube [--frames N]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/freeglut.h>

#include <raygl.h>

static int frames_left = 3;
static int frame;

static void face(const GLfloat color[3], const GLfloat v[4][3])
{
    rayglColor3fv(color);
    for (int i = 0; i < 4; i++)
        rayglVertex3fv(v[i]);
}

static void cube(void)
{
    static const GLfloat p[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int faces[6][4] = {{4, 5, 6, 7}, {1, 0, 3, 2}, {5, 1, 2, 6},
                                    {0, 4, 7, 3}, {7, 6, 2, 3}, {0, 1, 5, 4}};
    static const GLfloat colors[6][3] = {{0.9f, 0.2f, 0.2f}, {0.2f, 0.8f, 0.3f},
                                         {0.2f, 0.4f, 0.9f}, {0.9f, 0.8f, 0.2f},
                                         {0.8f, 0.3f, 0.8f}, {0.3f, 0.8f, 0.8f}};
    rayglBegin(GL_QUADS);
    for (int f = 0; f < 6; f++) {
        GLfloat v[4][3];
        for (int i = 0; i < 4; i++)
            memcpy(v[i], p[faces[f][i]], sizeof v[i]);
        face(colors[f], (const GLfloat(*)[3])v);
    }
    rayglEnd();
}

static void floor_tiles(void)
{
    rayglBegin(GL_QUADS);
    for (int i = -4; i < 4; i++)
        for (int j = -4; j < 4; j++) {
            float c = ((i + j) & 1) ? 0.85f : 0.35f;
            rayglColor3f(c, c, c);
            rayglVertex3f((float)i, -1.5f, (float)j);
            rayglVertex3f((float)i, -1.5f, (float)j + 1);
            rayglVertex3f((float)i + 1, -1.5f, (float)j + 1);
            rayglVertex3f((float)i + 1, -1.5f, (float)j);
        }
    rayglEnd();
}

static void display(void)
{
    rayglClearColor(0.15f, 0.15f, 0.25f, 1);
    rayglClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    raygluLookAt(0, 3, 7, 0, 0, 0, 0, 1, 0);
    floor_tiles();
    rayglRotatef(20.0f + 25.0f * (float)frame, 0, 1, 0);
    rayglRotatef(15, 1, 0, 0);
    cube();
    rayglutSwapBuffers();
    frame++;
    if (--frames_left <= 0) {
        rayglRecordClose();
        exit(rayglRecordStatus() == RAYGL_FAILED ? 1 : 0);
    }
}

static void reshape(int w, int h)
{
    rayglViewport(0, 0, w, h);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluPerspective(45, (double)w / (h ? h : 1), 0.5, 50);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--frames") == 0 && i + 1 < argc) {
            frames_left = atoi(argv[++i]);
        } else {
            fprintf(stderr, "usage: cube [--frames N]\n");
            return 2;
        }
    }
    glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
    glutInitWindowSize(480, 360);
    glutCreateWindow("RayGL cube");
    rayglEnable(GL_DEPTH_TEST);
    glutDisplayFunc(display);
    glutIdleFunc(glutPostRedisplay);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
