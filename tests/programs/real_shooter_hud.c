/* real_shooter_hud.c: a small arcade game's frame: a scrolling starfield
 * of quads and enemy ships (flat-coloured triangle fans) in gluOrtho2D, a
 * player ship, bullets as thin rectangles, translucent explosion discs
 * (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), then the HUD: a score and a
 * lives counter as bitmap text (a hand-made 8 x 8 digit font,
 * glRasterPos2i + glBitmap), a health bar. Everything moves with the
 * frame number. Unlit, no depth test. Four frames. */
#include "real.h"

#include <math.h>
#include <raygl/gl.h>

static const GLubyte digits[10][8] = {
    {0x3c, 0x66, 0x6e, 0x76, 0x66, 0x66, 0x3c, 0x00}, {0x7e, 0x18, 0x18, 0x18, 0x18, 0x38, 0x18, 0x00},
    {0x7e, 0x60, 0x30, 0x0c, 0x06, 0x66, 0x3c, 0x00}, {0x3c, 0x66, 0x06, 0x1c, 0x06, 0x66, 0x3c, 0x00},
    {0x0c, 0x0c, 0x7e, 0x4c, 0x2c, 0x1c, 0x0c, 0x00}, {0x3c, 0x66, 0x06, 0x06, 0x7c, 0x60, 0x7e, 0x00},
    {0x3c, 0x66, 0x66, 0x7c, 0x60, 0x66, 0x3c, 0x00}, {0x30, 0x30, 0x18, 0x0c, 0x06, 0x66, 0x7e, 0x00},
    {0x3c, 0x66, 0x66, 0x3c, 0x66, 0x66, 0x3c, 0x00}, {0x3c, 0x66, 0x06, 0x3e, 0x66, 0x66, 0x3c, 0x00}};

static void rect(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glVertex2f(x0 + 0.25f, y0 + 0.25f);
    glVertex2f(x1 + 0.25f, y0 + 0.25f);
    glVertex2f(x1 + 0.25f, y1 + 0.25f);
    glVertex2f(x0 + 0.25f, y1 + 0.25f);
    glEnd();
}

static void number(int x, int y, int n, int places)
{
    glRasterPos2i(x, y);
    for (int p = places - 1; p >= 0; p--) {
        int d = n;
        for (int k = 0; k < p; k++)
            d /= 10;
        glBitmap(8, 8, 0, 0, 10, 0, digits[d % 10]);
    }
}

static void ship(float x, float y, float s, float r, float g, float b)
{
    glColor3f(r, g, b);
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(x + 0.25f, y + 0.25f);
    glVertex2f(x + 0.25f, y + 1.2f * s + 0.25f);
    glVertex2f(x - s + 0.25f, y - s + 0.25f);
    glVertex2f(x + 0.25f, y - 0.5f * s + 0.25f);
    glVertex2f(x + s + 0.25f, y - s + 0.25f);
    glVertex2f(x + 0.25f, y + 1.2f * s + 0.25f);
    glEnd();
}

static void draw(int frame, int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.02f, 0.02f, 0.08f, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    for (int i = 0; i < 40; i++) {
        float x = (float)((i * 73) % w), y = (float)((i * 151 + h - 7 * frame * (1 + i % 3)) % h);
        float c = 0.4f + 0.15f * (float)(i % 4);
        glColor3f(c, c, c + 0.1f);
        rect(x, y, x + 2, y + 2);
    }
    for (int e = 0; e < 5; e++)
        ship(40.0f + 58.0f * (float)e + 6.0f * sinf((float)(frame + e)), 180.0f - 4.0f * (float)frame, 10,
             0.9f, 0.3f + 0.1f * (float)e, 0.2f);
    ship(150.0f + 12.0f * (float)frame, 40.0f, 12, 0.3f, 0.8f, 1.0f);
    glColor3f(1.0f, 1.0f, 0.4f);
    for (int b = 0; b < 3; b++)
        rect(149.0f + 12.0f * (float)frame, 60.0f + 30.0f * (float)b + 5.0f * (float)frame,
             151.0f + 12.0f * (float)frame, 70.0f + 30.0f * (float)b + 5.0f * (float)frame);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (int x = 0; x < 2; x++) {
        float cx = 98.0f + 116.0f * (float)x, cy = 176.0f - 4.0f * (float)frame;
        float r = 8.0f + 5.0f * (float)frame;
        glBegin(GL_TRIANGLE_FAN);
        glColor4f(1.0f, 0.9f, 0.5f, 0.8f);
        glVertex2f(cx + 0.25f, cy + 0.25f);
        glColor4f(1.0f, 0.4f, 0.1f, 0.2f);
        for (int k = 0; k <= 24; k++) {
            float a = 6.2831853f * (float)k / 24.0f;
            glVertex2f(cx + r * cosf(a) + 0.25f, cy + r * sinf(a) + 0.25f);
        }
        glEnd();
    }
    glDisable(GL_BLEND);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(1.0f, 1.0f, 1.0f);
    number(8, h - 16, 1250 + 350 * frame, 6);
    glColor3f(1.0f, 0.5f, 0.5f);
    number(w - 28, h - 16, 3 - frame / 2, 2);
    glColor3f(0.2f, 0.8f, 0.2f);
    rect(8, 8, 8 + 100 - 15 * (float)frame, 14);
    glColor3f(0.4f, 0.1f, 0.1f);
    rect(8 + 100 - 15 * (float)frame, 8, 108, 14);
}

RGL_REAL_MAIN(draw, 4)
