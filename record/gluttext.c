/* gluttext.c: GLUT's text, recorded in libraygl as the preload library
 * records it.
 *
 * freeglut draws bitmap text with glBitmap (under glPixelStorei and
 * glPush/PopClientAttrib) and stroke text with GL_LINE_STRIP strips and a
 * glTranslatef per character. The preload library does not interpose
 * glutBitmapCharacter, glutBitmapString, glutStrokeCharacter and
 * glutStrokeString, so those calls reach its twins as the program's
 * (docs/design.md, "What is not recorded"). With the drop-in header,
 * freeglut's calls bind to libGL instead: the twins of the four text
 * calls (entry_unrecorded.c, generated) raise a thread-local flag around
 * the real call, and libglut's GOT slots for the gl* names its text is
 * drawn with point at the hooks below: inside a text call each goes to its
 * raygl* twin (recorded, or counted where the preload counts it too),
 * outside one on to GL through the thread's table, as a direct call would
 * (forward.h). The slots are written once, at the first text call
 * (forward.c, relink.c), and again after each relink for OSMesa.
 */
#include <GL/gl.h>

#include "raygl.h"
#include "raygl/unrecorded.h"
#include "recorder.h"
#include "unrecorded.h"

#if defined(__GNUC__)
static __thread int in_text __attribute__((tls_model("initial-exec")));
#else
static _Thread_local int in_text;
#endif

#ifdef RGL_FORWARD_H

/* The hook has the type of the GL function it stands in for. */
#define RGL_HOOK_TYPE(name) \
    _Static_assert(__builtin_types_compatible_p(__typeof__(&hook_##name), __typeof__(&gl##name)), \
                   "hook_" #name)

static void GLAPIENTRY hook_Bitmap(GLsizei w, GLsizei h, GLfloat xo, GLfloat yo, GLfloat xm,
                                   GLfloat ym, const GLubyte *bits)
{
    if (in_text > 0)
        rayglBitmap(w, h, xo, yo, xm, ym, bits);
    else
        glBitmap(w, h, xo, yo, xm, ym, bits);
}
RGL_HOOK_TYPE(Bitmap);

static void GLAPIENTRY hook_PixelStorei(GLenum pname, GLint param)
{
    if (in_text > 0)
        rayglPixelStorei(pname, param);
    else
        glPixelStorei(pname, param);
}
RGL_HOOK_TYPE(PixelStorei);

static void GLAPIENTRY hook_PushClientAttrib(GLbitfield mask)
{
    if (in_text > 0)
        rayglPushClientAttrib(mask);
    else
        glPushClientAttrib(mask);
}
RGL_HOOK_TYPE(PushClientAttrib);

static void GLAPIENTRY hook_PopClientAttrib(void)
{
    if (in_text > 0)
        rayglPopClientAttrib();
    else
        glPopClientAttrib();
}
RGL_HOOK_TYPE(PopClientAttrib);

static void GLAPIENTRY hook_Begin(GLenum mode)
{
    if (in_text > 0)
        rayglBegin(mode);
    else
        glBegin(mode);
}
RGL_HOOK_TYPE(Begin);

static void GLAPIENTRY hook_End(void)
{
    if (in_text > 0)
        rayglEnd();
    else
        glEnd();
}
RGL_HOOK_TYPE(End);

static void GLAPIENTRY hook_Vertex2f(GLfloat x, GLfloat y)
{
    if (in_text > 0)
        rayglVertex2f(x, y);
    else
        glVertex2f(x, y);
}
RGL_HOOK_TYPE(Vertex2f);

static void GLAPIENTRY hook_Translatef(GLfloat x, GLfloat y, GLfloat z)
{
    if (in_text > 0)
        rayglTranslatef(x, y, z);
    else
        glTranslatef(x, y, z);
}
RGL_HOOK_TYPE(Translatef);

const char *const rgl_glut_text_names[RGL_GLUT_TEXT_HOOKS] = {
    "glBitmap", "glPixelStorei", "glPushClientAttrib", "glPopClientAttrib",
    "glBegin",  "glEnd",         "glVertex2f",         "glTranslatef",
};
void (*const rgl_glut_text_hooks[RGL_GLUT_TEXT_HOOKS])(void) = {
    (void (*)(void))hook_Bitmap,  (void (*)(void))hook_PixelStorei,
    (void (*)(void))hook_PushClientAttrib, (void (*)(void))hook_PopClientAttrib,
    (void (*)(void))hook_Begin,   (void (*)(void))hook_End,
    (void (*)(void))hook_Vertex2f, (void (*)(void))hook_Translatef,
};

int rgl_glut_text_enter(void)
{
    if (!rgl_forward_glut_text())
        return 0;
    in_text++;
    return 1;
}

#else

/* The preload library sees freeglut's calls as they are (and never hands
 * these twins out); the stub GL of the tests has no GLUT to hook. */
int rgl_glut_text_enter(void) { return 0; }

#endif

void rgl_glut_text_leave(int entered)
{
    if (entered)
        in_text--;
}
