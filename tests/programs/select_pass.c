/* select_pass.c: a picking pass (GL_SELECT) before the real draw.
 *
 * Covers: geometry drawn in GL_SELECT mode reaches no pixel (a full-window
 * red quad under a pick matrix would show as a phantom), a glClear in
 * GL_SELECT mode clears nothing (Mesa clears only in GL_RENDER mode), the
 * camera is the real draw's, not the pick matrix's, and the name-stack
 * calls of the render pass (which GL ignores there) change nothing in the
 * picture. The hit count glRenderMode returns picks a colour, so the GL
 * image shows that the selection really ran.
 */
#include "harness.h"

#include "raygl.h"
#include "shapes.h"

static void scene_rects(void)
{
    rayglInitNames();
    rayglPushName(1);
    rayglColor3f(0.2f, 0.7f, 0.3f);
    shape_rect(40, 40, 140, 200);
    rayglLoadName(2);
    rayglPushName(7);
    rayglColor3f(0.9f, 0.6f, 0.3f);
    shape_rect(180, 40, 280, 120);
    rayglPopName();
    rayglPopName();
}

static int draw(int w, int h)
{
    static GLuint hits[64];
    rayglViewport(0, 0, w, h);
    rayglClearColor(0.3f, 0.3f, 0.5f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);

    /* The picking pass around pixel (90, 120): a pick matrix (as
     * gluPickMatrix makes it, 4x4 pixels) and a red window-sized quad. */
    rayglSelectBuffer(64, hits);
    rayglRenderMode(GL_SELECT);
    rayglClearColor(1.0f, 0.0f, 0.0f, 1.0f);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglTranslatef((w - 2.0f * 90) / 4, (h - 2.0f * 120) / 4, 0);
    rayglScalef(w / 4.0f, h / 4.0f, 1);
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    scene_rects();
    rayglColor3f(1, 0, 0);
    shape_rect(0, 0, 320, 240);
    GLint nhits = rayglRenderMode(GL_RENDER);

    /* The real draw. */
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    raygluOrtho2D(0, 320, 0, 240);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0.13f, 0.37f, 0.0f);
    scene_rects();
    /* Two hits (the green rectangle, the red quad): a yellow mark. */
    if (nhits == 2)
        rayglColor3f(0.9f, 0.9f, 0.2f);
    else
        rayglColor3f(0.1f, 0.1f, 0.1f);
    shape_rect(180, 150, 280, 200);
    return 0;
}

RGL_TEST_MAIN(draw)
