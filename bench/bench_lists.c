/* bench_lists.c: writes the traces of the display-list benchmark
 * (bench/bench_lists.sh).
 *
 *   bench_lists --calls N --out FILE [--tris T] [--vertex-colours]
 *
 * One frame: a display list of T triangles (default 10000: a lit wavy
 * sphere with a normal per vertex, in one colour, or with
 * --vertex-colours a colour per vertex) compiled once, then
 * called N times, each call under its own transform (a 10 x 10 x 10 grid
 * of positions, each copy turned differently). Recorded through the raygl
 * API with no GL context: GL's no-op dispatch draws nothing, the trace
 * holds every call.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <raygl/gl.h>

#include "raygl.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static int vertex_colours;

static void vertex(double th, double ph)
{
    double r = 1 + 0.08 * sin(5 * th) * sin(4 * ph);
    double x = sin(ph) * cos(th), y = cos(ph), z = sin(ph) * sin(th);
    if (vertex_colours)
        glColor3f((float)(0.5 + 0.4 * x), (float)(0.5 + 0.4 * y), (float)(0.6 - 0.3 * z));
    glNormal3f((float)x, (float)y, (float)z);
    glVertex3f((float)(r * x), (float)(r * y), (float)(r * z));
}

/* A sphere of slices x stacks quads, two triangles each. */
static void body(int tris)
{
    int stacks = (int)sqrt(tris / 4.0), slices = tris / (2 * stacks);
    glColor3f(0.8f, 0.6f, 0.3f);
    glBegin(GL_TRIANGLES);
    for (int j = 0; j < stacks; j++)
        for (int i = 0; i < slices; i++) {
            double t0 = 2 * M_PI * i / slices, t1 = 2 * M_PI * (i + 1) / slices;
            double p0 = M_PI * (j + 0.5) / (stacks + 1), p1 = M_PI * (j + 1.5) / (stacks + 1);
            vertex(t0, p0), vertex(t0, p1), vertex(t1, p1);
            vertex(t0, p0), vertex(t1, p1), vertex(t1, p0);
        }
    glEnd();
}

int main(int argc, char **argv)
{
    long calls = -1, tris = 10000;
    const char *out = NULL;
    for (int i = 1; i < argc; i++) {
        if (i + 1 < argc && strcmp(argv[i], "--calls") == 0)
            calls = strtol(argv[++i], NULL, 10);
        else if (i + 1 < argc && strcmp(argv[i], "--tris") == 0)
            tris = strtol(argv[++i], NULL, 10);
        else if (i + 1 < argc && strcmp(argv[i], "--out") == 0)
            out = argv[++i];
        else if (strcmp(argv[i], "--vertex-colours") == 0)
            vertex_colours = 1;
        else
            calls = -1, i = argc;
    }
    if (calls < 1 || calls > 1000000 || tris < 8 || tris > 10000000 || !out) {
        fprintf(stderr, "usage: bench_lists --calls N --out FILE [--tris T] [--vertex-colours]\n");
        return 2;
    }
    if (rayglRecordOpen(out) != 0) {
        perror("bench_lists");
        return 1;
    }
    glViewport(0, 0, 640, 480);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(50.0, 640.0 / 480.0, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_COLOR_MATERIAL);
    GLfloat pos[4] = {1.0f, 2.0f, 3.0f, 0.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);

    glNewList(1, GL_COMPILE);
    body((int)tris);
    glEndList();

    glTranslatef(0.0f, 0.0f, -40.0f);
    for (long k = 0; k < calls; k++) {
        glPushMatrix();
        glTranslatef(3.0f * (float)(k % 10) - 13.5f, 3.0f * (float)(k / 10 % 10) - 13.5f,
                     -3.0f * (float)(k / 100 % 10));
        glRotatef((float)(k * 37 % 360), 0.3f, 1.0f, 0.2f);
        glCallList(1);
        glPopMatrix();
    }
    rayglFrameEnd();
    rayglRecordClose();
    if (rayglRecordStatus() == RAYGL_FAILED) {
        fprintf(stderr, "bench_lists: %s\n", rayglRecordError());
        return 1;
    }
    return 0;
}
