/* lines_stroke.c: stroke text as HUDs and demos draw it with
 * glutStrokeCharacter: each glyph a few GL_LINE_STRIPs in font units
 * (about 100 high, curves in many short segments, as GLUT's Roman font
 * has them), one glTranslatef after each glyph, the whole under glScalef:
 * 0.06 to 0.3 in window pixels over gluOrtho2D (a HUD), and turned in
 * perspective. The glyphs are this program's own (GLUT's strokes are
 * drawn inside freeglut, out of the recorder's reach here), with the same
 * GL calls. At these scales most segments are a pixel or two long: each
 * lights the pixels of its own diamond-exit rule, and no pixel between
 * them may go missing. */
#include "harness.h"

#include <math.h>

#include <raygl/gl.h>

static void arc(double cx, double cy, double rx, double ry, double a0, double a1, int n)
{
    for (int i = 0; i <= n; i++) {
        double a = (a0 + (a1 - a0) * i / n) * 3.14159265358979 / 180;
        glVertex2f((float)(cx + rx * cos(a)), (float)(cy + ry * sin(a)));
    }
}

static void seg(float x0, float y0, float x1, float y1)
{
    glBegin(GL_LINE_STRIP);
    glVertex2f(x0, y0);
    glVertex2f(x1, y1);
    glEnd();
}

/* One glyph, then the advance (glutStrokeCharacter's glTranslatef). */
static void glyph(char c)
{
    float adv = 70;
    switch (c) {
    case '0':
        glBegin(GL_LINE_LOOP);
        arc(30, 50, 26, 48, 0, 348, 29);
        glEnd();
        break;
    case '1':
        glBegin(GL_LINE_STRIP);
        glVertex2f(14, 80);
        glVertex2f(34, 100);
        glVertex2f(34, 0);
        glEnd();
        adv = 50;
        break;
    case '2':
        glBegin(GL_LINE_STRIP);
        arc(30, 72, 26, 26, 160, -40, 14);
        glVertex2f(4, 0);
        glVertex2f(58, 0);
        glEnd();
        break;
    case '3':
        glBegin(GL_LINE_STRIP);
        arc(30, 76, 24, 24, 150, -90, 16);
        arc(30, 28, 28, 28, 90, -150, 16);
        glEnd();
        break;
    case '8':
        glBegin(GL_LINE_LOOP);
        arc(30, 76, 22, 24, 270, -90, 24);
        arc(30, 26, 28, 26, 90, -270, 24);
        glEnd();
        break;
    case 'S':
        glBegin(GL_LINE_STRIP);
        arc(30, 75, 26, 25, 20, 270, 18);
        arc(30, 25, 28, 25, 90, -160, 18);
        glEnd();
        break;
    case 'C':
    case 'G':
        glBegin(GL_LINE_STRIP);
        arc(34, 50, 32, 50, 40, 320, 30);
        if (c == 'G') {
            glVertex2f(60, 40);
            glVertex2f(40, 40);
        }
        glEnd();
        break;
    case 'O':
        glBegin(GL_LINE_LOOP);
        arc(34, 50, 32, 50, 0, 350, 36);
        glEnd();
        adv = 78;
        break;
    case 'R':
    case 'P':
        glBegin(GL_LINE_STRIP);
        glVertex2f(6, 0);
        glVertex2f(6, 100);
        glVertex2f(34, 100);
        arc(34, 76, 24, 24, 90, -90, 12);
        glVertex2f(6, 52);
        glEnd();
        if (c == 'R')
            seg(32, 52, 60, 0);
        break;
    case 'A':
        glBegin(GL_LINE_STRIP);
        glVertex2f(2, 0);
        glVertex2f(32, 100);
        glVertex2f(62, 0);
        glEnd();
        seg(13, 36, 51, 36);
        break;
    case 'Y':
        glBegin(GL_LINE_STRIP);
        glVertex2f(2, 100);
        glVertex2f(32, 52);
        glVertex2f(62, 100);
        glEnd();
        seg(32, 52, 32, 0);
        break;
    case 'L':
        glBegin(GL_LINE_STRIP);
        glVertex2f(8, 100);
        glVertex2f(8, 0);
        glVertex2f(56, 0);
        glEnd();
        adv = 62;
        break;
    case 'F':
    case 'E':
        glBegin(GL_LINE_STRIP);
        if (c == 'E')
            glVertex2f(58, 0);
        glVertex2f(8, 0);
        glVertex2f(8, 100);
        glVertex2f(58, 100);
        glEnd();
        seg(8, 52, 44, 52);
        adv = 64;
        break;
    case ':':
        glBegin(GL_LINE_LOOP);
        arc(20, 66, 4, 4, 0, 300, 6);
        glEnd();
        glBegin(GL_LINE_LOOP);
        arc(20, 8, 4, 4, 0, 300, 6);
        glEnd();
        adv = 40;
        break;
    case '.':
        glBegin(GL_LINE_LOOP);
        arc(16, 6, 5, 5, 0, 300, 6);
        glEnd();
        adv = 34;
        break;
    default:
        adv = 50;
        break;
    }
    glTranslatef(adv, 0, 0);
}

static void text(const char *s)
{
    for (; *s; s++)
        glyph(*s);
}

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* Text turned in perspective first (a title floating in the scene). */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(45, (double)w / h, 1, 40);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(-2.2f, -0.9f, -6);
    glRotatef(-35, 1, 0, 0);
    glRotatef(15, 0, 1, 0);
    glScalef(0.006f, 0.006f, 0.006f);
    glColor3f(0.4f, 0.8f, 1);
    text("GRAPS 2018");

    /* The HUD: window pixels, several scales. */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluOrtho2D(0, w, 0, h);
    glMatrixMode(GL_MODELVIEW);
    static const float scale[6] = {0.06f, 0.08f, 0.1f, 0.13f, 0.18f, 0.3f};
    static const float ypos[6] = {228, 214, 198, 180, 156, 120};
    for (int i = 0; i < 6; i++) {
        glLoadIdentity();
        glTranslatef(6, ypos[i], 0);
        glScalef(scale[i], scale[i], 1);
        glColor3f(1, 1.0f - 0.12f * (float)i, 0.3f + 0.1f * (float)i);
        text(i % 2 ? "FPS: 38.2 ALL CLEAR" : "SCORE 123 8032 LOG");
    }
    return 0;
}

RGL_TEST_MAIN(draw)
