/* dropin_prog.c: an ordinary GL/GLUT program with no RayGL in its source.
 * Built with -include raygl/gl.h, it records; test_process checks the
 * trace. Runs without a window or context (batch). It also makes calls
 * RayGL does not record (counted), and holds a function pointer named as
 * a glext.h-only entry point, as programs that look such calls up do (the
 * drop-in header leaves those names alone without GL_GLEXT_PROTOTYPES). */
#include <GL/gl.h>
#include <GL/glut.h>

static PFNGLUSEPROGRAMPROC glUseProgram;

static void display(float angle)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glLoadIdentity();
    glRotatef(angle, 0, 0, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0);
    glVertex3f(-0.5f, -0.5f, 0);
    glVertex3f(0.5f, -0.5f, 0);
    glVertex3f(0, 0.5f, 0);
    glEnd();
    glutSolidTorus(0.25, 1, 8, 16);
    glIndexi(0);
    glIndexf(1);
    glIndexf(2);
    if (glUseProgram)
        glUseProgram(0);
    (void)glGetError(); /* a query: not counted */
    glutSwapBuffers();
}

int main(void)
{
    display(0);
    display(15);
    return 0;
}
