/* test_shapes.c: issue 14's shapes in the interpreter.
 *
 * Quadric state and display lists: GLU quadric calls are client state,
 * done at compile time and never stored in a list, so a quadric state
 * command in a list body (the recorder writes a compiled shape's state
 * there) holds for the body alone; the quadric outside keeps its own.
 *
 * glPolygonOffset: an offset polygon draw moves one pixel along the
 * camera's rays (away for a positive offset), an offset shape is drawn as
 * GL's facets, lines are not moved, and a note says so.
 */
#include <GL/gl.h>
#include <GL/glu.h>
#include <string.h>

#include "check.h"
#include "interp.h"
#include "tracegen.h"

static scene sc;
static diag_log dlog;
static seq body;

static rgl_status fetch(void *ctx, uint32_t id, rgl_resource *out, rgl_error *err)
{
    (void)ctx;
    if (id != 1) {
        err->status = RGL_E_RESOURCE;
        return RGL_E_RESOURCE;
    }
    memset(out, 0, sizeof *out);
    out->id = id;
    out->kind = RGL_RES_COMMANDS;
    out->data = body.data;
    out->size = body.len;
    return RGL_OK;
}

static interp *fresh(void)
{
    scene_reset(&sc);
    diag_clear(&dlog);
    interp *ip = interp_create(&sc, &dlog);
    interp_set_resources(ip, fetch, NULL);
    interp_begin_frame(ip);
    return ip;
}

static void run(interp *ip, seq *s)
{
    rgl_error err;
    CHECK(interp_run(ip, s->data, s->len, 0, &err) == RGL_OK);
    seq_free(s);
}

static void test_quadric_state_in_list(void)
{
    interp *ip = fresh();
    seq_init(&body);
    CMD(&body, QuadricDrawStyle, 1, GLU_LINE);
    CMD(&body, Disk, 1, 0.25, 1.0, 8, 2);
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 64, 64);
    CMD(&s, NewQuadric, 1);
    CMD(&s, NewList, 1, GL_COMPILE, 1);
    CMD0(&s, EndList);
    CMD(&s, Translatef, 0, 0, -5);
    CMD(&s, CallList, 1);
    run(ip, &s);
    size_t lines = sc.nlines;
    CHECK(lines > 0);           /* the body's GLU_LINE disk */
    CHECK_EQ_U(sc.nsolids, 0);
    seq_init(&s);
    CMD(&s, Disk, 1, 0.25, 1.0, 8, 2); /* the quadric's own style: GLU_FILL */
    run(ip, &s);
    CHECK_EQ_U(sc.nlines, lines);
    CHECK_EQ_U(sc.nsolids, 1); /* a full filled disk is an exact disc */
    interp_destroy(ip);
    seq_free(&body);
}

/* The eye-space z of the first vertex of mesh m. */
static double mesh_z(size_t m)
{
    const scene_mesh *me = &sc.meshes[m];
    const scene_vertex *v = &sc.verts[sc.tris[me->first_tri].v[0]];
    double in[4] = {v->pos[0], v->pos[1], v->pos[2], 1}, out[4];
    mat4_apply(&me->to_eye, in, out);
    return out[2];
}

static void test_polygon_offset(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 100, 100);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 100);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Translatef, 0, 0, -10);
    CMD(&s, Begin, GL_TRIANGLES); /* not offset: the reference */
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, Enable, GL_POLYGON_OFFSET_FILL);
    CMD(&s, PolygonOffset, 1, 1);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, PolygonOffset, -1, -1);
    CMD(&s, Color3f, 0, 1, 0);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD(&s, Vertex2f, 0, 1);
    CMD0(&s, End);
    CMD(&s, Begin, GL_LINES); /* lines: GL offsets polygons only */
    CMD(&s, Vertex2f, 0, 0);
    CMD(&s, Vertex2f, 1, 0);
    CMD0(&s, End);
    CMD(&s, NewQuadric, 1);
    CMD(&s, Sphere, 1, 1.0, 8, 4); /* offset: GL's facets, no true sphere */
    run(ip, &s);
    CHECK(sc.nmeshes >= 3);
    if (sc.nmeshes >= 3) {
        /* 10 units away, 100 pixels over a height of 2 at unit distance:
         * one pixel is 0.2 units there. */
        CHECK_NEAR(mesh_z(0), -10, 1e-9);
        CHECK_NEAR(mesh_z(1), -10.2, 1e-9);
        CHECK_NEAR(mesh_z(2), -9.8, 1e-9);
    }
    CHECK(sc.nlines == 1);
    CHECK_EQ_U(sc.nsolids, 0);
    CHECK(sc.ntris > 3);
    CHECK_EQ_U(dlog.e[DIAG_NOTE_POLYGON_OFFSET].count, 1);
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    test_quadric_state_in_list();
    test_polygon_offset();
    scene_finish(&sc);
    return CHECK_RESULT("test_shapes");
}
