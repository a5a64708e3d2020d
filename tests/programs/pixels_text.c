/* pixels_text.c: bitmap text over a lit 3D scene, as a GLUT program draws
 * it with glutBitmapString: glRasterPos in object coordinates under an
 * orthographic overlay projection, then one glBitmap per character from a
 * hand-made 5 x 7 font (GLUT needs a display; freeglut's fonts cannot be
 * copied), each advancing the raster position. Drawn after the scene with
 * the depth test and lighting off, so it lies on top. A second line starts
 * at a position outside the view volume: invalid, so it draws nothing; a
 * third, from a font of display lists (glCallLists), is placed by
 * glWindowPos2i, in a colour set after it (the raster colour is the one
 * current at the call).
 */
#include "lit_scene.h"

/* Rows bottom first, bit 7 the leftmost pixel, as glBitmap reads them. */
static const GLubyte font[][7] = {
    {0x88, 0x88, 0xf8, 0x88, 0x88, 0x50, 0x20}, /* A */
    {0xf0, 0x88, 0x88, 0xf0, 0x88, 0x88, 0xf0}, /* B */
    {0x70, 0x88, 0x80, 0x80, 0x80, 0x88, 0x70}, /* C */
    {0x88, 0xd8, 0xa8, 0xa8, 0x88, 0x88, 0x88}, /* W */
};

static void text(const char *s)
{
    for (; *s; s++) {
        int k = *s == 'W' ? 3 : *s - 'A';
        /* Origin (0.5, 1) and a move of 7 pixels: fractional positions
         * floor as GL's do. */
        glBitmap(5, 7, 0.5f, 1.0f, 7.0f, 0.0f, font[k]);
    }
}

static int draw(int w, int h)
{
    lit_begin(w, h);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    GLfloat pos[4] = {0.5f, 1.5f, -2.5f, 1.0f};
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_LIGHT0);
    lit_material(0.3f, 0.6f, 0.85f, 0.7f, 30.0f);
    lit_pair();

    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glOrtho(0, w, 0, h, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glLoadIdentity();
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glColor3f(1.0f, 0.9f, 0.2f);
    glRasterPos2f(20.3f, (float)h - 30.0f);
    for (int i = 0; i < 3; i++)
        text("ABCWABCWABCW");
    glColor3f(1.0f, 0.2f, 0.2f);
    glRasterPos2f(-10.0f, 40.0f); /* outside: invalid */
    text("WWWW");
    /* A font in display lists, as glXUseXFont makes one: glCallLists of
     * a string. */
    GLuint base = glGenLists(4);
    for (int k = 0; k < 4; k++) {
        glNewList(base + (GLuint)k, GL_COMPILE);
        glBitmap(5, 7, 0.5f, 1.0f, 7.0f, 0.0f, font[k]);
        glEndList();
    }
    glColor3f(0.2f, 1.0f, 0.4f);
    glWindowPos2i(30, 20);
    glColor3f(0.0f, 0.0f, 1.0f); /* too late for the raster colour */
    static const GLubyte cab[] = {2, 0, 1, 3, 3, 1};
    glListBase(base);
    glCallLists(6, GL_UNSIGNED_BYTE, cab);
    glListBase(0);
    glPopMatrix();
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    return 0;
}

RGL_TEST_MAIN(draw)
