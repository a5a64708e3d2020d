/* test_nurbs_osmesa.c: GLU NURBS through the twins with a real GLU and a
 * software GL context. Frame 0 draws a surface with a trim and a curve in
 * GLU_NURBS_RENDERER mode: the trace holds the GLU calls themselves, never
 * the evaluator or primitive calls GLU makes to draw them. Frame 1 draws
 * the surface in GLU_NURBS_TESSELLATOR mode, whose callbacks draw with the
 * program's own raygl* calls: those are recorded. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <GL/osmesa.h>

#include "check.h"
#include "wire.h"
#include "raygl.h"

static unsigned char pixels[64 * 64 * 4];
static GLfloat ctl[4][4][3];
static GLfloat knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
static int tess_vertices;

static void GLAPIENTRY cb_begin(GLenum mode) { rayglBegin(mode); }
static void GLAPIENTRY cb_vertex(GLfloat *v)
{
    tess_vertices++;
    rayglVertex3fv(v);
}
static void GLAPIENTRY cb_normal(GLfloat *n) { rayglNormal3fv(n); }
static void GLAPIENTRY cb_end(void) { rayglEnd(); }

static void surface(GLUnurbs *n)
{
    raygluBeginSurface(n);
    raygluNurbsSurface(n, 8, knots, 8, knots, 4 * 3, 3, &ctl[0][0][0], 4, 4, GL_MAP2_VERTEX_3);
    static GLfloat hole[5][2] = {{0.3f, 0.3f}, {0.3f, 0.7f}, {0.7f, 0.7f}, {0.7f, 0.3f},
                                 {0.3f, 0.3f}};
    static GLfloat outer[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    raygluBeginTrim(n);
    raygluPwlCurve(n, 5, &outer[0][0], 2, GLU_MAP1_TRIM_2);
    raygluEndTrim(n);
    raygluBeginTrim(n);
    raygluPwlCurve(n, 5, &hole[0][0], 2, GLU_MAP1_TRIM_2);
    raygluEndTrim(n);
    raygluEndSurface(n);
}

int main(void)
{
    char path[] = "/tmp/raygl-nurbs-XXXXXX";
    int fd = mkstemp(path);
    if (!CHECK(fd >= 0))
        return check_exit();
    close(fd);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    if (!CHECK(ctx && OSMesaMakeCurrent(ctx, pixels, GL_UNSIGNED_BYTE, 64, 64)))
        return check_exit();
    for (int u = 0; u < 4; u++)
        for (int v = 0; v < 4; v++) {
            ctl[u][v][0] = (GLfloat)u - 1.5f;
            ctl[u][v][1] = (GLfloat)v - 1.5f;
            ctl[u][v][2] = (u == 1 || u == 2) && (v == 1 || v == 2) ? 1.0f : 0.0f;
        }

    CHECK(rayglRecordOpen(path) == 0);
    rayglMatrixMode(GL_PROJECTION);
    rayglLoadIdentity();
    rayglFrustum(-1, 1, -1, 1, 1, 10);
    rayglMatrixMode(GL_MODELVIEW);
    rayglLoadIdentity();
    rayglTranslatef(0, 0, -4);
    rayglEnable(GL_AUTO_NORMAL);
    GLUnurbs *n = raygluNewNurbsRenderer();
    raygluNurbsProperty(n, GLU_SAMPLING_TOLERANCE, 10.0f);
    surface(n);
    static GLfloat cpts[4][3] = {{-1, -1, 0}, {-0.5f, 1, 0}, {0.5f, -1, 0}, {1, 1, 0}};
    raygluBeginCurve(n);
    raygluNurbsCurve(n, 8, knots, 3, &cpts[0][0], 4, GL_MAP1_VERTEX_3);
    raygluEndCurve(n);
    rayglutSwapBuffers();

    /* Frame 1: the tessellator hands the triangles to the callbacks. */
    raygluNurbsProperty(n, GLU_NURBS_MODE, GLU_NURBS_TESSELLATOR);
    gluNurbsCallback(n, GLU_NURBS_BEGIN, (void (*)(void))cb_begin);
    gluNurbsCallback(n, GLU_NURBS_VERTEX, (void (*)(void))cb_vertex);
    gluNurbsCallback(n, GLU_NURBS_NORMAL, (void (*)(void))cb_normal);
    gluNurbsCallback(n, GLU_NURBS_END, (void (*)(void))cb_end);
    surface(n);
    CHECK(tess_vertices > 0);
    rayglutSwapBuffers();
    raygluDeleteNurbsRenderer(n);
    rayglRecordClose();
    OSMesaDestroyContext(ctx);

    rgl_reader *r = trace_open(path);
    if (r) {
        rgl_frame_info fi;
        trace_cmds c = trace_frame(r, 0, &fi);
        CHECK(c.clean);
        CHECK(trace_cmds_find(&c, 0, "gluNewNurbsRenderer(nurb=#1)") >= 0);
        CHECK(trace_cmds_find(&c, 0, "gluNurbsProperty(nurb=#1, property=") >= 0);
        CHECK(trace_cmds_count(&c, RGL_OP_BeginSurface) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_NurbsSurface) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_PwlCurve) == 2);
        CHECK(trace_cmds_count(&c, RGL_OP_BeginTrim) == 2);
        CHECK(trace_cmds_count(&c, RGL_OP_EndSurface) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_NurbsCurve) == 1);
        CHECK(trace_cmds_count(&c, RGL_OP_EndCurve) == 1);
        /* What GLU draws with is not the program's. */
        CHECK(trace_cmds_count(&c, RGL_OP_Begin) == 0);
        CHECK(trace_cmds_count(&c, RGL_OP_Map2f) == 0);
        CHECK(trace_cmds_count(&c, RGL_OP_Map1f) == 0);
        CHECK(trace_cmds_count(&c, RGL_OP_EvalMesh2) == 0);
        CHECK(trace_cmds_count(&c, RGL_OP_EvalCoord2f) == 0);
        CHECK(trace_cmds_count(&c, RGL_OP_Vertex3f) == 0);
        trace_cmds_done(&c, "frame 0");

        c = trace_frame(r, 1, &fi);
        CHECK(c.clean);
        CHECK(trace_cmds_find(&c, 0, "gluNurbsProperty(nurb=#1, property=GLU_NURBS_MODE, value=100161)") >= 0);
        CHECK(trace_cmds_count(&c, RGL_OP_NurbsSurface) == 1);
        /* The callbacks' calls are the program's own. */
        CHECK(trace_cmds_count(&c, RGL_OP_Begin) > 0);
        CHECK(trace_cmds_count(&c, RGL_OP_Vertex3fv) == (size_t)tess_vertices);
        trace_cmds_done(&c, "frame 1");
        rgl_reader_destroy(r);
    }
    unlink(path);
    return check_exit();
}
