/* test_linkorder.c: an OSMesa program records and draws the same in every
 * link order of libGL and libOSMesa (record/forward.h). Built twice, with
 * -Wl,--no-as-needed and libGL before libOSMesa, and the other way round;
 * the first argument says which, and the program checks that the loaded
 * libraries are in that order, so both builds test what they claim.
 *
 * One frame: a triangle through the twins, a GLU disk, a quad drawn with
 * the program's own gl* calls, and with a second argument `glut` a GLUT
 * cube (glutInit needs a display: meson runs that under xvfb-run).
 * Each must land in the OSMesa buffer, and the frame must be recorded with
 * the live context's state snapshot. Then a context switch (OSMesa
 * released, made current again) across RayGL's frame boundaries.
 */
#include <dlfcn.h>
#include <link.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GL/osmesa.h>
#include <GL/freeglut.h>

#include "check.h"
#include "raygl.h"

#define SIDE 64
static unsigned char pixels[SIDE * SIDE * 4];

typedef struct order {
    int gl, osmesa, n;
} order;

static int find_libs(struct dl_phdr_info *info, size_t size, void *arg)
{
    (void)size;
    order *o = arg;
    const char *base = strrchr(info->dlpi_name, '/');
    base = base ? base + 1 : info->dlpi_name;
    if (o->gl < 0 && strncmp(base, "libGL.so", 8) == 0)
        o->gl = o->n;
    if (o->osmesa < 0 && strncmp(base, "libOSMesa.so", 12) == 0)
        o->osmesa = o->n;
    o->n++;
    return 0;
}

/* The pixel at (x, y), bottom row first, is r, g, b. */
static bool pixel_is(int x, int y, int r, int g, int b, const char *what)
{
    const unsigned char *p = pixels + ((size_t)y * SIDE + (size_t)x) * 4;
    return CHECKM(p[0] == r && p[1] == g && p[2] == b, "%s at (%d,%d): %d,%d,%d, want %d,%d,%d",
                  what, x, y, p[0], p[1], p[2], r, g, b);
}

/* glBegin as the program's own calls reach it (its GOT slot, read anew). */
__attribute__((noinline)) static void *own_glBegin(void)
{
    void (*volatile f)(GLenum) = glBegin;
    void *p;
    memcpy(&p, (const void *)&f, sizeof p);
    return p;
}

/* A context switch: the program's calls follow the GL current at RayGL's
 * frame boundaries, and go back to the linked one when OSMesa is released. */
static void test_switch(OSMesaContext ctx)
{
    void *osm = dlopen("libOSMesa.so.8", RTLD_LAZY | RTLD_NOLOAD);
    void *os_begin = osm ? dlsym(osm, "glBegin") : NULL;
    void *linked_begin = dlsym(RTLD_DEFAULT, "glBegin");
    CHECK(os_begin != NULL && linked_begin != NULL);
    CHECKM(own_glBegin() == os_begin, "OSMesa current: the program's glBegin is not OSMesa's");
    CHECK(OSMesaMakeCurrent(NULL, NULL, 0, 0, 0));
    rayglFrameEnd();
    CHECKM(own_glBegin() == linked_begin, "no context: the program's glBegin is not the linked one");
    CHECK(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, SIDE, SIDE));
    /* The first twin call of the frame chooses OSMesa again. */
    rayglClearColor(0, 1, 1, 1);
    rayglClear(GL_COLOR_BUFFER_BIT);
    CHECKM(own_glBegin() == os_begin, "OSMesa current again: the program's glBegin is not OSMesa's");
    glFinish();
    pixel_is(SIDE / 2, SIDE / 2, 0, 255, 255, "the second clear colour");
    rayglFrameEnd();
    if (osm)
        dlclose(osm);
}

int main(int argc, char **argv)
{
    if (argc < 2 || argc > 3 ||
        (strcmp(argv[1], "gl-first") != 0 && strcmp(argv[1], "osmesa-first") != 0) ||
        (argc == 3 && strcmp(argv[2], "glut") != 0)) {
        fprintf(stderr, "usage: test_linkorder gl-first|osmesa-first [glut]\n");
        return 2;
    }
    bool gl_first = strcmp(argv[1], "gl-first") == 0;
    order o = {-1, -1, 0};
    dl_iterate_phdr(find_libs, &o);
    CHECKM(o.gl >= 0 && o.osmesa >= 0 && (o.gl < o.osmesa) == gl_first,
           "load order: libGL %d, libOSMesa %d", o.gl, o.osmesa);

    bool glut = argc == 3;
    if (glut) {
        int gargc = 1;
        char *gargv[2] = {argv[0], NULL};
        glutInit(&gargc, gargv);
    }
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!CHECK(ctx != NULL) || !CHECK(OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, SIDE, SIDE)))
        return check_exit();
    char dir[] = "/tmp/raygl-linkorder-XXXXXX";
    if (!CHECK(mkdtemp(dir) != NULL))
        return check_exit();
    char path[64];
    snprintf(path, sizeof path, "%s/t.raygl", dir);
    CHECK(rayglRecordOpen(path) == 0);

    rayglClearColor(0, 0, 1, 1);
    rayglClear(GL_COLOR_BUFFER_BIT);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    /* Lower left: the twins. */
    rayglColor3f(1, 0, 0);
    rayglBegin(GL_TRIANGLES);
    rayglVertex2f(-1, -1);
    rayglVertex2f(0, -1);
    rayglVertex2f(-1, 0);
    rayglEnd();
    /* Upper right: GLU. */
    rayglColor3f(0, 1, 0);
    rayglPushMatrix();
    rayglTranslatef(0.5f, 0.5f, 0);
    GLUquadric *q = raygluNewQuadric();
    raygluDisk(q, 0, 0.4, 16, 1);
    raygluDeleteQuadric(q);
    rayglPopMatrix();
    /* Upper left: the program's own calls. */
    glColor3f(1, 1, 1);
    glBegin(GL_QUADS);
    glVertex2f(-0.9f, 0.1f);
    glVertex2f(-0.1f, 0.1f);
    glVertex2f(-0.1f, 0.9f);
    glVertex2f(-0.9f, 0.9f);
    glEnd();
    /* Lower right: GLUT. */
    if (glut) {
        rayglColor3f(1, 1, 0);
        rayglPushMatrix();
        rayglTranslatef(0.5f, -0.5f, 0);
        rayglutSolidCube(0.5);
        rayglPopMatrix();
    }
    rayglFrameEnd();
    glFinish();

    int lo = SIDE / 8, hi = SIDE - SIDE / 4;
    pixel_is(SIDE / 2, SIDE / 2 + 2, 0, 0, 255, "the clear colour");
    pixel_is(lo, lo, 255, 0, 0, "the twins' triangle");
    pixel_is(hi, hi, 0, 255, 0, "the GLU disk");
    pixel_is(SIDE / 4, hi, 255, 255, 255, "the program's own quad");
    if (glut)
        pixel_is(hi, SIDE / 4, 255, 255, 0, "the GLUT cube");
    else
        pixel_is(hi, SIDE / 4, 0, 0, 255, "the clear colour");
    /* What GL tells the twins is read from the same context. */
    GLint vp[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    CHECK(vp[2] == SIDE && vp[3] == SIDE);

    test_switch(ctx);
    rayglRecordClose();
    rgl_reader *r = trace_open(path);
    if (r) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, 0, &fi);
        CHECK(c.clean);
        CHECKM(fi.flags == RGL_FRAME_LIVE_CONTEXT, "frame flags %u", (unsigned)fi.flags);
        CHECK(trace_cmds_find(&c, 0, "gluDisk(") >= 0);
        CHECK(trace_cmds_find(&c, 0, "@Matrix(mode=GL_MODELVIEW") >= 0);
        trace_cmds_free(&c);
        rgl_reader_destroy(r);
    }
    OSMesaDestroyContext(ctx);
    if (!check_failures) {
        unlink(path);
        rmdir(dir);
    }
    return check_exit();
}
