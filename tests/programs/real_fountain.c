/* real_fountain.c: a particle fountain in the style of the particle
 * lessons: 150 particles on deterministic ballistic paths (their age from
 * the frame number), each a small camera-facing quad blended additively
 * (GL_SRC_ALPHA, GL_ONE) with the depth test off, its colour and alpha
 * fading with age, over a depth-tested perspective floor grid of quads.
 * Four frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.02f, 0.02f, 0.05f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 50);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0013f, -1.5f, -12.0f);
    glRotatef(15, 1, 0, 0);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    for (int i = -5; i < 5; i++)
        for (int j = -5; j < 5; j++) {
            float c = (i + j) % 2 ? 0.25f : 0.18f;
            glColor3f(c, c, c + 0.05f);
            glVertex3f((float)i, 0, (float)j + 1);
            glVertex3f((float)i + 1, 0, (float)j + 1);
            glVertex3f((float)i + 1, 0, (float)j);
            glVertex3f((float)i, 0, (float)j);
        }
    glEnd();
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glBegin(GL_QUADS);
    for (int p = 0; p < 150; p++) {
        float age = fmodf(0.37f * (float)p + 0.5f * (float)frame, 3.0f);
        float a = 0.7f * (float)p, v = 1.2f + 0.4f * sinf(1.7f * (float)p);
        float x = v * cosf(a) * age * 0.6f, z = v * sinf(a) * age * 0.6f;
        float y = 0.05f + 4.5f * age - 1.6f * age * age;
        if (y < 0)
            continue;
        float s = 0.08f + 0.03f * age, fade = 1.0f - age / 3.0f;
        glColor4f(0.5f + 0.5f * fade, 0.4f + 0.4f * fade, 1.0f - 0.6f * fade, 0.3f + 0.6f * fade);
        glVertex3f(x - s, y - s, z);
        glVertex3f(x + s, y - s, z);
        glVertex3f(x + s, y + s, z);
        glVertex3f(x - s, y + s, z);
    }
    glEnd();
    glDisable(GL_BLEND);
}

RGL_REAL_MAIN(draw, 4)
