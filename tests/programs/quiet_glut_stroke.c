/* quiet_glut_stroke.c: stroke text in a GLUT frame built with the drop-in
 * header (GLUT window: run under Xvfb). The drop-in GLUT records the
 * program's glutStrokeString as the strokes freeglut draws (GL_LINE_STRIPs,
 * record/gluttext.c), so the scene has the text and raygl2pov has nothing
 * to say (issue 22: no message in vain); before the newcomer branch the
 * call went unrecorded and was said. Under raygl record the same calls are
 * recorded (tests/capture, case quiet). A filled bar under the text is
 * drawn as ever.
 */
#include "harness.h"

#include <raygl/gl.h>

#include <GL/freeglut.h>

static int draw(int w, int h)
{
    glViewport(0, 0, w, h);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 320, 0, 240, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(0.2f, 0.3f, 0.6f);
    glRectf(10.13f, 20.37f, 310.13f, 60.37f);
    glColor3f(1.0f, 1.0f, 0.4f);
    glTranslatef(20.0f, 100.0f, 0.0f);
    glScalef(0.25f, 0.25f, 1.0f);
    glutStrokeString(GLUT_STROKE_ROMAN, (const unsigned char *)"RayGL");
    return 0;
}

RGL_TEST_MAIN(draw)
