/* test_fogsec.c: fog coordinates, the colour sum and fog on shapes.
 *
 * Unlit untextured draws take GL's fog of their fog coordinates and the
 * secondary colour into the vertex colours (no fog layer); lit draws keep
 * the layer and say so; a fogged GLUT solid gets the fog layer in the
 * SDL, and so does an unlit one with a fog coordinate baked in its colour;
 * fogged display-list calls stay inline (each call's own eye distance);
 * the raster colour under lighting is lit as a vertex; depth-tested
 * pixels at one depth lie at that depth.
 */
#include <GL/gl.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "check.h"
#include "interp_fixture.h"
#include "interp.h"
#include "interp_internal.h"
#include "outbuf.h"
#include "povwrite.h"
#include "tracegen.h"

/* A red triangle at z = -5 with fog coordinates 0, 5 and 10. */
static void fog_tri(seq *s)
{
    CMD(s, Color3f, 1, 0, 0);
    CMD(s, Begin, GL_TRIANGLES);
    CMD(s, FogCoordf, 0);
    CMD(s, Vertex3f, -1, -1, -5);
    CMD(s, FogCoordf, 5);
    CMD(s, Vertex3f, 1, -1, -5);
    CMD(s, FogCoordf, 10);
    CMD(s, Vertex3f, 0, 1, -5);
    CMD0(s, End);
}

static void fog_setup(seq *s, GLenum mode)
{
    CMD(s, Enable, GL_DEPTH_TEST);
    CMD(s, Enable, GL_FOG);
    CMD(s, Fogi, GL_FOG_COORD_SRC, GL_FOG_COORD);
    CMD(s, Fogi, GL_FOG_MODE, mode);
    CMD(s, Fogf, GL_FOG_START, 0);
    CMD(s, Fogf, GL_FOG_END, 10);
    CMD(s, Fogf, GL_FOG_DENSITY, 0.2);
    CMD(s, Fogfv, GL_FOG_COLOR, 0, 0, 1, 1);
}

static void test_fog_coord_linear(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    fog_setup(&s, GL_LINEAR);
    fog_tri(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.nmeshes, 1);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK(!sc.meshes[0].look.fog); /* baked: no eye-distance layer */
    static const float want[3][3] = {{1, 0, 0}, {0.5f, 0, 0.5f}, {0, 0, 1}};
    for (int k = 0; k < 3; k++)
        for (int c = 0; c < 3; c++)
            CHECK_NEAR(sc.verts[sc.tris[0].v[k]].color[c], want[k][c], 1e-6);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD), 0);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD_VERTEX), 0);
    interp_destroy(ip);
}

static void test_fog_coord_exp(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    fog_setup(&s, GL_EXP2);
    fog_tri(&s);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    double f = exp(-(0.2 * 5) * (0.2 * 5));
    CHECK_NEAR(sc.verts[sc.tris[0].v[1]].color[0], f, 1e-6);
    CHECK_NEAR(sc.verts[sc.tris[0].v[1]].color[2], 1 - f, 1e-6);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD_VERTEX), 1);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD), 0);
    interp_destroy(ip);

    /* Eye distance (the default source): the layer, colours untouched. */
    ip = fresh();
    seq_init(&s);
    fog_setup(&s, GL_LINEAR);
    CMD(&s, Fogi, GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
    fog_tri(&s);
    run(ip, &s);
    CHECK(sc.nmeshes == 1 && sc.meshes[0].look.fog);
    CHECK_NEAR(sc.verts[sc.tris[0].v[2]].color[0], 1, 0);
    interp_destroy(ip);
}

/* Lit surfaces: POV-Ray computes the colour; the eye-distance layer stays,
 * with a note. */
static void test_fog_coord_lit(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    fog_setup(&s, GL_LINEAR);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    fog_tri(&s);
    run(ip, &s);
    CHECK(sc.nmeshes == 1 && sc.meshes[0].look.fog && !sc.meshes[0].look.fog_fixed);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD), 1);
    interp_destroy(ip);

    /* One coordinate for the whole draw: a constant factor, exact. */
    ip = fresh();
    seq_init(&s);
    fog_setup(&s, GL_LINEAR);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    CMD(&s, FogCoordf, 2.5);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, -1, -1, -5);
    CMD(&s, Vertex3f, 1, -1, -5);
    CMD(&s, Vertex3f, 0, 1, -5);
    CMD0(&s, End);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK(sc.nmeshes == 1 && sc.meshes[0].look.fog && sc.meshes[0].look.fog_fixed);
    if (sc.nmeshes == 1)
        CHECK_NEAR(sc.meshes[0].look.fog_f, 0.75, 1e-6);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_COORD), 0);
    write_sdl();
    CHECK(strstr(sdl, "#declare rgl_fog=texture{pigment{rgbt<0,0,1,0.75>}") != NULL);
    interp_destroy(ip);
}

static void test_color_sum(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_COLOR_SUM);
    CMD(&s, Color3f, 0.5, 0.2, 0);
    CMD(&s, SecondaryColor3f, 0.7, 0.1, 0.3);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, -1, -1, -5);
    CMD(&s, Vertex3f, 1, -1, -5);
    CMD(&s, Vertex3f, 0, 1, -5);
    CMD0(&s, End);
    CMD(&s, Disable, GL_COLOR_SUM);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, -1, -1, -6);
    CMD(&s, Vertex3f, 1, -1, -6);
    CMD(&s, Vertex3f, 0, 1, -6);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 2);
    const float *c0 = sc.verts[sc.tris[0].v[0]].color, *c1 = sc.verts[sc.tris[1].v[0]].color;
    CHECK_NEAR(c0[0], 1.2, 1e-6); /* POV-Ray clamps the pixel, as GL the fragment */
    CHECK_NEAR(c0[1], 0.3, 1e-6);
    CHECK_NEAR(c0[2], 0.3, 1e-6);
    CHECK_NEAR(c1[0], 0.5, 1e-6);
    CHECK_NEAR(c1[2], 0, 0);
    CHECK_EQ_U(count(DIAG_NOTE_COLOR_SUM), 0);
    interp_destroy(ip);
}

/* A fogged GLUT sphere is a solid with the fog layer over its texture. */
static void test_fogged_solid(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Enable, GL_FOG);
    CMD(&s, Translatef, 0, 0, -8);
    CMD(&s, SolidSphere, 1, 32, 24);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nsolids, 1);
    write_sdl();
    const char *decl = strstr(sdl, "#declare rgl_fog=");
    const char *sph = strstr(sdl, "sphere{<0,0,0>,1");
    CHECK(decl != NULL && sph != NULL && decl < sph);
    CHECK(sph != NULL && strstr(sph, "texture{rgl_fog}") != NULL);
    interp_destroy(ip);

    /* Unlit with a fog coordinate: the fogged colour, no layer. */
    ip = fresh();
    seq_init(&s);
    fog_setup(&s, GL_LINEAR);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, FogCoordf, 2.5);
    CMD(&s, Translatef, 0, 0, -8);
    CMD(&s, SolidSphere, 1, 32, 24);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(sc.nsolids, 1);
    CHECK(!sc.solids[0].look.fog);
    CHECK_NEAR(sc.solids[0].color[0], 0.75, 1e-6);
    CHECK_NEAR(sc.solids[0].color[2], 0.25, 1e-6);
    write_sdl();
    CHECK(strstr(sdl, "rgl_fog") == NULL);
    interp_destroy(ip);
}

/* Calls of one list at other depths: unfogged they share a prototype;
 * fogged each stays inline, fogged by its own eye distance. */
static void test_fogged_list(void)
{
    seq b;
    seq_init(&b);
    CMD(&b, Begin, GL_TRIANGLES);
    CMD(&b, Vertex2f, 0, 0);
    CMD(&b, Vertex2f, 1, 0);
    CMD(&b, Vertex2f, 0, 1);
    CMD0(&b, End);
    CMD(&b, Translatef, 0, 0, -5);
    bodies[0] = b;
    nbodies = 1;
    for (int fog = 0; fog < 2; fog++) {
        interp *ip = fresh();
        seq s;
        seq_init(&s);
        CMD(&s, Enable, GL_DEPTH_TEST);
        if (fog)
            CMD(&s, Enable, GL_FOG);
        CMD(&s, Translatef, 0, 0, -3);
        CMD(&s, NewList, 1, GL_COMPILE, 1);
        CMD0(&s, EndList);
        for (int i = 0; i < 3; i++)
            CMD(&s, CallList, 1);
        run(ip, &s);
        interp_end_frame(ip);
        CHECK_EQ_U(sc.nprotos, fog ? 0 : 1);
        CHECK_EQ_U(sc.ntris, fog ? 3 : 1);
        if (fog) {
            write_sdl();
            const char *p = sdl;
            size_t n = 0;
            while ((p = strstr(p, "#declare rgl_fog=")) != NULL) {
                n++;
                p++;
            }
            CHECK_EQ_U(n, 3); /* one fog per call, at its own depth */
        }
        interp_destroy(ip);
    }
    seq_free(&bodies[0]);
    nbodies = 0;
}

/* GL lights the raster position as a vertex (GL 2.1 2.13): GL_LIGHT0's
 * defaults, the default material, model ambient 0.2: 0.2 * 0.2 + 0.8 (N.L). */
static void test_raster_lit(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Ortho, -1, 1, -1, 1, -1, 1);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_LIGHTING);
    CMD(&s, Enable, GL_LIGHT0);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Normal3f, 0, 0, 1);
    CMD(&s, RasterPos3f, 0.5, 0, 0);
    run(ip, &s);
    const gl_attribs *a = &interp_state(ip)->a;
    for (int k = 0; k < 3; k++)
        CHECK_NEAR(a->current.raster_color[k], 0.84, 1e-6);
    seq_init(&s);
    CMD(&s, Normal3f, 0, 0, -1); /* facing away: the ambient terms only */
    CMD(&s, RasterPos3f, 0.5, 0, 0);
    run(ip, &s);
    CHECK_NEAR(a->current.raster_color[0], 0.04, 1e-6);
    seq_init(&s);
    CMD(&s, Disable, GL_LIGHTING); /* unlit: the current colour */
    CMD(&s, RasterPos3f, 0.5, 0, 0);
    run(ip, &s);
    CHECK_NEAR(a->current.raster_color[0], 1, 0);
    CHECK_NEAR(a->current.raster_color[1], 0, 0);
    interp_destroy(ip);
}

/* The fog-coordinate and secondary-colour arrays: each element sets the
 * current value as glFogCoord / glSecondaryColor would. */
static void test_arrays(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    fog_setup(&s, GL_LINEAR);
    CMD(&s, Enable, GL_COLOR_SUM);
    CMD(&s, Color3f, 0.5, 0, 0);
    static const float xyz[9] = {-1, -1, -5, 1, -1, -5, 0, 1, -5};
    static const double fog[3] = {0, 5, 10};
    static const uint8_t sec[9] = {0, 0, 0, 0, 255, 0, 0, 0, 255};
    seq_cmd_bytes(&s, RGL_OP_ArrayData, xyz, sizeof xyz,
                  (const double[]){GL_VERTEX_ARRAY, 0, 3, GL_FLOAT}, 4);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, fog, sizeof fog,
                  (const double[]){GL_FOG_COORD_ARRAY, 0, 1, GL_DOUBLE}, 4);
    seq_cmd_bytes(&s, RGL_OP_ArrayData, sec, sizeof sec,
                  (const double[]){GL_SECONDARY_COLOR_ARRAY, 0, 3, GL_UNSIGNED_BYTE}, 4);
    CMD(&s, DrawArrays, GL_TRIANGLES, 0, 3);
    run(ip, &s);
    CHECK_EQ_U(sc.ntris, 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 0);
    if (sc.ntris == 1) {
        const float *c1 = sc.verts[sc.tris[0].v[1]].color, *c2 = sc.verts[sc.tris[0].v[2]].color;
        /* (0.5, 1, 0) fogged by half toward (0, 0, 1); (0.5, 0, 1) all fog. */
        CHECK_NEAR(c1[0], 0.25, 1e-6);
        CHECK_NEAR(c1[1], 0.5, 1e-6);
        CHECK_NEAR(c1[2], 0.5, 1e-6);
        CHECK_NEAR(c2[0], 0, 1e-6);
        CHECK_NEAR(c2[2], 1, 1e-6);
    }
    const gl_attribs *a = &interp_state(ip)->a;
    CHECK_NEAR(a->current.fog_coord, 10, 0); /* the last element's */
    CHECK_NEAR(a->current.secondary[2], 1, 0);
    interp_destroy(ip);
}

/* Lines and points take the fog of their eye distance at their ends. */
static void test_fogged_lines(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 320, 240);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 30);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_FOG);
    CMD(&s, Fogi, GL_FOG_MODE, GL_LINEAR);
    CMD(&s, Fogf, GL_FOG_START, 0);
    CMD(&s, Fogf, GL_FOG_END, 10);
    CMD(&s, Fogfv, GL_FOG_COLOR, 0, 0, 1, 1);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Begin, GL_LINES);
    CMD(&s, Vertex3f, 0, 0, -2);
    CMD(&s, Vertex3f, 1, 0, -8);
    CMD0(&s, End);
    CMD(&s, Begin, GL_POINTS);
    CMD(&s, Vertex3f, 0, 0.5, -5);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(sc.nlines, 1);
    CHECK_EQ_U(sc.npoints, 1);
    /* The draw-order step (interp_painter_apply: 5e-5 of the distance per
     * draw) moves eye z a little before the fog is taken: well under a
     * level (1/255), so 1e-3. */
    if (sc.nlines == 1) {
        CHECK_NEAR(sc.lines[0].color[0][0], 0.8, 1e-3);
        CHECK_NEAR(sc.lines[0].color[0][2], 0.2, 1e-3);
        CHECK_NEAR(sc.lines[0].color[2][0], 0.2, 1e-3);
    }
    if (sc.npoints == 1)
        CHECK_NEAR(sc.points[0].color[2], 0.5, 1e-3);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_LINES), 0);
    seq_init(&s);
    CMD(&s, Fogi, GL_FOG_MODE, GL_EXP); /* not affine in z: noted */
    CMD(&s, Begin, GL_LINES);
    CMD(&s, Vertex3f, 0, 0, -2);
    CMD(&s, Vertex3f, 1, 0, -8);
    CMD0(&s, End);
    run(ip, &s);
    CHECK_EQ_U(count(DIAG_NOTE_FOG_LINES), 1);
    interp_destroy(ip);
}

/* GL_FOG_DISTANCE_MODE_NV: its three values taken, others refused; the
 * radial distance at a line's end; a large triangle gets GL's
 * interpolated distance as its own fog plane, a small one the per-pixel
 * radial layer; GL_EYE_PLANE fogs by the signed z. */
static void test_fog_distance(void)
{
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 320, 240);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 30);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_FOG);
    CMD(&s, Fogi, GL_FOG_MODE, GL_LINEAR);
    CMD(&s, Fogf, GL_FOG_START, 0);
    CMD(&s, Fogf, GL_FOG_END, 10);
    CMD(&s, Fogfv, GL_FOG_COLOR, 0, 0, 1, 1);
    CMD(&s, Fogi, GL_FOG_DISTANCE_MODE_NV, GL_LINEAR); /* refused */
    CMD(&s, Fogi, GL_FOG_DISTANCE_MODE_NV, GL_EYE_RADIAL_NV);
    CMD(&s, Color3f, 1, 0, 0);
    CMD(&s, Begin, GL_LINES);
    CMD(&s, Vertex3f, 0, 0, -2);
    CMD(&s, Vertex3f, 3, 0, -4); /* 5 from the eye: f 0.5 */
    CMD0(&s, End);
    CMD(&s, Begin, GL_TRIANGLES); /* large: GL's interpolation is its own plane */
    CMD(&s, Vertex3f, -4, -3, -4);
    CMD(&s, Vertex3f, 4, -3, -4);
    CMD(&s, Vertex3f, 0, 3, -4);
    CMD0(&s, End);
    CMD(&s, Begin, GL_TRIANGLES); /* small: the radial distance per pixel */
    CMD(&s, Vertex3f, 0, 0, -6);
    CMD(&s, Vertex3f, 0.01, 0, -6);
    CMD(&s, Vertex3f, 0, 0.01, -6);
    CMD0(&s, End);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK_EQ_U(sc.nlines, 1);
    if (sc.nlines == 1)
        CHECK_NEAR(sc.lines[0].color[2][0], 0.5, 2e-3);
    CHECK(sc.fog.on && sc.fog.distance == SCENE_FOG_RADIAL);
    size_t own = 0, plain = 0;
    for (size_t i = 0; i < sc.nmeshes; i++)
        if (sc.meshes[i].look.fog)
            *(sc.meshes[i].look.fog_own ? &own : &plain) += 1;
    CHECK_EQ_U(own, 1);
    CHECK_EQ_U(plain, 1);
    write_sdl();
    CHECK(strstr(sdl, "-sqrt(pow(") != NULL);
    interp_destroy(ip);

    ip = fresh();
    seq_init(&s);
    CMD(&s, Enable, GL_FOG);
    CMD(&s, Fogi, GL_FOG_DISTANCE_MODE_NV, GL_EYE_PLANE);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, -1, -1, -5);
    CMD(&s, Vertex3f, 1, -1, -5);
    CMD(&s, Vertex3f, 0, 1, -5);
    CMD0(&s, End);
    run(ip, &s);
    interp_end_frame(ip);
    CHECK(sc.fog.on && sc.fog.distance == SCENE_FOG_Z);
    write_sdl();
    const char *fog = strstr(sdl, "#declare rgl_fog=");
    CHECK(fog && strstr(fog, "min(1,max(0,exp(-(") != NULL);
    if (fog && !strstr(fog, "min(1,max(0,exp(-("))
        fprintf(stderr, "%.200s\n", fog);
    interp_destroy(ip);
}

/* GL_COMBINE settings equal to a fixed mode, and the rest. */
static void test_combine(void)
{
    struct gl_texture_unit t;
    memset(&t, 0, sizeof t);
    interp_combine_defaults(&t);
    CHECK(interp_combine_mode(&t, 0, true) == GL_MODULATE); /* GL's initial setting */
    t.combine_src[0] = GL_PRIMARY_COLOR;
    t.combine_src[1] = GL_TEXTURE;
    CHECK(interp_combine_mode(&t, 0, true) == GL_MODULATE);
    CHECK(interp_combine_mode(&t, 1, false) == 0); /* PRIMARY_COLOR is not PREVIOUS there */
    t.combine_src[1] = GL_TEXTURE1;
    t.combine_src[0] = GL_PREVIOUS;
    t.combine_rgb = GL_ADD;
    CHECK(interp_combine_mode(&t, 1, false) == GL_ADD);
    CHECK(interp_combine_mode(&t, 2, false) == 0); /* another unit's texel */
    t.rgb_scale = 2;
    CHECK(interp_combine_mode(&t, 1, false) == 0);
    t.rgb_scale = 1;
    t.combine_rgb = GL_SUBTRACT;
    CHECK(interp_combine_mode(&t, 1, false) == 0);
    t.combine_rgb = GL_INTERPOLATE;
    t.combine_src[0] = GL_CONSTANT;
    t.combine_src[1] = GL_PREVIOUS;
    t.combine_src[2] = GL_TEXTURE;
    t.combine_op[2] = GL_SRC_COLOR;
    CHECK(interp_combine_mode(&t, 1, false) == GL_BLEND);
    t.combine_src[0] = GL_TEXTURE;
    t.combine_op[2] = GL_SRC_ALPHA;
    CHECK(interp_combine_mode(&t, 1, false) == GL_DECAL);
    t.combine_op[0] = GL_ONE_MINUS_SRC_COLOR;
    CHECK(interp_combine_mode(&t, 1, false) == 0);

    /* glTexEnv: stored on the active unit; bad values refused. */
    interp *ip = fresh();
    seq s;
    seq_init(&s);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGB);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB); /* RGB only */
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
    CMD(&s, TexEnvi, GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_ALPHA);
    CMD(&s, TexEnvf, GL_TEXTURE_ENV, GL_RGB_SCALE, 3);
    CMD(&s, TexEnvf, GL_TEXTURE_ENV, GL_ALPHA_SCALE, 4);
    run(ip, &s);
    const struct gl_texture_unit *u = &interp_state(ip)->a.texture;
    CHECK(u->combine_rgb == GL_DOT3_RGB && u->combine_alpha == GL_MODULATE);
    CHECK(u->combine_src[2] == GL_PRIMARY_COLOR && u->combine_op[1] == GL_ONE_MINUS_SRC_ALPHA);
    CHECK(u->rgb_scale == 1 && u->alpha_scale == 4);
    CHECK_EQ_U(count(DIAG_GL_INVALID_ENUM), 1);
    CHECK_EQ_U(count(DIAG_GL_INVALID_VALUE), 1);
    interp_destroy(ip);
}

static const uint8_t one_bit = 0x80;

/* A perspective camera fixed by a triangle at depth 10, then what `tail`
 * adds; the frame ends. */
static interp *pixels_frame(bool depth_test, const double *zs, int nz, bool after)
{
    free_res();
    add_bytes(&one_bit, 1); /* the bitmap, id 1 */
    interp *ip = fresh();
    interp_set_resources(ip, fetch_res, NULL);
    seq s;
    seq_init(&s);
    CMD(&s, Viewport, 0, 0, 40, 30);
    CMD(&s, MatrixMode, GL_PROJECTION);
    CMD(&s, Frustum, -1, 1, -1, 1, 1, 30);
    CMD(&s, MatrixMode, GL_MODELVIEW);
    CMD(&s, Enable, GL_DEPTH_TEST);
    CMD(&s, Begin, GL_TRIANGLES);
    CMD(&s, Vertex3f, -1, -1, -10);
    CMD(&s, Vertex3f, 1, -1, -10);
    CMD(&s, Vertex3f, 0, 1, -10);
    CMD0(&s, End);
    if (!depth_test)
        CMD(&s, Disable, GL_DEPTH_TEST);
    for (int i = 0; i < nz; i++) {
        CMD(&s, RasterPos3f, 0, 0, zs[i]);
        CMD(&s, Bitmap, 1, 1, 0, 0, 0, 0, 1);
    }
    if (after) {
        CMD(&s, Begin, GL_TRIANGLES);
        CMD(&s, Vertex3f, -1, -1, -4);
        CMD(&s, Vertex3f, 1, -1, -4);
        CMD(&s, Vertex3f, 0, 1, -4);
        CMD0(&s, End);
    }
    run(ip, &s);
    interp_end_frame(ip);
    return ip;
}

static double plane_at(double z)
{
    const double *a = sc.overlay_plane;
    return a[2] * z + a[3];
}

/* Depth-tested pixels at one raster depth lie in that plane of eye space;
 * otherwise in front, noted where GL would differ. */
static void test_pixels_depth(void)
{
    static const double six[2] = {-6, -6}, mixed[2] = {-6, -7};
    interp *ip = pixels_frame(true, six, 2, true);
    CHECK(sc.overlay != NULL && sc.overlay_at_depth);
    CHECK_NEAR(plane_at(-6) / plane_at(-5), 0, 1e-9);
    CHECK(plane_at(-5) * plane_at(-7) < 0);
    CHECK_EQ_U(count(DIAG_NOTE_PIXELS_DEPTH), 0);
    write_sdl();
    CHECK(strstr(sdl, "-6>") != NULL || strstr(sdl, ",-6>") != NULL);
    interp_destroy(ip);

    ip = pixels_frame(true, mixed, 2, false); /* two depths: in front */
    CHECK(sc.overlay != NULL && !sc.overlay_at_depth);
    CHECK_EQ_U(count(DIAG_NOTE_PIXELS_DEPTH), 1);
    interp_destroy(ip);

    ip = pixels_frame(false, six, 1, false); /* no depth test, nothing after: exact */
    CHECK(sc.overlay != NULL && !sc.overlay_at_depth);
    CHECK_EQ_U(count(DIAG_NOTE_PIXELS_DEPTH), 0);
    interp_destroy(ip);

    ip = pixels_frame(false, six, 1, true); /* drawn over by GL: noted */
    CHECK_EQ_U(count(DIAG_NOTE_PIXELS_DEPTH), 1);
    interp_destroy(ip);
}

int main(void)
{
    scene_init(&sc);
    fx_fetch = fetch_bodies;
    test_fog_coord_linear();
    test_fog_coord_exp();
    test_fog_coord_lit();
    test_color_sum();
    test_fogged_solid();
    test_fogged_list();
    test_raster_lit();
    test_pixels_depth();
    test_arrays();
    test_combine();
    test_fogged_lines();
    test_fog_distance();
    scene_finish(&sc);
    free_res();
    return CHECK_RESULT("test_fogsec");
}
