/* cube.c: the README's example. A GLUT program written with the raygl*
 * twins: a lit scene (example_scene.h), a turning cube, a sphere and a cone on a
 * checkered floor under a directional light. Each glutSwapBuffers
 * (rayglutSwapBuffers) ends a frame of the trace.
 *
 *   RAYGL_TRACE=cube.raygl ./cube [--frames N]
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <GL/freeglut.h>

#include <raygl.h>

#include "example_scene.h"

static int frames_left = 3;
static int frame;
static int width = 480, height = 360;

static void display(void)
{
    example_draw(frame, width, height);
    rayglutSwapBuffers();
    frame++;
    if (--frames_left <= 0) {
        rayglRecordClose();
        exit(rayglRecordStatus() == RAYGL_FAILED ? 1 : 0);
    }
}

static void reshape(int w, int h)
{
    width = w;
    height = h;
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
    glutDisplayFunc(display);
    glutIdleFunc(glutPostRedisplay);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
